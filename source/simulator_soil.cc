// The driver's path for scenes with plastic soil: the harmonics are coupled
// through theta at the soil's quadrature points, so they are solved together
// by CoupledSoilSolver on one HarmonicSet (doc/soil-plasticity.md).
#include <cmath>
#include <deal.II/base/timer.h>
#include <fourier_ssi/capacity_plateau.h>
#include <fourier_ssi/coupled_iteration.h>
#include <fourier_ssi/coupled_soil_solver.h>
#include <fourier_ssi/discretization_design.h>
#include <fourier_ssi/simulator.h>
#include <iomanip>
#include <limits>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Soil plasticity";

    /**
     * Target accuracy: the ratio of the capacity's changes per doubling of
     * n_max where fewer than three values cannot show it; the capacity
     * studies measured 0.27-0.46 (doc/soil-plasticity.md 8b).
     */
    constexpr double harmonic_doubling_ratio = 0.5;

    /** What the plastic-soil path does not do yet: one line each. */
    void
    check_supported(const AllParameters &parameters, const MPI_Comm comm)
    {
      // Coulomb interfaces iterate with the soil (one correction load for
      // both), on the harmonics given: no growth.
      const NonlinearInterfaceParameters &settings =
        parameters.nonlinear_interfaces;
      AssertThrow(!parameters.interfaces.any_nonlinear() ||
                    settings.maximum_harmonic <=
                      highest_harmonic(parameters.discretization.harmonics),
                  ExcMessage("Nonlinear interfaces/Maximum harmonic: not "
                             "yet with plastic soil (the harmonics do not "
                             "grow); list them in Discretization/Harmonics"));
      AssertThrow(parameters.discretization.refinement_cycles == 1,
                  ExcMessage(entry + ": not yet: Discretization/Refinement "
                                     "cycles > 1 with plastic soil"));
      // Under mpirun the harmonics are distributed over the ranks (each
      // harmonic's system serial; Stiffness = tangent is refused by the
      // solver); one harmonic's system over several ranks is the other kind
      // of distribution.
      (void)comm;
      AssertThrow(!parameters.solver.distributed_always,
                  ExcMessage(entry + ": not yet: Linear solver/Distributed = "
                                     "always (a harmonic's system over "
                                     "several ranks) with plastic soil; "
                                     "under mpirun the harmonics are "
                                     "distributed over the ranks"));
      AssertThrow(parameters.output.lines.empty() &&
                    !parameters.output.write_3d_vtu,
                  ExcMessage(entry + ": not yet: Output/Lines 3D and Write "
                                     "3d vtu with plastic soil"));
      AssertThrow(!parameters.rigid_foundation.stiffness_coefficients,
                  ExcMessage(entry + ": Rigid foundation/Stiffness "
                                     "coefficients are linear quantities; "
                                     "set it false with plastic soil"));
    }

    /** The plastic state of every converged step, after the common rows. */
    void
    add_plastic_state_rows(const CoupledSoilSolver &solver,
                           const AllParameters     &parameters,
                           ResultsTable            &results)
    {
      const Harmonic any{0, Family::symmetric};
      const auto    &steps = solver.get_steps();
      for (unsigned int s = 0; s < steps.size(); ++s)
        {
          results.add(
            "step_plastic_samples", any, s + 1, steps[s].n_plastic, "-");
          results.add("step_largest_yield_value",
                      any,
                      s + 1,
                      steps[s].largest_yield_value,
                      "kPa");
          if (!parameters.interfaces.any_nonlinear())
            continue;
          const ContactCounts &contact = steps[s].contact;
          results.add(
            "step_interface_stick_samples", any, s + 1, contact[0], "-");
          results.add(
            "step_interface_slip_samples", any, s + 1, contact[1], "-");
          results.add(
            "step_interface_open_samples", any, s + 1, contact[2], "-");
          results.add("step_interface_largest_yield_value",
                      any,
                      s + 1,
                      steps[s].largest_interface_yield_value,
                      "kPa");
        }
    }

    /**
     * Displacement control: the capacity as the plateau of the curve, the
     * load that works on the controlled motion at the last step; how much
     * it rose over the last tenth of the controlled path and the plateau's
     * error (the rise to the asymptote of the last three steps,
     * capacity_plateau.h). A plateau rises little; the mesh and harmonic
     * errors need other meshes (Target accuracy, doc/soil-plasticity.md 8c).
     */
    struct Capacity
    {
      NamedLoad load;
      double    rise = 0., plateau_error = 0.;
    };

    /** The capacity of a displacement-controlled curve of >= 2 steps. */
    Capacity
    capacity_of(const CoupledSoilSolver &solver,
                const AllParameters     &parameters)
    {
      const NonlinearInterfaceParameters &settings =
        parameters.nonlinear_interfaces;
      const auto &steps   = solver.get_steps();
      const auto  load_at = [&](const SoilStepResult &s) {
        return conjugate_load(solver.applied_loads(s.load_factor,
                                                   s.held_fraction),
                              parameters.rigid_foundation,
                              settings.motion);
      };
      const auto motion_at = [&](const SoilStepResult &s) {
        return controlled_component(s.motion, settings.motion);
      };
      // The controlled path starts where the held loads left it.
      double start = 0.;
      for (const SoilStepResult &s : steps)
        if (s.load_factor == 0.)
          start = motion_at(s);
      const double end     = motion_at(steps.back());
      Capacity     result  = {load_at(steps.back()), 0., 0.};
      double       earlier = 0.;
      for (const SoilStepResult &s : steps)
        if (std::abs(motion_at(s) - start) <=
            0.9 * std::abs(end - start) * (1. + 1e-12))
          earlier = load_at(s).value;
      result.rise = result.load.value != 0. ?
                      (result.load.value - earlier) / result.load.value :
                      0.;
      std::vector<double> motion, load;
      for (const SoilStepResult &s : steps)
        if (s.load_factor != 0.)
          {
            motion.push_back(motion_at(s) - start);
            load.push_back(load_at(s).value);
          }
      result.plateau_error = plateau_error(motion, load);
      return result;
    }

    bool
    has_capacity(const CoupledSoilSolver &solver,
                 const AllParameters     &parameters)
    {
      return parameters.nonlinear_interfaces.control ==
               NonlinearInterfaceParameters::Control::displacement &&
             solver.get_steps().size() >= 2;
    }

    /** The capacity's rows and log line. */
    void
    report_capacity(const CoupledSoilSolver &solver,
                    const AllParameters     &parameters,
                    std::ostream            &log,
                    ResultsTable            &results)
    {
      if (!has_capacity(solver, parameters))
        return;
      const Capacity     c     = capacity_of(solver, parameters);
      const NamedLoad    last  = c.load;
      const double       rise  = c.rise;
      const double       error = c.plateau_error;
      const unsigned int step  = solver.get_steps().size();
      const Harmonic     any{0, Family::symmetric};
      results.add("capacity_" + last.name, any, step, last.value, last.unit);
      results.add(
        "capacity_" + last.name + "_plateau_rise", any, step, rise, "-");
      results.add("capacity_" + last.name + "_plateau_error",
                  any,
                  step,
                  error,
                  last.unit);
      log << "capacity (the load at the end of the controlled path): "
          << last.name << " = " << last.value << " " << last.unit
          << "; it rose " << 100. * rise << " % over the last tenth of the path"
          << (std::abs(rise) < 0.01 ? " (a plateau)" :
                                      " (not a plateau yet: go further)")
          << (std::isfinite(error) ?
                "; the asymptote of the last three steps lies " +
                  (std::ostringstream() << error).str() + " " + last.unit +
                  " beyond it (the plateau's error; the mesh and harmonic "
                  "errors: Discretization/Target accuracy, or "
                  "tools/capacity.py)" :
                std::string("; the plateau's error is unbounded (the last "
                            "three steps do not bend over, or there are "
                            "fewer than three)"))
          << std::endl;
    }

    /**
     * Target accuracy: the harmonic sets n <= n_max / 4 and n_max / 2
     * whose capacities, with the scene's, give the truncation error (only
     * those that keep the loaded harmonics, n <= 1, and differ from the
     * scene's).
     */
    std::vector<unsigned int>
    truncations(const std::vector<Harmonic> &harmonics)
    {
      const unsigned int        n_max = highest_harmonic(harmonics);
      std::vector<unsigned int> result;
      for (const unsigned int n : {n_max / 4, n_max / 2})
        if (n >= 1 && n < n_max && (result.empty() || result.back() != n))
          result.push_back(n);
      return result;
    }
  } // namespace

  void
  Simulator::solve_plastic_soil(std::ostream &log)
  {
    check_supported(parameters, communicator);
    if (parameters.discretization.target_accuracy > 0.)
      {
        solve_plastic_soil_to_target(log);
        return;
      }
    const std::unique_ptr<CoupledSoilSolver> solver =
      solve_plastic_curve(log, true);
    add_plastic_rows(*solver, log);
    write_plastic_files(*solver, log);
  }

  std::unique_ptr<CoupledSoilSolver>
  Simulator::solve_plastic_curve(std::ostream &log, const bool keep_incomplete)
  {
    Timer timer;
    make_distributed_harmonic_set();
    log << "assembled and factorized " << harmonic_set->size()
        << " harmonics in " << timer.wall_time() << " s" << std::endl;
    log_harmonic_distribution(log);
    auto solver =
      std::make_unique<CoupledSoilSolver>(*harmonic_set, parameters);
    // Keep the converged steps, marked as such by the file name (not in
    // `written`: a failed run removes its results, not this record).
    run_keeping_converged_steps(*solver,
                                log,
                                keep_incomplete && writes_csv() ?
                                  parameters.output.directory +
                                    "/load-displacement-incomplete.csv" :
                                  "");
    log << "coupled solve: " << solver->get_steps().size() << " steps in "
        << timer.wall_time() << " s" << std::endl;
    return solver;
  }

  void
  Simulator::add_plastic_rows(const CoupledSoilSolver &solver,
                              std::ostream            &log)
  {
    add_load_step_rows(solver, results);
    add_plastic_state_rows(solver, parameters, results);
    report_capacity(solver, parameters, log, results);
  }

  void
  Simulator::write_plastic_files(const CoupledSoilSolver &solver,
                                 std::ostream            &log)
  {
    if (!writes_csv())
      return;
    const std::string directory = parameters.output.directory;
    const std::string curve     = directory + "/load-displacement.csv";
    written.push_back(curve);
    solver.write_csv(curve);
    log << "load-displacement curve written to " << curve << std::endl;
    if (solver.has_coulomb_interfaces())
      {
        const std::string state = directory + "/interface-state.csv";
        written.push_back(state);
        solver.write_interface_state_csv(state);
        log << "interface state around the circumference written to " << state
            << std::endl;
      }
    const std::string name = directory + "/" + parameters.output.results_file;
    written.push_back(name);
    results.write_csv(name);
    log << "results written to " << name << std::endl;
  }

  std::vector<double>
  Simulator::capacities_with_fewer_harmonics(std::ostream &log)
  {
    const std::vector<Harmonic> all = plan.harmonics;
    std::vector<double>         values;
    for (const unsigned int n_max : truncations(all))
      {
        plan.harmonics.clear();
        for (const Harmonic &h : all)
          if (h.n <= n_max)
            plan.harmonics.push_back(h);
        // Its own log: the study's curves are not the answer's.
        std::ostringstream study_log;
        try
          {
            const auto solver = solve_plastic_curve(study_log, false);
            values.push_back(capacity_of(*solver, parameters).load.value);
          }
        catch (...)
          {
            plan.harmonics = all;
            throw;
          }
        plan.harmonics = all;
        harmonic_set.reset();
        log << "  harmonics n <= " << n_max << ": capacity " << values.back()
            << std::endl;
      }
    return values;
  }

  void
  Simulator::solve_plastic_soil_to_target(std::ostream &log)
  {
    // Members: the scene's mesh and element refined globally k times (the
    // error at bonded corners and shear bands falls by about one halving
    // per member); on member 0 the harmonic truncation (n_max / 4, n_max /
    // 2, n_max); on every member the plateau's error. The answer is the
    // last member's capacity (doc/soil-plasticity.md section 8c).
    const double        target = parameters.discretization.target_accuracy;
    Timer               run_timer;
    double              last_member_time = 0.;
    std::vector<double> mesh_values, harmonic_values;
    std::unique_ptr<CoupledSoilSolver> solver;
    Capacity                           capacity;
    double                             harmonic_error = 0., mesh_error = 0.;
    bool                               harmonics_estimated = false;
    for (unsigned int member = 0;; ++member)
      {
        if (member > 0)
          {
            // The coupled tangent is one LU over all harmonics: their DoFs
            // together are what Maximum DoFs bounds here.
            double dofs = 0.;
            for (unsigned int h = 0; h < harmonic_set->size(); ++h)
              dofs += harmonic_set->problem(h).get_dof_handler().n_dofs();
            Triangulation<2> next;
            DiscretizationDesign::build_plastic_member(parameters,
                                                       member,
                                                       interface_ids,
                                                       next);
            const double growth = static_cast<double>(next.n_active_cells()) /
                                  triangulation.n_active_cells();
            if (growth * dofs > parameters.adaptivity.maximum_dofs)
              {
                std::ostringstream line;
                line << "Discretization/Target accuracy " << target
                     << " not reached: estimated relative error of the "
                        "capacity ";
                if (mesh_values.size() >= 2)
                  line << std::setprecision(2)
                       << (mesh_error + harmonic_error +
                           capacity.plateau_error) /
                            std::abs(capacity.load.value);
                else
                  line << "unknown (one mesh solved)";
                line << " with " << static_cast<long long>(dofs)
                     << " DoFs (all harmonics); the next mesh (about "
                     << static_cast<long long>(growth * dofs)
                     << ") exceeds Adaptivity/Maximum DoFs = "
                     << std::setprecision(6)
                     << parameters.adaptivity.maximum_dofs;
                target_not_reached = line.str();
                log << target_not_reached << std::endl;
                break;
              }
            solver.reset();
            reconstruction = FieldReconstruction();
            harmonic_set.reset();
            outcomes.clear();
            DiscretizationDesign::build_plastic_member(parameters,
                                                       member,
                                                       interface_ids,
                                                       triangulation);
          }
        Timer member_timer;
        log << "target accuracy " << target << ": mesh " << member << ", "
            << triangulation.n_active_cells() << " cells" << std::endl;
        if (member == 0)
          {
            // The truncation on the coarsest mesh: cheap, and the
            // harmonics' share of the error changes little with the mesh
            // (doc/soil-plasticity.md 8b).
            harmonic_values = capacities_with_fewer_harmonics(log);
          }
        solver = solve_plastic_curve(log, false);
        AssertThrow(has_capacity(*solver, parameters),
                    ExcMessage("Discretization/Target accuracy: the curve "
                               "has fewer than two steps (Nonlinear "
                               "interfaces/Load steps)"));
        capacity = capacity_of(*solver, parameters);
        mesh_values.push_back(capacity.load.value);
        last_member_time = member_timer.wall_time();
        if (!std::isfinite(capacity.plateau_error))
          {
            target_not_reached =
              "Discretization/Target accuracy " +
              (std::ostringstream() << target).str() +
              " not reached: the curve does not bend over by its end "
              "(no plateau: raise Nonlinear interfaces/Target)";
            log << target_not_reached << std::endl;
            break;
          }
        if (member == 0)
          {
            harmonic_values.push_back(capacity.load.value);
            harmonics_estimated = harmonic_values.size() >= 2;
            if (harmonics_estimated)
              harmonic_error = estimate_sequence_error(harmonic_values,
                                                       harmonic_doubling_ratio)
                                 .absolute;
            continue; // two meshes are needed for the mesh error
          }
        mesh_error =
          estimate_sequence_error(mesh_values, one_halving_ratio).absolute;
        const double total =
          (mesh_error + harmonic_error + capacity.plateau_error) /
          std::abs(capacity.load.value);
        log << "target accuracy " << target << ": mesh " << member
            << ", estimated relative error of the capacity "
            << std::setprecision(2) << total << std::setprecision(6)
            << std::endl;
        if (total <= target)
          break;
        // What a finer mesh cannot lower: stop, saying which.
        const double fixed = (harmonic_error + capacity.plateau_error) /
                             std::abs(capacity.load.value);
        if (fixed > target)
          {
            std::ostringstream line;
            line << "Discretization/Target accuracy " << target
                 << " not reached: estimated relative error of the capacity "
                 << std::setprecision(2) << total
                 << ", of which the harmonic truncation (n <= "
                 << highest_harmonic(plan.harmonics) << ") "
                 << harmonic_error / std::abs(capacity.load.value)
                 << " and the plateau "
                 << capacity.plateau_error / std::abs(capacity.load.value)
                 << " do not fall with the mesh: list more harmonics "
                    "(Discretization/Harmonics) or take the path further "
                    "(Nonlinear interfaces/Target)";
            target_not_reached = line.str();
            log << target_not_reached << std::endl;
            break;
          }
      }
    estimate_wall_time = run_timer.wall_time() - last_member_time;
    // The answer (the last member's curve), its error bar, the files.
    add_plastic_rows(*solver, log);
    const NamedLoad &load  = capacity.load;
    const double     scale = std::abs(load.value);
    const bool       two   = mesh_values.size() >= 2;
    const double     total =
      two ? (mesh_error + harmonic_error + capacity.plateau_error) / scale :
                std::numeric_limits<double>::quiet_NaN();
    const bool         reached = target_not_reached.empty() && total <= target;
    const Harmonic     any{0, Family::symmetric};
    const unsigned int step = solver->get_steps().size();
    const std::string  name = "capacity_" + load.name;
    log << "error estimate of the capacity (relative; the mesh from "
        << mesh_values.size() << " nested meshes, geometric tail; the "
        << "harmonics "
        << (harmonics_estimated ? "from n_max halved on the coarsest mesh" :
            highest_harmonic(plan.harmonics) == 0 ?
                                  "none (n = 0 only: an axisymmetric problem)" :
                                  "NOT estimated (n_max = 1 cannot be halved)")
        << "; the plateau):\n    " << load.name << " = " << std::setprecision(7)
        << load.value << " " << load.unit << " \u00b1 " << std::setprecision(2)
        << total << " (rel): mesh "
        << (two ? mesh_error / scale : std::numeric_limits<double>::quiet_NaN())
        << ", harmonics " << harmonic_error / scale << ", plateau "
        << capacity.plateau_error / scale << std::setprecision(6) << std::endl;
    results.add(name + "_error", any, step, total, "-");
    results.add(name + "_error_mesh",
                any,
                step,
                two ? mesh_error / scale :
                      std::numeric_limits<double>::quiet_NaN(),
                "-");
    results.add(
      name + "_error_harmonics", any, step, harmonic_error / scale, "-");
    results.add(
      name + "_error_plateau", any, step, capacity.plateau_error / scale, "-");
    results.add(name + "_converged", any, step, reached ? 1. : 0., "-");
    results.add("target_accuracy", any, step, target, "-");
    results.add("target_accuracy_reached", any, step, reached ? 1. : 0., "-");
    results.add("time_error_estimate", any, step, estimate_wall_time, "s");
    write_plastic_files(*solver, log);
  }
} // namespace FourierSSI
