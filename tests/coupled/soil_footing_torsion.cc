// Torsional capacity of a rigid ROUGH circular surface footing on Tresca
// soil (prm/footing-capacity.prm: a = 1 m, s_u = 10 kPa, G = 3000 kPa,
// nu = 0.49; harmonic n = 0 antisymmetric: the circumferential displacement
// alone), twisted to 0.02 rad. The soil disc under the footing turning on a
// shear surface at its base dissipates s_u int r dA = 2 pi a^3 s_u / 3, and
// the uniform shear s_u on the base balances it: T_ult = 2 pi a^3 s_u / 3 =
// 20.944 kNm, exact (doc/soil-plasticity.md section 5b).
// On the shipped mesh coarsened 2x (5 + 7 by 10 cells) and as shipped
// (10 + 14 by 20): measured 24.168 (+15.4 %) and 22.381 (+6.86 %); a mesh
// refined 2x more gives 21.613 (+3.19 %, 3 minutes, not run here).
// Checks, with their reasons:
//  - both above T_ult: a displacement element is too stiff in the shear
//    band under the base (what makes the FE limit exceed the exact one);
//  - the error falls by at least 1.8x from the coarse to the shipped mesh:
//    at least first order at the footing edge (measured 2.24x);
//  - Richardson's extrapolation with order 1, 2 T_h - T_2h, within 2 % of
//    T_ult (the tolerance; measured -1.67 %; with the order 1.22
//    observed on three meshes the extrapolation is +0.43 %);
//  - every converged step in equilibrium to 1e-8 and on or inside the
//    yield surface.
#include "soil_test_support.h"

#include <iomanip>

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  double
  torsional_capacity(const bool coarse)
  {
    Run run(scene(joined({{"Family", "antisymmetric"},
                          {"Vertical force", "0\n  set Torque = 1"},
                          {"Controlled motion", "twist"},
                          {"Target", "0.02"},
                          {"Load steps", "10"}},
                         footing_mesh(coarse))));
    run.solver->run(std::cout);
    const auto &steps = run.solver->get_steps();
    check_equilibrium_and_yield("", steps, 10.);
    check::relative("twist at the last step [rad]",
                    steps.back().motion.twist,
                    0.02,
                    1e-12);
    return run.solver->applied_loads(steps.back().load_factor)[5];
  }
} // namespace

int
main()
{
  const double exact   = 2. * numbers::PI * 10. / 3.;
  const double coarse  = torsional_capacity(true);
  const double shipped = torsional_capacity(false);
  std::cout << std::setprecision(8) << "T_ult = " << coarse << " kNm (coarse), "
            << shipped << " kNm (shipped mesh), exact " << exact << " kNm"
            << std::endl;
  check::that("coarse mesh above T_ult", coarse > exact);
  check::that("shipped mesh above T_ult", shipped > exact);
  check::in_range("error ratio coarse / shipped",
                  (coarse - exact) / (shipped - exact),
                  1.8,
                  1e300);
  check::relative("Richardson 2 T_h - T_2h vs 2 pi a^3 s_u / 3",
                  2. * shipped - coarse,
                  exact,
                  0.02);
  return check::summary();
}
