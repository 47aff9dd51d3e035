// A coulomb interface line that ends inside plastic soil, under the coupled
// Newton tangent (doc/soil-plasticity.md section 6b): the short pile of
// prm/pile-sand.prm with the coulomb line on its SHAFT only, so the soil
// under the tip is bonded to the pile and the line's lower end node,
// (r, z) = (0.5, -5), is one node of both faces: every pair there lists the
// same DoFs on face A and face B.
//  (0) derivative: soil kept elastic (Tresca, s_u = 1e6 kPa), a shaft that
//      slips, opens (tensionless) and rubs (c = 5 kPa, phi = 20 deg),
//      harmonics 0..2, random fields with jumps of ~1e-2 m: the coupled
//      tangent applied to x equals K x minus the central difference of
//      the out-of-balance load, (G(u + e x) - G(u - e x)) / 2e, at every
//      unconstrained DoF, the end node's included (its relative
//      displacement is zero, so its softening must vanish: a value written
//      to one of its two copies would show here). Tolerance 1e-6 of the
//      largest entry, for the reasons of soil_coulomb_interface.cc (the
//      forward differences of relative step 1e-6 in the return's tangent;
//      e = 1e-9 moves about that fraction of samples across a state change).
//  (1) the sand pile (Mohr-Coulomb c' = 0, phi' = 30 deg, coulomb shaft
//      phi = 20 deg, c = 0, K0 = 0.5) and the clay pile (Tresca s_u = 10
//      kPa, coulomb shaft c = 5 kPa, phi = 0; K0 = 1, a geostatic stress
//      inside Tresca), pushed sideways at the head to 0.005 d in 2 steps:
//      Newton on the coupled tangent converges at every step, in
//      equilibrium |R| <= 1e-8 |lambda F| (the stopping rule's tolerance),
//      with every soil point on or inside its yield surface (f <= 1e-9 kPa
//      for the sand, the round-off of stresses of 100 kPa is 1e-12 kPa;
//      1e-9 x 2 s_u for the clay) and every interface sample on or inside
//      its slip surface (f <= 1e-9 kPa). At most 15 Newton iterations a
//      step (measured 8 and 5 for the sand, 5 and 4 for the clay; with the
//      end node's softening written to one of its two copies the clay took
//      31 and 28: the consistent tangent's fast convergence is the check).
#include "soil_test_support.h"


using namespace FourierSSI;
using namespace soil_test;

namespace
{
  /** pile-sand.prm on a coarse mesh, the coulomb line on the shaft only. */
  std::string
  shaft_only_pile(const std::string &soil_law,
                  const std::string &interface_law,
                  const std::string &harmonics,
                  const std::string &K0 = "0.5")
  {
    return test_support::bundled_prm("prm/pile-sand.prm",
                                     {{"Harmonics", harmonics},
                                      {"R cells", "1, 4"},
                                      {"Z cells", "2, 4"},
                                      {"Interface lines", "5: r=0.5, z=-5..0"},
                                      {"Laws", soil_law},
                                      {"Interfaces", "5: " + interface_law},
                                      {"Theta samples", "8"},
                                      {"Target", "0.005"},
                                      {"Load steps", "2"},
                                      {"K0", K0}});
  }

  void
  check_newton(const std::string &name,
               const std::string &soil_law,
               const std::string &interface_law,
               const std::string &K0,
               const double       yield_scale)
  {
    std::cout << "(1) " << name << ": Newton on the coupled tangent"
              << std::endl;
    Run run(shaft_only_pile(soil_law, interface_law, "0, 1", K0));
    run.solver->run(std::cout);
    const auto &steps = run.solver->get_steps();
    check::in_range(name + ": converged steps", steps.size(), 2u, 1000u);
    check_equilibrium_and_yield(name + ": ", steps, yield_scale);
    unsigned int most = 0;
    for (const LoadStepResult &s : steps)
      most = std::max(most, s.iterations);
    check::in_range(name + ": Newton iterations per step (most)", most, 1, 15);
    check_interface_admissible(name, steps, 1e-9);
  }
} // namespace

int
main()
{
  // (0) soil kept elastic; the shaft slips, opens and rubs.
  Run derivative(
    shaft_only_pile("0: tresca, su=1e6",
                    "coulomb, kn=1e4, ks=1e4, c=5, phi=20, sigma_t=0",
                    "0, 1, 2"));
  check_interface_tangent(derivative);
  // check_equilibrium_and_yield allows f <= 1e-9 x 2 s_u: s_u = 0.5 kPa
  // gives the sand's 1e-9 kPa.
  check_newton("sand",
               "0: mohr-coulomb, c=0, phi=30, psi=0",
               "coulomb, kn=1e6, ks=1e6, c=0, phi=20",
               "0.5",
               0.5);
  check_newton("clay",
               "0: tresca, su=10",
               "coulomb, kn=1e6, ks=1e6, c=5, phi=0",
               "1",
               10.);
  return check::summary();
}
