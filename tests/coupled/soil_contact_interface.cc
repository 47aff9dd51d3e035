// Exact contact (`contact`, augmented Lagrangian) with plastic soil
// (doc/soil-plasticity.md section 6b, doc/nonlinear-interfaces.md section
// 5d): the plane-strain pile slice of prm/pile-capacity.prm (rigid pile
// d = 1 m in Tresca clay s_u = 10 kPa, G = 3000 kPa, nu = 0.49, B-bar) with
// its shaft a tensionless interface, harmonics n = 0..4, Theta samples = 9
// = 2 n_max + 1 for every run (the soil and the interface on the same
// samples, so that the runs differ only in the interface), pushed to
// u = 0.01 d in 8 steps.
//  (1) two engines, one answer: with soil that never yields
//      (s_u = 1e6 kPa) the plastic-soil solver (coupled tangent of every
//      harmonic, multipliers updated around its Newton iteration) and the
//      interface solver (Newton on the condensed interface system) give
//      the same load at every step to 1e-8 relative (measured 2e-14), at
//      Tolerance 1e-10 for both: each stops at |R| <= 1e-10 of its force
//      scale and at multipliers whose change has a nodal force within
//      1e-10 of that scale, so 1e-8 is what both resolve (at
//      the slice's own 1e-8 they were 3e-7 apart). They share only the
//      interface law.
//  (2) the penalty limit: smooth and tensionless (phi = 0, c = 0), contact
//      against the 1/kappa extrapolation of `coulomb` penalty runs at
//      kappa = kn l / G = 1e4 and 1e5 (kn = 3e6, 3e7 kPa/m; G / l =
//      3000 kPa / 10 m), H_inf = H(1e5) + (H(1e5) - H(1e4)) / 9, to 1e-4
//      relative at every step. Reason: the penalty error is a / kappa +
//      O(1 / kappa^2); the extrapolation's own error is of order
//      (H(1e5) - H(1e4)) / 10 = 1.5e-4 H(1e5) / 10, about 2e-5 H, and the
//      soil is path dependent, so a step sequence that differed would
//      move H by far more (the test checks that the steps match). A
//      contact that kept its augmentation (1e3 G / l) as a spring would
//      be off by about H(1e4) - H(1e3) ~ 1.3e-2 H.
//  (3) friction, slip and a gap: `contact, phi=20` at every converged step:
//      no tension (t_n <= 1e-9 of the largest |t_n|), no penetration
//      (d_n >= -1e-7 of the largest |d|: what the multiplier updates
//      resolve at Tolerance 1e-8; measured 1.7e-8), |t| on or inside the
//      Coulomb cone (f <= 1e-9 kPa scale), samples sticking, slipping and open
//      at the last step, the soil in equilibrium and on or inside Tresca, at
//      most 15 multiplier updates and 60 Newton iterations a step (measured 5-7
//      and 7-12: about 1-2 updates of Newton per multiplier update).
#include "coupled_interface_test_support.h"
#include "soil_test_support.h"

#include <algorithm>
#include <cmath>

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  /**
   * The slice with `interface_law` on the shaft and `laws` for the soil,
   * to u = target in `steps` steps, at the force tolerance given (both
   * engines read Load path).
   */
  std::string
  slice(const std::string &interface_law,
        const std::string &laws,
        const std::string &target    = "0.00875",
        const std::string &steps     = "7",
        const std::string &tolerance = "1e-8")
  {
    return test_support::bundled_prm("prm/pile-capacity.prm",
                                     {{"Harmonics", "0, 1, 2, 3, 4"},
                                      {"Target", target},
                                      {"Load steps", steps},
                                      {"Tolerance", tolerance},
                                      {"Interfaces", "5: " + interface_law},
                                      {"Laws", laws}}) +
           test_support::entries("Load path",
                                 {{"Theta samples", "9"},
                                  {"Stiffness", "tangent"}});
  }

  std::vector<LoadStepResult>
  soil_curve(const std::string &text)
  {
    Run run(text);
    run.solver->run(std::cout);
    return run.solver->get_steps();
  }

  void
  check_same_steps(const std::string                 &name,
                   const std::vector<LoadStepResult> &a,
                   const std::vector<LoadStepResult> &b)
  {
    check::equal(name + ": converged steps", a.size(), b.size());
    for (unsigned int s = 0; s < a.size() && s < b.size(); ++s)
      check::relative(name + ": step " + std::to_string(s + 1) + " u",
                      a[s].motion.horizontal_displacement,
                      b[s].motion.horizontal_displacement,
                      1e-12);
  }

  void
  check_two_engines()
  {
    std::cout << "(1) soil that never yields: soil engine vs interface engine"
              << std::endl;
    const std::string law = "contact, phi=0";
    const auto        soil =
      soil_curve(slice(law, "0: tresca, su=1e6", "0.01", "4", "1e-10"));
    const auto alone =
      coupled_test::solve_steps(slice(law, "", "0.01", "4", "1e-10"));
    check::equal("converged steps", soil.size(), alone.steps.size());
    for (unsigned int s = 0; s < soil.size() && s < alone.steps.size(); ++s)
      check::relative("step " + std::to_string(s + 1) + " H",
                      soil[s].load_factor,
                      alone.steps[s].load_factor,
                      1e-8);
  }

  void
  check_penalty_limit()
  {
    std::cout << "(2) contact against the 1/kappa extrapolation" << std::endl;
    const std::string tresca = "0: tresca, su=10";
    const auto        exact  = soil_curve(slice("contact, phi=0", tresca));
    const auto        soft   = soil_curve(
      slice("coulomb, kn=3e6, ks=3e6, c=0, phi=0, sigma_t=0", tresca));
    const auto stiff = soil_curve(
      slice("coulomb, kn=3e7, ks=3e7, c=0, phi=0, sigma_t=0", tresca));
    check_same_steps("contact vs kappa = 1e4", exact, soft);
    check_same_steps("contact vs kappa = 1e5", exact, stiff);
    for (unsigned int s = 0;
         s < exact.size() && s < soft.size() && s < stiff.size();
         ++s)
      {
        const double limit = stiff[s].load_factor +
                             (stiff[s].load_factor - soft[s].load_factor) / 9.;
        check::relative("step " + std::to_string(s + 1) +
                          " H vs the penalty limit",
                        exact[s].load_factor,
                        limit,
                        1e-4);
      }
    check_equilibrium_and_yield("contact, phi = 0: ", exact, 10.);
  }

  void
  check_contact_conditions()
  {
    std::cout << "(3) friction, slip and a gap: the contact conditions"
              << std::endl;
    const auto steps =
      soil_curve(slice("contact, phi=20", "0: tresca, su=10", "0.01", "8"));
    double       most_tension = -1e300, largest_pressure = 0.;
    double       most_penetration = 0., largest_relative = 0.;
    unsigned int most_updates = 0, most_iterations = 0;
    for (const LoadStepResult &s : steps)
      {
        const InterfaceSnapshot &state = s.interface_state;
        for (unsigned int k = 0; k < state.traction.size(); ++k)
          {
            most_tension = std::max(most_tension, state.traction[k][1]);
            largest_pressure =
              std::max(largest_pressure, std::abs(state.traction[k][1]));
            most_penetration =
              std::max(most_penetration, -state.relative[k][1]);
            for (const double d : state.relative[k])
              largest_relative = std::max(largest_relative, std::abs(d));
          }
        most_updates    = std::max(most_updates, s.multiplier_updates);
        most_iterations = std::max(most_iterations, s.iterations);
      }
    check::in_range("largest t_n / largest |t_n| (no tension)",
                    most_tension / largest_pressure,
                    -1e300,
                    1e-9);
    check::in_range("largest -d_n / largest |d| (no penetration)",
                    most_penetration / largest_relative,
                    -1e300,
                    1e-7);
    check_interface_admissible("contact, phi = 20", steps, 1e-9 * 10.);
    check_equilibrium_and_yield("contact, phi = 20: ", steps, 10.);
    const ContactCounts &last = steps.back().contact;
    for (unsigned int c = 0; c < 3; ++c)
      check::in_range(std::string("samples ") +
                        (c == 0 ? "sticking" :
                         c == 1 ? "slipping" :
                                  "open") +
                        " at the last step",
                      last[c],
                      1u,
                      1000u);
    check::in_range("multiplier updates per step (most)", most_updates, 1, 15);
    check::in_range("Newton iterations per step (most)",
                    most_iterations,
                    1,
                    60);
  }
} // namespace

int
main()
{
  check_two_engines();
  check_penalty_limit();
  check_contact_conditions();
  return check::summary();
}
