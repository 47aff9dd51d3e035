// The driver's path for scenes with plastic soil: the harmonics are coupled
// through theta at the soil's quadrature points, so they are solved together
// by CoupledSolver on one HarmonicSet (doc/soil-plasticity.md).
#include <chrono>
#include <cmath>
#include <deal.II/base/timer.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/plastic_field_recorder.h>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/estimation/capacity_plateau.h>
#include <fourier_ssi/input/problem_checks.h>
#include <fourier_ssi/mesh/discretization_design.h>
#include <fourier_ssi/postprocess/plastic_field_output.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  namespace
  {
    /**
     * A rise of the foundation above this fraction of its horizontal
     * displacement is warned of (warn_weightless_heave); below it, the
     * round-off and the small uplift of an elastic rocking mode.
     */
    constexpr double heave_warning_fraction = 0.05;

    const std::string entry = "Soil plasticity";

    /** Target accuracy or Refinement cycles > 1: more than one mesh. */
    bool
    on_nested_meshes(const AllParameters &parameters)
    {
      return parameters.discretization.target_accuracy > 0. ||
             parameters.discretization.refinement_cycles > 1;
    }

    /** What the plastic-soil path does not do yet: one line each. */
    void
    check_supported(const AllParameters &parameters)
    {
      // Growth with a swipe (its second multiplier keeping w) is not
      // checked yet.
      const LoadPathParameters &settings = parameters.load_path;
      AssertThrow(!parameters.rigid_foundation.swipes() ||
                    settings.maximum_harmonic <=
                      highest_harmonic(parameters.discretization.harmonics),
                  ExcMessage("Load path/Maximum harmonic: not "
                             "yet with a swipe (the harmonics do not grow); "
                             "list them in Discretization/Harmonics"));
      check_coupled_path_supported(parameters,
                                   parameters.soil_plasticity.any() ?
                                     "plastic soil" :
                                     "a swipe through nonlinear interfaces");
      AssertThrow(parameters.output.lines.empty() &&
                    !parameters.output.write_3d_vtu,
                  ExcMessage(entry + ": not yet: Output/Lines 3D and Write "
                                     "3d vtu with plastic soil or a swipe"));
      AssertThrow(parameters.output.plastic_field_steps.empty() ||
                    !on_nested_meshes(parameters),
                  ExcMessage("Output/Plastic field steps: not yet with "
                             "Discretization/Target accuracy or Refinement "
                             "cycles > 1 (the field of the last step of the "
                             "last mesh only): set Plastic field steps = "
                             "last"));
      AssertThrow(!parameters.output.soil_reaction_curves() ||
                    !on_nested_meshes(parameters),
                  ExcMessage("Output/Soil reaction depths: not yet with "
                             "Discretization/Target accuracy or Refinement "
                             "cycles > 1 (the curves of one mesh); set "
                             "Refinement cycles = 1 and no target"));
    }

    /** The plastic state of every converged step, after the common rows. */
    void
    add_plastic_state_rows(const CoupledSolver &solver,
                           const AllParameters &parameters,
                           ResultsTable        &results)
    {
      const Harmonic any{0, Family::symmetric};
      const auto    &steps = solver.get_steps();
      // With growth (Maximum harmonic above the listed) the harmonics
      // solved at every step.
      const bool grows = parameters.load_path.maximum_harmonic >
                         highest_harmonic(parameters.discretization.harmonics);
      for (unsigned int s = 0; s < steps.size(); ++s)
        {
          if (grows)
            results.add(
              "step_harmonics", any, s + 1, steps[s].n_harmonics, "-");
          if (solver.n_soil_points() > 0)
            {
              results.add(
                "step_plastic_samples", any, s + 1, steps[s].n_plastic, "-");
              results.add("step_largest_yield_value",
                          any,
                          s + 1,
                          steps[s].largest_yield_value,
                          "kPa");
            }
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

    /** A load read at each converged step. */
    using LoadAtStep = std::function<NamedLoad(const LoadStepResult &)>;

    /** The applied load that works on the controlled motion. */
    LoadAtStep
    applied_load(const CoupledSolver &solver, const AllParameters &parameters)
    {
      return [&](const LoadStepResult &s) {
        return conjugate_load(solver.applied_loads(s.load_factor,
                                                   s.held_fraction),
                              parameters.rigid_foundation,
                              parameters.load_path.motion);
      };
    }

    /**
     * A direction probe's H (or M): the load on the foundation along the
     * probe (probe_H, probe_M), not the drive.
     */
    LoadAtStep
    probe_load(const FoundationMotion motion, const AllParameters &parameters)
    {
      return [motion, &parameters](const LoadStepResult &s) {
        NamedLoad load{parameters.rigid_foundation.reaction_row(motion),
                       load_unit_of(motion)};
        for (const auto &[held, value] : s.held_reactions)
          if (held == motion)
            load.value = value;
        return load;
      };
    }

    /**
     * The load whose capacity Target accuracy estimates: the applied load
     * on the controlled motion, or for a direction probe the probe's own
     * load on it (probe_H when u is driven, probe_M when the rotation is).
     */
    LoadAtStep
    goal_load(const CoupledSolver &solver, const AllParameters &parameters)
    {
      if (!parameters.rigid_foundation.probes_direction())
        return applied_load(solver, parameters);
      return probe_load(parameters.load_path.motion ==
                            LoadPathParameters::Motion::rotation ?
                          FoundationMotion::rotation :
                          FoundationMotion::u,
                        parameters);
    }

    /** The capacity of a displacement-controlled curve of >= 2 steps. */
    Capacity
    capacity_of(const CoupledSolver &solver,
                const AllParameters &parameters,
                const LoadAtStep    &load_at)
    {
      const LoadPathParameters &settings  = parameters.load_path;
      const auto               &steps     = solver.get_steps();
      const auto                motion_at = [&](const LoadStepResult &s) {
        return controlled_component(s.motion, settings.motion);
      };
      // The controlled path starts where the held loads left it.
      double start = 0.;
      for (const LoadStepResult &s : steps)
        if (s.load_factor == 0.)
          start = motion_at(s);
      const double end     = motion_at(steps.back());
      Capacity     result  = {load_at(steps.back()), 0., 0.};
      double       earlier = 0.;
      for (const LoadStepResult &s : steps)
        if (std::abs(motion_at(s) - start) <=
            0.9 * std::abs(end - start) * (1. + 1e-12))
          earlier = load_at(s).value;
      result.rise = result.load.value != 0. ?
                      (result.load.value - earlier) / result.load.value :
                      0.;
      std::vector<double> motion, load;
      for (const LoadStepResult &s : steps)
        if (s.load_factor != 0.)
          {
            motion.push_back(motion_at(s) - start);
            load.push_back(load_at(s).value);
          }
      result.plateau_error = plateau_error(motion, load);
      return result;
    }

    /** A displacement-controlled curve of >= 2 steps: it has a capacity. */
    bool
    has_capacity(const CoupledSolver &solver, const AllParameters &parameters)
    {
      // A cyclic path has loops, not a capacity (load-cycles.csv).
      return parameters.load_path.control ==
               LoadPathParameters::Control::displacement &&
             !parameters.load_path.is_cyclic() &&
             solver.get_steps().size() >= 2;
    }

    /**
     * A foundation with no vertical load on it (no Vertical force or Held
     * vertical force, w not held or driven, no Body force) is weightless:
     * pushed sideways over dilatant or frictional soil it rises, which a
     * real caisson or footing under its own weight does not. Warned, not
     * refused: the path is the one the input asks for.
     */
    void
    warn_weightless_heave(const CoupledSolver &solver,
                          const AllParameters &parameters,
                          std::ostream        &log)
    {
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      const LoadPathParameters        &path       = parameters.load_path;
      const bool                       drives_w =
        path.control == LoadPathParameters::Control::displacement &&
        path.motion == LoadPathParameters::Motion::vertical;
      if (!foundation.enabled || solver.get_steps().empty() ||
          foundation.vertical_force != 0. ||
          foundation.held_vertical_force != 0. ||
          foundation.holds(FoundationMotion::w) || drives_w ||
          !parameters.boundary_conditions.body_force.is_zero())
        return;
      const RigidMotion &motion = solver.get_steps().back().motion;
      const double       w      = motion.vertical_displacement;
      if (w > 0. &&
          w > heave_warning_fraction * std::abs(motion.horizontal_displacement))
        log << "warning: the foundation rose by w = +" << w
            << " m over the path (u = " << motion.horizontal_displacement
            << " m at the end) with no vertical load on it: a weightless "
               "foundation heaves as it is pushed; give Rigid "
               "foundation/Held vertical force (its weight, negative "
               "down) for the path of a real one"
            << std::endl;
    }

    /** The capacity's rows and log line. */
    void
    report_capacity(const Capacity      &c,
                    const CoupledSolver &solver,
                    std::ostream        &log,
                    ResultsTable        &results)
    {
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
     * The .pvd series of the plastic field: (step, file) per plane, and
     * the revolved files last.
     */
    using PlasticSeries =
      std::vector<std::vector<std::pair<double, std::string>>>;

    /** One step's plastic-field files and its log line. */
    void
    write_plastic_field_step(const PlasticFieldSnapshot &snapshot,
                             const OutputParameters     &output,
                             ResultFiles                &files,
                             PlasticSeries              &series,
                             std::ostream               &log)
    {
      log << "plastic field of step " << snapshot.step << " ("
          << snapshot.n_plastic << " plastic of " << snapshot.n_total
          << " samples, " << snapshot.n_samples << " theta samples) written to";
      const std::vector<double> &planes = output.plastic_field_planes;
      for (unsigned int i = 0; i < planes.size(); ++i)
        {
          const std::string name =
            plastic_field_plane_name(planes[i], snapshot.step);
          write_plastic_field_plane(snapshot, planes[i], files.claim(name));
          series[i].emplace_back(snapshot.step, name);
          // The plane shows the theta sample nearest to its angle.
          log << (i == 0 ? " " : ", ") << output.directory << "/" << name
              << " (theta sample "
              << theta_sample_degrees(snapshot.n_samples,
                                      nearest_theta_sample(snapshot.n_samples,
                                                           planes[i]))
              << " deg)";
        }
      if (output.plastic_field_3d)
        {
          const std::string name = plastic_field_3d_name(snapshot.step);
          write_plastic_field_revolved(snapshot,
                                       output.theta_divisions,
                                       files.claim(name));
          series.resize(planes.size() + 1);
          series.back().emplace_back(snapshot.step, name);
          log << (planes.empty() ? " " : ", ") << output.directory << "/"
              << name << " (" << output.theta_divisions << " sectors)";
        }
      log << std::endl;
    }

    /** The .pvd series of every plane and of the revolved files. */
    void
    write_plastic_field_series_files(const PlasticSeries    &series,
                                     const OutputParameters &output,
                                     ResultFiles            &files,
                                     std::ostream           &log)
    {
      const std::vector<double> &planes = output.plastic_field_planes;
      for (unsigned int i = 0; i < series.size(); ++i)
        write_pvd_series(series[i],
                         files.claim(i < planes.size() ?
                                       plastic_field_plane_series(planes[i]) :
                                       plastic_field_3d_series()));
      log << "plastic field series (.pvd, for ParaView) written to "
          << output.directory << "/plastic-field-*.pvd";
    }
  } // namespace

  void
  Simulator::solve_plastic_soil(std::ostream &log)
  {
    check_supported(parameters);
    if (on_nested_meshes(parameters))
      {
        solve_plastic_soil_on_meshes(log);
        return;
      }
    const std::unique_ptr<CoupledSolver> solver =
      solve_coupled_curve(log, true, [&](CoupledSolver &s) {
        record_soil_reactions(s);
        record_plastic_field(s);
      });
    add_plastic_rows(*solver, log);
    write_plastic_files(*solver, log);
  }

  void
  Simulator::record_soil_reactions(CoupledSolver &solver)
  {
    reaction_curves.reset();
    if (!parameters.output.soil_reaction_curves())
      return;
    // The reactions are those of n = 1, symmetric (H along x, M about y).
    unsigned int h = 0;
    while (h < harmonic_set->size() &&
           !(harmonic_set->harmonic(h).n == 1 &&
             harmonic_set->harmonic(h).family == Family::symmetric))
      ++h;
    AssertThrow(h < harmonic_set->size(),
                ExcMessage("Output/Soil reaction depths: Discretization/"
                           "Harmonics has no n = 1 (symmetric): no lateral "
                           "reaction"));
    reaction_curves = std::make_unique<SoilReactionCurves>(
      harmonic_set->problem(h).get_dof_handler(), parameters);
    SoilReactionCurves &curves = *reaction_curves;
    solver.add_step_observer([&solver, &curves, h, this](
                               const LoadStepResult &step) {
      const auto start = std::chrono::steady_clock::now();
      const auto shaft = solver.soil_nodal_force(
        [&](const Point<2> &c) { return curves.beside_shaft(c); });
      const auto base = solver.soil_nodal_force(
        [&](const Point<2> &c) { return curves.below_base(c); });
      const auto loads =
        solver.applied_loads(step.load_factor, step.held_fraction);
      curves.record(shaft[h],
                    base[h],
                    solver.solution(h),
                    step.motion,
                    loads[0],
                    moment_about_reference(loads, parameters.rigid_foundation));
      curves.wall_time +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    });
  }

  void
  Simulator::record_plastic_field(CoupledSolver &solver)
  {
    plastic_field.reset();
    if (solver.n_soil_points() == 0 ||
        !parameters.output.writes_plastic_field())
      return;
    plastic_field = std::make_unique<PlasticFieldRecorder>(solver,
                                                           *harmonic_set,
                                                           parameters.output);
    PlasticFieldRecorder &recorder = *plastic_field;
    solver.add_step_observer([&solver, &recorder](const LoadStepResult &) {
      recorder.observe(solver.get_steps().size());
    });
  }

  void
  Simulator::finish_plastic_field(const CoupledSolver &solver)
  {
    if (!plastic_field)
      return;
    plastic_field->finish(solver.get_steps().size());
  }

  void
  Simulator::write_plastic_field(std::ostream &log)
  {
    if (!plastic_field)
      return;
    const auto    start = std::chrono::steady_clock::now();
    PlasticSeries series(parameters.output.plastic_field_planes.size());
    for (const PlasticFieldSnapshot &snapshot : plastic_field->snapshots())
      write_plastic_field_step(
        snapshot, parameters.output, result_files, series, log);
    write_plastic_field_series_files(series,
                                     parameters.output,
                                     result_files,
                                     log);
    log << "; "
        << plastic_field->wall_time() +
             std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
               .count()
        << " s for the plastic field" << std::endl;
  }

  void
  Simulator::add_plastic_rows(const CoupledSolver &solver, std::ostream &log)
  {
    add_load_step_rows(solver);
    add_plastic_state_rows(solver, parameters, results);
    if (reaction_curves)
      {
        // The pile's balance of the curves (doc/soil-reaction-curves.md 2).
        const auto         imbalance = reaction_curves->largest_imbalance();
        const Harmonic     any{0, Family::symmetric};
        const unsigned int step = solver.get_steps().size();
        results.add(
          "soil_reaction_imbalance_H", any, step, imbalance.first, "-");
        results.add(
          "soil_reaction_imbalance_M", any, step, imbalance.second, "-");
        reaction_curves->add_result_rows(results);
      }
    keep_last_step(solver);
    add_held_reaction_rows(solver);
    warn_weightless_heave(solver, parameters, log);
    if (!has_capacity(solver, parameters))
      return;
    if (parameters.rigid_foundation.probes_direction())
      {
        // A direction probe's capacity is the point (probe_H, probe_M),
        // each with its plateau, not the applied load that drives it.
        for (const FoundationMotion motion :
             parameters.rigid_foundation.reported_motions())
          report_capacity(capacity_of(solver,
                                      parameters,
                                      probe_load(motion, parameters)),
                          solver,
                          log,
                          results);
        return;
      }
    const Capacity c =
      capacity_of(solver, parameters, applied_load(solver, parameters));
    report_capacity(c, solver, log, results);
    // Without a target the capacity's error bar is the plateau's alone.
    report_normalised_capacity(c.load.name,
                               c.load.value,
                               c.load.unit,
                               c.plateau_error / std::abs(c.load.value),
                               "the plateau's error only",
                               solver.get_steps().size(),
                               log);
  }

  void
  Simulator::write_plastic_files(const CoupledSolver &solver, std::ostream &log)
  {
    // Before any result file: a chosen step beyond the path stops the run
    // here (and the capture of the last step is a collective).
    finish_plastic_field(solver);
    check_interface_state_steps(solver);
    if (!writes_csv())
      return;
    write_load_displacement_csv(solver, log);
    if (solver.has_nonlinear_interfaces())
      {
        const std::string state = result_files.claim("interface-state.csv");
        solver.write_interface_state_csv(state);
        log << "interface state around the circumference written to " << state
            << std::endl;
        write_interface_state_3d(solver, log);
      }
    if (reaction_curves)
      {
        const std::string name = result_files.claim("soil-reaction-curves.csv");
        reaction_curves->write_csv(name);
        const auto imbalance = reaction_curves->largest_imbalance();
        log << "soil-reaction curves (" << reaction_curves->depths().size()
            << " depths x " << reaction_curves->n_steps()
            << " steps) written to " << name
            << "; the pile's balance over the steps: |int p + H_B - H| <= "
            << imbalance.first << " |H|, moments <= " << imbalance.second
            << " |H| L; " << reaction_curves->wall_time << " s for the curves"
            << std::endl;
      }
    // The stress of plastic soil is not C eps(u): displacements only (an
    // elastic soil's stress is).
    write_last_step_vtu(solver.n_soil_points() == 0, log);
    write_plastic_field(log);
    const std::string name = result_files.claim_results_file();
    results.write_csv(name);
    log << "results written to " << name << std::endl;
  }

  void
  Simulator::solve_plastic_soil_on_meshes(std::ostream &log)
  {
    // Displacement control aims at the capacity; load control at the work
    // of the loads at the end of the path (the scene's loads are reached:
    // a load step that does not converge stops the run).
    const bool load_control =
      parameters.load_path.control == LoadPathParameters::Control::load;
    std::unique_ptr<CoupledSolver> solver;
    CoupledCurveRun                run;
    run.goal_prefix = load_control ? "end_" : "capacity_";
    run.plateau     = !load_control;
    run.solve       = [&](std::ostream &out) {
      solver.reset();
      solver           = solve_coupled_curve(out, false);
      const auto steps = static_cast<unsigned int>(solver->get_steps().size());
      if (load_control)
        return CoupledGoal{"work", "kJ", solver->load_work(), 0., steps};
      AssertThrow(has_capacity(*solver, parameters),
                  ExcMessage("Discretization/Target accuracy: the curve "
                                   "has fewer than two steps (Load "
                                   "path/Load steps)"));
      const Capacity c =
        capacity_of(*solver, parameters, goal_load(*solver, parameters));
      return CoupledGoal{
        c.load.name, c.load.unit, c.load.value, c.plateau_error, steps};
    };
    run.release  = [&]() { solver.reset(); };
    run.add_rows = [&](std::ostream &out) { add_plastic_rows(*solver, out); };
    run.write_files = [&](std::ostream &out) {
      // The field of the last step of the last mesh (Plastic field steps
      // other than last are refused with a target).
      record_plastic_field(*solver);
      write_plastic_files(*solver, out);
    };
    run.last_solver = [&]() -> const CoupledSolver & { return *solver; };
    solve_coupled_on_meshes(log, run);
  }

} // namespace FourierSSI
