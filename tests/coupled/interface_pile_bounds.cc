// Bounds of the lateral pile curve (the bundled scene
// prm/pile-lateral-slip.prm: the thesis pile, Coulomb interface phi = 25
// degrees, c = 0, tensionless, over geostatic stress gamma' = 10 kN/m^3,
// K0 = 0.5, kn = ks = 1e4 kPa/m, harmonics n = 0..6):
//  (1) the curve starts on the linear elastic slope of the same interface
//      stiffness: one step to u = 1e-5 m, where every (point, theta) sample
//      sticks (checked), gives H/u equal to the linear law kn = ks = 1e4
//      (n = 1 only) to 1e-8 (the iteration tolerance 1e-10 of the force
//      residual, times the conditioning; 0 iterations make it round-off);
//  (2) along the first 4 steps to u = 0.02 m (2 % of the diameter), where
//      points near the surface slip and the back of the pile opens, H(u)
//      lies between the tensionless frictionless curve (phi = 0, same kn,
//      same initial stress: the interface that carries only compression)
//      and the linear elastic line of the same stiffness, itself below the
//      linear `rough` one (bonded, kn = ks = 1e10). Slip and opening only
//      remove strength, so the bounds are strict; the comparison uses a
//      margin of 1e-8 relative (the iteration tolerance);
// (Equilibrium of the interface tractions with H is checked where the
// foundation is the interface's own material, Tie = material: the disc and
// the rigid pile of interface_coulomb_pile; here the load enters through a
// cap on the pile head, Tie = boundary, and the pile carries it down.)
#include "check.h"
#include "coupled_interface_test_support.h"

using namespace FourierSSI;
using test_support::with_entry;

namespace
{
  std::string
  pile(const std::string &target, const std::string &steps)
  {
    std::string text = test_support::bundled_prm("prm/pile-lateral-slip.prm");
    text             = with_entry(text, "Target", target);
    return with_entry(text, "Load steps", steps);
  }
} // namespace

int
main()
{
  const std::string scene =
    test_support::bundled_prm("prm/pile-lateral-slip.prm");
  const double elastic =
    coupled_test::linear_lateral_slope(scene, "5: kn=1e4, ks=1e4");
  const double rough = coupled_test::linear_lateral_slope(scene, "5: rough");
  std::cout << "  linear slopes: elastic (kn = ks = 1e4) " << elastic
            << " kN/m, rough " << rough << " kN/m" << std::endl;

  // (1) The start of the curve.
  const coupled_test::Curve start = coupled_test::run(pile("1e-5", "1"));
  const coupled_test::Step &s0    = start.steps.front();
  check::equal("u = 1e-5 m: samples not sticking", s0.slip + s0.open, 0);
  check::relative("initial slope H/u vs linear elastic slope",
                  s0.H / s0.u,
                  elastic,
                  1e-8);

  // (2) Bounds along the curve, (3) equilibrium.
  const coupled_test::Curve coulomb      = coupled_test::run(pile("0.02", "4"));
  const coupled_test::Curve frictionless = coupled_test::run(with_entry(
    pile("0.02", "4"), "Interfaces", "5: coulomb, kn=1e4, ks=1e4, c=0, phi=0"));
  check::that("rough is stiffer than the elastic interface", rough > elastic);
  for (unsigned int k = 0; k < coulomb.steps.size(); ++k)
    {
      const coupled_test::Step &c = coulomb.steps[k],
                               &f = frictionless.steps[k];
      const std::string at        = "step " + std::to_string(k + 1);
      std::cout << "  " << at << ": u " << c.u << " m: H frictionless " << f.H
                << ", Coulomb " << c.H << ", elastic " << elastic * c.u
                << " kN; Coulomb slip/open " << c.slip << '/' << c.open << ", "
                << c.iterations << " iterations" << std::endl;
      check::relative(at + ": same controlled u", f.u, c.u, 1e-12);
      check::in_range(at + ": H between frictionless and elastic [kN]",
                      c.H,
                      f.H * (1. - 1e-8),
                      elastic * c.u * (1. + 1e-8));
    }
  return check::summary();
}
