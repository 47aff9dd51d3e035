// Vertical bearing capacity of a rigid circular surface footing on Tresca
// soil, ROUGH (prm/footing-capacity.prm: a = 1 m, s_u = 10 kPa, G = 3000
// kPa, nu = 0.49, FE_Q(2) + B-bar, n = 0 only, displacement control):
// N_c = V_ult / (pi a^2 s_u) against Eason & Shield (1960) 6.05 within 2 %
// (the tolerance: the footing-edge singularity makes this mesh
// overestimate by about 1.7 %, doc/soil-plasticity.md table 1); at every
// converged step equilibrium |R| <= 1e-8 |lambda F| and no stress outside
// the yield surface by more than 1e-9 * 2 s_u.
#include "soil_test_support.h"

int
main()
{
  soil_test::check_capacity("rough", "all", 6.05);
  return check::summary();
}
