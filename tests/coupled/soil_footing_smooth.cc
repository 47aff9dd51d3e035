// Vertical bearing capacity of a rigid circular surface footing on Tresca
// soil, SMOOTH (prm/footing-capacity.prm with Tied components = normal):
// N_c = V_ult / (pi a^2 s_u) against Cox, Eason & Hopkins (1961) 5.69
// within 2 % (mesh error as for the rough footing, doc/soil-plasticity.md
// table 1); equilibrium and the yield condition at every converged step.
#include "soil_test_support.h"

int
main()
{
  soil_test::check_capacity("smooth", "normal", 5.69);
  return check::summary();
}
