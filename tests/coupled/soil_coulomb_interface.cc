// Plastic soil and coulomb interfaces in one coupled iteration
// (doc/soil-plasticity.md section 6b): the plane-strain pile slice of
// prm/pile-capacity.prm with its shaft a coulomb interface.
//  (0) derivative: with the soil kept elastic (s_u = 1e6 kPa) and an
//      interface that slips, opens (tensionless) and rubs (phi = 20 deg),
//      harmonics 0..2 of both families, random fields with jumps of ~1e-2
//      m (tractions ~100 kPa against c = 5 kPa): the interface part of the
//      coupled tangent, K x - K_t x, equals the central difference of the
//      out-of-balance load (G(u + e x) - G(u - e x)) / 2e, whose only
//      shared pieces are the return mapping and the projection. Tolerance
//      1e-6 of the largest entry (measured 2.0e-10 with the closed-form
//      tangent of the return, 2.3e-9 when it was a forward difference of
//      relative step 1e-6): the central difference's own error on the
//      curved part of the radial return is far below that, and e = 1e-9
//      moves about that fraction of the samples across a state change,
//      where the difference quotient and the tangent part.
//  (1) a coulomb interface that never reaches its strength (c = 100 kPa
//      against the soil's s_u = 10 kPa) is the linear interface with the
//      same kn, ks: the same curve to 1e-12 at kn = ks = 1e6 kPa/m (3.3e3
//      G / l, below the soil solver's cap of 1e4 G / l: the only
//      difference is a zero out-of-balance load added). (1b) At 1e7 (above
//      the cap: K holds 1e4 G / l and the multipliers carry kn,
//      doc/nonlinear-interfaces.md section 5d) the two iterations differ,
//      so the curves agree to what both converge to, |R| <= 1e-8 of the
//      force scale: 1e-8 (measured 1.7e-11).
//  (2) Newton on the coupled tangent and the initial-stiffness iteration
//      give the same curve for an interface that slips (c = 5 kPa = 0.5
//      s_u), to 1e-7 (both stop at |R| <= 1e-8 |lambda F|); Newton within
//      25 iterations a step. 8 steps to u = 0.01 d: Newton's first step
//      from the elastic state to 0.005 d fails (its first update raises
//      |R| fourfold) and is cut, which would make the two step sequences
//      differ. kn = ks = 1e5 kPa/m (about G / h of the first
//      soil cell): the initial-stiffness iteration contracts by about
//      1 - (slipping stiffness) / ks per iteration, and with the scene's
//      1e7 it needs thousands (measured: step cuts, then no convergence
//      in 3000), which is why Newton is the default.
//  (3) at every converged step the interface tractions stay on or inside
//      the slip surface (f <= 1e-9 c) and the soil's on or inside Tresca.
#include "soil_test_support.h"


using namespace FourierSSI;
using namespace soil_test;

namespace
{
  std::string
  pile_scene(const std::vector<std::pair<std::string, std::string>> &changes,
             const std::string &interface_law,
             const std::string &more = "")
  {
    return test_support::bundled_prm(
             "prm/pile-capacity.prm",
             soil_test::joined(changes,
                               {{"Interfaces", "5: " + interface_law}})) +
           more;
  }

  std::vector<LoadStepResult>
  curve(const std::string &interface_law,
        const std::string &stiffness,
        const std::string &load_steps)
  {
    Run run(pile_scene({{"Harmonics", "0, 1, 2, 3, 4"},
                        {"Target", "0.01"},
                        {"Load steps", load_steps}},
                       interface_law,
                       "subsection Soil plasticity\n  set Stiffness = " +
                         stiffness + "\nend\n"));
    run.solver->run(std::cout);
    return run.solver->get_steps();
  }

  void
  check_same_curve(const std::string                 &name,
                   const std::vector<LoadStepResult> &a,
                   const std::vector<LoadStepResult> &b,
                   const double                       tolerance)
  {
    check::equal(name + ": steps", a.size(), b.size());
    for (unsigned int s = 0; s < a.size() && s < b.size(); ++s)
      check::relative(name + ": step " + std::to_string(s + 1) + " load factor",
                      a[s].load_factor,
                      b[s].load_factor,
                      tolerance);
  }

  void
  check_admissible(const std::string                 &name,
                   const std::vector<LoadStepResult> &steps,
                   const double                       c)
  {
    check_equilibrium_and_yield(name + ": ", steps, 10.);
    check_interface_admissible(name, steps, 1e-9 * c);
  }
} // namespace

int
main()
{
  // (0) soil kept elastic; the interface slips, opens and rubs.
  Run derivative(pile_scene({{"Harmonics", "0, 1, 2"},
                             {"Family", "both"},
                             {"Laws", "0: tresca, su=1e6"}},
                            "coulomb, kn=1e4, ks=1e4, c=5, phi=20, sigma_t=0"));
  check_interface_tangent(derivative);

  std::cout << "(1) a coulomb interface that does not slip is linear"
            << std::endl;
  const auto strong =
    curve("coulomb, kn=1e6, ks=1e6, c=100, phi=0, sigma_t=none",
          "tangent",
          "2");
  const auto linear = curve("kn=1e6, ks=1e6", "tangent", "2");
  check_same_curve("c = 100 kPa vs linear", strong, linear, 1e-12);
  check::equal("c = 100 kPa: slipping samples at the last step",
               strong.back().contact[1],
               0u);
  // (1b) above the soil cap, through the multipliers.
  const auto stiff =
    curve("coulomb, kn=1e7, ks=1e7, c=100, phi=0, sigma_t=none",
          "tangent",
          "2");
  const auto stiff_linear = curve("kn=1e7, ks=1e7", "tangent", "2");
  check_same_curve("kn = 1e7, c = 100 kPa vs linear",
                   stiff,
                   stiff_linear,
                   1e-8);

  std::cout << "(2) slipping interface: Newton vs initial stiffness"
            << std::endl;
  const std::string adhesive =
    "coulomb, kn=1e5, ks=1e5, c=5, phi=0, sigma_t=none";
  const auto newton  = curve(adhesive, "tangent", "8");
  const auto elastic = curve(adhesive, "elastic", "8");
  check_same_curve("c = 5 kPa", newton, elastic, 1e-7);
  unsigned int most = 0;
  for (const LoadStepResult &s : newton)
    most = std::max(most, s.iterations);
  check::in_range("Newton iterations per step (most)", most, 1, 25);
  check::in_range("c = 5 kPa: slipping samples at the last step",
                  newton.back().contact[1],
                  1u,
                  1000000u);

  std::cout << "(3) admissible tractions and stresses" << std::endl;
  check_admissible("Newton", newton, 5.);
  check_admissible("initial stiffness", elastic, 5.);
  return check::summary();
}
