// Requirement "loads mean what the documentation says", coulomb interfaces:
// with a Rigid foundation, a traction (Boundary conditions/Traction) is a
// held load: applied in full by the held stage (Load path/Held
// load steps), then constant while the load factor scales only the
// foundation's load (CoupledInterfaceSolver::run_stage, held_stage_load).
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
//     today's scaling of the traction with lambda breaks it by (1 - lambda)
//     Q;
//  3. the pull-out capacity: with kn = 1 kPa/m the normal stress on the
//     shaft stays at K0 gamma' z and the base carries nothing (as in the
//     pull-out check of interface_coulomb_pile.cc), so the pile pulls out
//     when the shaft friction 2 pi a int K0 gamma' z tan(phi) dz acts
//     downward against V - Q: V_u = shaft + Q. Tolerance 0.5 % as there (the
//     plateau is approached as the last sticking points slip).
#include "check.h"
#include "factorized_scene.h"

#include <fourier_ssi/coupled/coupled_interface_solver.h>

using namespace FourierSSI;

namespace
{
  const double a = 0.5, L = 5., unit_weight = 10., K0 = 0.5, q = 50.;

  std::string
  pile_scene(const std::string &held_load_steps)
  {
    return R"(
subsection Discretization
  set Harmonics         = 0
  set Family            = symmetric
  set Polynomial degree = 2
end
subsection Mesh
  set R breakpoints   = 0, 0.5, 10
  set R cells         = 2, 8
  set R growth        = 1, 1.4
  set Z breakpoints   = -10, -5, 0
  set Z cells         = 5, 6
  set Z growth        = 0.8, 1
  set Material regions = 1: 0, 0.5, -5, 0
  set Interface lines = 5: r=0.5, z=-5..0; 6: z=-5, r=0..0.5
end
subsection Materials
  set Materials = 0: G=10000, nu=0.3; 1: G=1e7, nu=0.2
end
subsection Interfaces
  set Interfaces = 5: coulomb, kn=1, ks=1e5, phi=25; 6: coulomb, kn=1, ks=1e5, phi=25
end
subsection Initial stress
  set Effective unit weight = 10
  set K0                    = 0.5
end
subsection Boundary conditions
  set Dirichlet = 1: u=0, v=0, w=0; 2: u=0, v=0, w=0
  # 3: the top; the pile's part r < a carries q downward.
  set Traction  = 3: z=-50*(r<0.5)
end
subsection Rigid foundation
  set Enabled        = true
  set Tie            = material
  set Id             = 1
  set Vertical force = 1
end
subsection Load path
  set Control           = displacement
  set Controlled motion = vertical
  set Target            = 0.04
  set Load steps        = 8
  set Held load steps   = )" +
           held_load_steps + R"(
  set Tolerance         = 1e-12
end
)";
  }

  /** `text` with each `from` replaced by its `to` (each must be there). */
  std::string
  replaced(std::string                                             text,
           const std::vector<std::pair<std::string, std::string>> &changes)
  {
    for (const auto &[from, to] : changes)
      {
        const auto at = text.find(from);
        AssertThrow(at != std::string::npos, ExcMessage(from));
        text.replace(at, from.size(), to);
      }
    return text;
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
    const std::string text = replaced(
      pile_scene("2"),
      {{"set Harmonics         = 0", "set Harmonics         = 0, 1"},
       {"5: coulomb, kn=1,", "5: coulomb, kn=1e5,"},
       {"6: coulomb, kn=1,", "6: coulomb, kn=1e5,"},
       {"z=-50*(r<0.5)", "z=-50*(r<0.5)*(n==0)"},
       {"set Vertical force = 1", "set Horizontal force = 1"},
       {"Controlled motion = vertical", "Controlled motion = horizontal"},
       {"set Target            = 0.04", "set Target            = 0.02"},
       {"set Load steps        = 8", "set Load steps        = 4"},
       {"set Tolerance         = 1e-12", "set Tolerance         = 1e-10"}});
    test_support::FactorizedScene scene(text);
    CoupledInterfaceSolver        solver(scene.set, scene.parameters);
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

  test_support::FactorizedScene scene(pile_scene(std::to_string(held_steps)));
  CoupledInterfaceSolver        solver(scene.set, scene.parameters);
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
