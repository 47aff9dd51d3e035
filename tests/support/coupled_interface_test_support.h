// Helpers shared by the tests of the coupled (nonlinear-interface) solve:
// run a scene's load steps through CoupledSolver on a HarmonicSet,
// and the linear stiffness of the same scene with a linear law.
#ifndef fourier_ssi_tests_coupled_interface_test_support_h
#define fourier_ssi_tests_coupled_interface_test_support_h

#include "factorized_scene.h"
#include "two_ranks.h"

#include <fourier_ssi/coupled/coupled_solver.h>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace coupled_test
{
  using namespace FourierSSI;

  /** One converged step of a lateral (H, u) curve. */
  struct Step
  {
    double       H = 0., u = 0.; // [kN], [m]
    unsigned int iterations = 0, n_harmonics = 0;
    unsigned int stick = 0, slip = 0, open = 0;
    double       equilibrium = 0.; // |resultant_x - H| / |H|
  };

  struct Curve
  {
    std::vector<Step> steps;
    /** Harmonics of the set after the run (growth included). */
    unsigned int n_harmonics = 0;
    double       seconds     = 0.;
  };

  /**
   * prm/disc-gap.prm (the disc in a ring) with `law` on the interface
   * (boundary 5, the text after "5: "), harmonics n = 0..32, no VTU: the
   * scene of the Newton, contact and Newton-on-ranks tests.
   */
  inline std::string
  disc_in_ring(const std::string &law)
  {
    std::string text = test_support::bundled_prm("prm/disc-gap.prm");
    text = test_support::with_entry(text, "Interfaces", "5: " + law);
    text = test_support::with_entry(text, "Write vtu", "false");
    std::string harmonics = "0";
    for (unsigned int n = 1; n <= 32; ++n)
      harmonics += ", " + std::to_string(n);
    return test_support::with_entry(text, "Harmonics", harmonics);
  }

  /** G / l of the free-head pile's shaft faces (3000 kPa, l = 10 m / 12). */
  constexpr double free_head_pile_G_over_l = 3000. / (10. / 12.); // kPa/m

  /**
   * prm/pile-free-head.prm in elastic soil with `law` on the shaft (the
   * text after "5: "), n = 0..4 with Theta samples = 2 n_max + 1 = 9,
   * Newton, pushed to u = 0.02 m in 2 steps, the nonlinear interfaces
   * integrated by `integration` (gauss or nodal): the scene of the
   * frictional-contact and stiff-penalty tests.
   */
  inline std::string
  free_head_pile(const std::string &law, const std::string &integration)
  {
    std::string text = test_support::bundled_prm("prm/pile-free-head.prm",
                                                 {{"Laws", ""},
                                                  {"Soil reaction depths", ""},
                                                  {"Interfaces", "5: " + law},
                                                  {"Theta samples", "9"},
                                                  {"Load steps", "2"},
                                                  {"Target", "0.02"}});
    return text + "subsection Load path\n  set Stiffness = tangent\nend\n" +
           "subsection Interfaces\n  set Nonlinear integration = " +
           integration + "\nend\n";
  }

  /**
   * A tensionless coulomb shaft of the free-head pile, phi = 20, c = 0,
   * kn = ks = kappa G / l.
   */
  inline std::string
  free_head_pile_penalty(const double kappa)
  {
    std::ostringstream law;
    law << std::setprecision(17)
        << "coulomb, kn=" << kappa * free_head_pile_G_over_l
        << ", ks=" << kappa * free_head_pile_G_over_l
        << ", c=0, phi=20, sigma_t=0";
    return law.str();
  }

  /** The solver's load steps; their log echoed to std::cout and returned. */
  inline std::string
  run_with_log(CoupledSolver &solver)
  {
    std::ostringstream log;
    solver.run(log);
    std::cout << log.str();
    return log.str();
  }

  /** The converged load steps of a coupled solve, as the solver gives them. */
  struct StepResults
  {
    std::vector<LoadStepResult> steps;
    std::vector<double>         applied; // H or P per step [kN]
    /** Harmonics of the set after the run (growth included). */
    unsigned int n_harmonics = 0;
    double       seconds     = 0.;
  };

  /**
   * The scene's load steps through CoupledSolver, serial or with
   * the harmonics distributed over the ranks of MPI_COMM_WORLD.
   */
  inline StepResults
  solve_steps(const std::string &text,
              const bool         distributed = false,
              std::ostream      &log         = std::cout)
  {
    test_support::FactorizedScene scene(text, distributed);
    CoupledSolver                 solver(scene.set, scene.parameters);
    solver.run(log);
    StepResults results;
    results.steps = solver.get_steps();
    for (const LoadStepResult &r : results.steps)
      {
        results.applied.push_back(solver.applied_loads(r.load_factor)[0]);
        results.seconds += r.time;
      }
    results.n_harmonics = scene.set.size();
    return results;
  }

  /**
   * solve_steps() alone on every rank and then with the harmonics over the
   * ranks (two_ranks::serial_and_distributed), the converged step counts
   * compared on rank 0; (serial, distributed), meaningful on rank 0.
   */
  inline std::pair<StepResults, StepResults>
  solve_steps_serial_and_distributed(const std::string &name,
                                     const std::string &text)
  {
    auto pair = two_ranks::serial_and_distributed(
      [&](const bool distribute, std::ostream &log) {
        return solve_steps(text, distribute, log);
      },
      name + ", harmonics distributed over 2 ranks:");
    if (two_ranks::is_root())
      check::equal(name + ": converged steps, 2 ranks vs 1",
                   pair.second.steps.size(),
                   pair.first.steps.size());
    return pair;
  }

  /** The serial solve_steps() as a lateral (H, u) curve. */
  inline Curve
  run(const std::string &text, std::ostream &log = std::cout)
  {
    const StepResults results = solve_steps(text, false, log);
    Curve             curve;
    for (unsigned int i = 0; i < results.steps.size(); ++i)
      {
        const LoadStepResult &r = results.steps[i];
        Step                  s;
        s.H           = results.applied[i];
        s.u           = r.motion.horizontal_displacement;
        s.iterations  = r.iterations;
        s.n_harmonics = r.n_harmonics;
        s.stick       = r.contact[0];
        s.slip        = r.contact[1];
        s.open        = r.contact[2];
        s.equilibrium = std::abs(r.resultant[0] - s.H) / std::abs(s.H);
        curve.steps.push_back(s);
      }
    curve.seconds     = results.seconds;
    curve.n_harmonics = results.n_harmonics;
    return curve;
  }

  /**
   * H / u of the scene with a linear interface law and n = 1 only (the
   * lateral load's harmonic): the linear elastic slope [kN/m].
   */
  inline double
  linear_lateral_slope(std::string text, const std::string &law)
  {
    // A linear scene is one solve of the unit load: no displacement
    // control and no capacity (both refused there).
    text = std::regex_replace(text,
                              std::regex("set Control *= *displacement"),
                              "set Control = load");
    text =
      std::regex_replace(text,
                         std::regex("set Capacity normalisation *= [^\n]*"),
                         "set Capacity normalisation =");
    text = test_support::with_entry(text, "Interfaces", law);
    text = test_support::with_entry(text, "Harmonics", "1");
    test_support::FactorizedScene scene(text);
    const AllParameters          &parameters = scene.parameters;
    HarmonicSet                  &set        = scene.set;
    const RigidMotion             m =
      set.problem(0).get_foundation()->motion(scene.linear_solutions()[0]);
    return parameters.rigid_foundation.horizontal_force /
           m.horizontal_displacement;
  }
} // namespace coupled_test

#endif
