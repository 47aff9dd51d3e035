// Combined loading of the rough footing on Tresca soil (prm/footing-capacity
// .prm: a = 1 m, s_u = 10 kPa, G = 3000 kPa, nu = 0.49): a vertical load
// brought on and then held (Rigid foundation/Held vertical force) while the
// footing is pushed sideways by displacement control
// (doc/soil-plasticity.md section 5c).
// Checks, with their reasons:
//  1. V held follows the path of the same V applied by load control in the
//     same steps: both solve the same equations (the held loads' elastic
//     solution is added where the pattern's was), so the settlements agree
//     to the iteration tolerance (1e-8 on the force; 1e-6 relative on w
//     leaves room for the different round-off of the two paths);
//  2. the horizontal capacity does not depend on V while V <= V_ult / 2:
//     Tresca strength does not depend on pressure and the sliding
//     mechanism under the base is unchanged (exact for the strip, Green
//     1954; the same in FE studies of circular footings, e.g. Taiebat &
//     Carter 2000). V = 47.5 kN = V_ult / 4 with the published
//     V_ult = 6.05 pi a^2 s_u = 190 kN; H at u = 0.01 m = 5 elastic yield
//     displacements, both runs on the same coarse mesh (its discretization
//     error, +15 % against A s_u, is common to both): within 1 %
//     (measured 0.32 %: 36.141 against 36.257 kN);
//  3. every step of the sideways stage keeps V at the held value exactly,
//     reaches the prescribed u, is in equilibrium to 1e-8 and on or inside
//     the yield surface; H stays above the sliding limit A s_u (the
//     displacement FE is too stiff in the shear band).
#include "soil_test_support.h"

#include <iomanip>

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  /** Settlements of V = -95 kN in 4 steps, held (true) or load control. */
  std::vector<double>
  settlements(const bool held)
  {
    Run run(scene(
      {{"Vertical force", held ? "0\n  set Held vertical force = -95" : "-95"},
       {"Control", "load"},
       {"Load steps", held ? "1\n  set Held load steps = 4" : "4"}}));
    run.solver->run(std::cout);
    const auto &steps = run.solver->get_steps();
    check_equilibrium_and_yield("", steps, 10.);
    std::vector<double> w;
    for (unsigned int s = 0; s < 4; ++s)
      {
        const auto loads = run.solver->applied_loads(steps[s].load_factor,
                                                     steps[s].held_fraction);
        check::relative("V at step " + std::to_string(s + 1) + " [kN]",
                        loads[2],
                        -95. * (s + 1) / 4.,
                        1e-14);
        w.push_back(steps[s].motion.vertical_displacement);
      }
    return w;
  }

  /** H at u = 0.01 m with V held (coarse mesh, n = 0 and 1). */
  double
  horizontal_capacity(const double held_vertical_force)
  {
    std::ostringstream load;
    load << "0\n  set Horizontal force = 1\n  set Held vertical force = "
         << held_vertical_force;
    Run run(scene(joined({{"Harmonics", "0, 1"},
                          {"Vertical force", load.str()},
                          {"Theta samples", "8"},
                          {"Controlled motion", "horizontal"},
                          {"Target", "0.01"},
                          {"Load steps", "10"}},
                         footing_mesh(true))));
    run.solver->run(std::cout);
    const auto &steps = run.solver->get_steps();
    check_equilibrium_and_yield("", steps, 10.);
    for (const LoadStepResult &s : steps)
      if (s.held_fraction == 1.)
        check::relative("V held while H grows [kN]",
                        run.solver->applied_loads(s.load_factor, 1.)[2],
                        held_vertical_force,
                        1e-14);
    check::relative("u at the last step [m]",
                    steps.back().motion.horizontal_displacement,
                    0.01,
                    1e-12);
    return run.solver->applied_loads(steps.back().load_factor,
                                     steps.back().held_fraction)[0];
  }
} // namespace

int
main()
{
  const std::vector<double> held = settlements(true), load = settlements(false);
  for (unsigned int s = 0; s < 4; ++s)
    check::relative("w held vs load control, step " + std::to_string(s + 1),
                    held[s],
                    load[s],
                    1e-6);

  const double sliding = numbers::PI * 10.; // A s_u [kN]
  const double alone   = horizontal_capacity(0.);
  const double with_V  = horizontal_capacity(-47.5);
  std::cout << std::setprecision(8) << "H at u = 0.01 m: " << alone
            << " kN (V = 0), " << with_V
            << " kN (V = 47.5 kN held); A s_u = " << sliding << " kN"
            << std::endl;
  check::that("H above A s_u (V = 0)", alone > sliding);
  check::that("H above A s_u (V held)", with_V > sliding);
  check::relative("H with V = V_ult / 4 held vs H alone", with_V, alone, 0.01);
  return check::summary();
}
