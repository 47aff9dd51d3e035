// Requirement "loads mean what the documentation says", coulomb interfaces:
// with a Rigid foundation, a traction (Boundary conditions/Traction) is a
// held load: applied in full by the held stage (Load path/Held
// load steps), then constant while the load factor scales only the
// foundation's load (LoadPath::run_stage, held_stage_load).
//
// The rigid pile of tests/coupled/interface_coulomb_pile.cc (a = 0.5 m,
// L = 5 m, n = 0; c = 0, phi = 25 deg on shaft and base, geostatic
// gamma' = 10, K0 = 0.5), with a downward traction q = 50 kPa on its top
// (r < a at z = 0: Q = q pi a^2 = 39.27 kN, below the shaft's capacity), then
// pulled out by displacement control (Vertical force = 1 gives the
// direction).
// Checks, with their reasons (4: a lateral push, below):
//  1. the held stage reaches Q with lambda = 0 and the pull stage keeps it
//     (held fraction 1 at every step);
//  2. equilibrium of the pile at every converged step: the interface
//     tractions integrated over shaft, base and circumference (the change
//     from the geostatic state) equal rho Q + lambda V to 1e-8 of the
//     larger of the two (the iteration's residual is 1e-12 of the force
//     scale; this bounds the sum of the residuals of a few hundred DoFs);
//     a traction scaled with lambda instead of held would break it by
//     (1 - lambda) Q;
//  3. the pull-out capacity: with kn = 1 kPa/m the normal stress on the
//     shaft stays at K0 gamma' z and the base carries nothing (as in the
//     pull-out check of interface_coulomb_pile.cc), so the pile pulls out
//     when the shaft friction 2 pi a int K0 gamma' z tan(phi) dz acts
//     downward against V - Q: V_u = shaft + Q. Tolerance 0.5 % as there (the
//     plateau is approached as the last sticking points slip).
#include "check.h"
#include "factorized_scene.h"
#include "rigid_pile_scene.h"

#include <fourier_ssi/coupled/coupled_solver.h>

using namespace FourierSSI;

namespace
{
  const double a = 0.5, L = 5., unit_weight = 10., K0 = 0.5, q = 50.;

  /** Coulomb laws on shaft (5) and base (6), c = 0, phi = 25 deg. */
  std::string
  coulomb_laws(const std::string &kn)
  {
    return "5: coulomb, kn=" + kn + ", ks=1e5, phi=25; 6: coulomb, kn=" + kn +
           ", ks=1e5, phi=25";
  }

  /**
   * The rigid pile with q on its top (boundary 3, the pile's part r < a;
   * `traction` is that expression), pushed by the foundation load `force`
   * under displacement control of `motion` to `target`, Q held over
   * `held_load_steps` steps first.
   */
  std::string
  pile_scene(const std::string                                      &kn,
             const std::string                                      &traction,
             const std::string                                      &force,
             const std::string                                      &motion,
             const std::vector<std::pair<std::string, std::string>> &stepping)
  {
    std::vector<std::pair<std::string, std::string>> load_path = {
      {"Control", "displacement"}, {"Controlled motion", motion}};
    load_path.insert(load_path.end(), stepping.begin(), stepping.end());
    return test_support::rigid_pile_scene() +
           test_support::entries("Interfaces",
                                 {{"Interfaces", coulomb_laws(kn)}}) +
           test_support::entries("Boundary conditions",
                                 {{"Traction", "3: z=" + traction}}) +
           test_support::entries("Rigid foundation", {{force, "1"}}) +
           test_support::entries("Load path", load_path);
  }

  /** 1-3: pulled out (kn = 1 kPa/m) to 0.04 m, Q held first. */
  std::string
  pull_scene(const std::string &held_load_steps)
  {
    return pile_scene("1",
                      "-50*(r<0.5)",
                      "Vertical force",
                      "vertical",
                      {{"Target", "0.04"},
                       {"Load steps", "8"},
                       {"Held load steps", held_load_steps},
                       {"Tolerance", "1e-12"}});
  }

  /**
   * 4. The same pile with Q held pushed sideways (n = 0, 1; kn = 1e5 so
   *    that the soil resists the push): at every step the interface
   *    resultant carries the held Q vertically and lambda H horizontally,
   *    to 1e-8 of max(|H|, Q) as in 2 (the iteration tolerance 1e-10 of
   *    the force scale). Scaling the traction with lambda would make the
   *    vertical resultant follow H instead.
   */
  void
  lateral_push(const double Q)
  {
    std::cout << "4. lateral push with Q held" << std::endl;
    const std::string text =
      pile_scene("1e5",
                 "-50*(r<0.5)*(n==0)",
                 "Horizontal force",
                 "horizontal",
                 {{"Target", "0.02"},
                  {"Load steps", "4"},
                  {"Held load steps", "2"},
                  {"Tolerance", "1e-10"}}) +
      test_support::entries("Discretization", {{"Harmonics", "0, 1"}});
    test_support::FactorizedScene scene(text);
    CoupledSolver                 solver(scene.set, scene.parameters);
    solver.run(std::cout);
    double vertical = 0., horizontal = 0., H = 0.;
    for (const LoadStepResult &s : solver.get_steps())
      {
        H                  = solver.applied_loads(s.load_factor)[0];
        const double scale = std::max(std::abs(H), Q);
        vertical =
          std::max(vertical,
                   std::abs(s.resultant[2] + s.held_fraction * Q) / scale);
        horizontal = std::max(horizontal, std::abs(s.resultant[0] - H) / scale);
      }
    std::cout << "  H at u = 0.02 m: " << H << " kN" << std::endl;
    check::that("the push reached H > 0", H > 0.);
    check::small("max |F_z + rho Q| / max(|H|, Q)", vertical, 1e-8);
    check::small("max |F_x - lambda H| / max(|H|, Q)", horizontal, 1e-8);
  }
} // namespace

int
main()
{
  const double Q = q * M_PI * a * a;
  const double shaft =
    2. * M_PI * a * K0 * unit_weight * std::tan(25. * M_PI / 180.) * L * L / 2.;
  const unsigned int held_steps = 2;

  test_support::FactorizedScene scene(pull_scene(std::to_string(held_steps)));
  CoupledSolver                 solver(scene.set, scene.parameters);
  solver.run(std::cout);
  const auto &steps = solver.get_steps();

  std::cout << "1. the held stage, then the pull with Q held" << std::endl;
  check::that("held steps and pull steps converged",
              steps.size() >= held_steps + 2);
  for (unsigned int s = 0; s < held_steps; ++s)
    {
      check::relative("held stage step " + std::to_string(s + 1) +
                        ": held fraction",
                      steps[s].held_fraction,
                      (s + 1.) / held_steps,
                      1e-14);
      check::small("held stage: load factor", steps[s].load_factor, 0.);
    }
  for (unsigned int s = held_steps; s < steps.size(); ++s)
    check::relative("pull step " + std::to_string(s + 1) + ": held fraction",
                    steps[s].held_fraction,
                    1.,
                    0.);

  std::cout << "2. equilibrium of the pile at every step" << std::endl;
  double worst = 0.;
  for (const LoadStepResult &s : steps)
    {
      const double V        = solver.applied_loads(s.load_factor)[2];
      const double expected = V - s.held_fraction * Q;
      worst                 = std::max(worst,
                       std::abs(s.resultant[2] - expected) /
                         std::max(std::abs(V), Q));
    }
  check::small("max |interface resultant F_z - (lambda V - rho Q)| / "
               "max(|V|, Q)",
               worst,
               1e-8);

  std::cout << "3. pull-out capacity with the pile top pushed by Q"
            << std::endl;
  const double V_u = solver.applied_loads(steps.back().load_factor)[2];
  std::cout << "  V_u = " << V_u << " kN; shaft + Q = " << shaft + Q
            << " kN (shaft " << shaft << ", Q " << Q << ")" << std::endl;
  check::relative("plateau V [kN] vs shaft friction + held Q",
                  V_u,
                  shaft + Q,
                  5e-3);
  lateral_push(Q);
  return check::summary();
}
