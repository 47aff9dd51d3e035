#include <chrono>
#include <cmath>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/load_path_capacity.h>
#include <fourier_ssi/driver/plastic_soil_output.h>
#include <fourier_ssi/postprocess/plastic_field_output.h>
#include <fourier_ssi/postprocess/vtu_output.h>
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
  PlasticStateRows::add_rows(const CoupledSolver     &solver,
                             const CoupledRunContext &context,
                             std::ostream &)
  {
    add_plastic_state_rows(solver, context.parameters, context.results);
  }

  void
  SoilReactionOutput::observe(CoupledSolver           &solver,
                              const CoupledRunContext &context)
  {
    curves.reset();
    const AllParameters &parameters = context.parameters;
    if (!parameters.output.soil_reaction_curves())
      return;
    // The reactions are those of n = 1, symmetric (H along x, M about y).
    const HarmonicSet &set = *context.harmonic_set;
    unsigned int       h   = 0;
    while (h < set.size() && !(set.harmonic(h).n == 1 &&
                               set.harmonic(h).family == Family::symmetric))
      ++h;
    AssertThrow(h < set.size(),
                ExcMessage("Output/Soil reaction depths: Discretization/"
                           "Harmonics has no n = 1 (symmetric): no lateral "
                           "reaction"));
    curves =
      std::make_unique<SoilReactionCurves>(set.problem(h).get_dof_handler(),
                                           parameters);
    SoilReactionCurves &recorded = *curves;
    solver.add_step_observer([&solver, &recorded, h, &parameters](
                               const LoadStepResult &step) {
      const auto start = std::chrono::steady_clock::now();
      const auto shaft = solver.soil_nodal_force(
        [&](const Point<2> &c) { return recorded.beside_shaft(c); });
      const auto base = solver.soil_nodal_force(
        [&](const Point<2> &c) { return recorded.below_base(c); });
      const auto loads =
        solver.applied_loads(step.load_factor, step.held_fraction);
      recorded.record(shaft[h],
                      base[h],
                      solver.solution(h),
                      step.motion,
                      loads[0],
                      moment_about_reference(loads,
                                             parameters.rigid_foundation));
      recorded.wall_time +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    });
  }

  void
  SoilReactionOutput::add_rows(const CoupledSolver     &solver,
                               const CoupledRunContext &context,
                               std::ostream &)
  {
    if (!curves)
      return;
    // The pile's balance of the curves (doc/soil-reaction-curves.md 2).
    const auto         imbalance = curves->largest_imbalance();
    const Harmonic     any{0, Family::symmetric};
    const unsigned int step = solver.get_steps().size();
    context.results.add(
      "soil_reaction_imbalance_H", any, step, imbalance.first, "-");
    context.results.add(
      "soil_reaction_imbalance_M", any, step, imbalance.second, "-");
    curves->add_result_rows(context.results);
  }

  void
  SoilReactionOutput::write_files(const CoupledSolver &,
                                  const CoupledRunContext &context,
                                  std::ostream            &log)
  {
    if (!context.writes_csv || !curves)
      return;
    const std::string name =
      context.result_files.claim("soil-reaction-curves.csv");
    curves->write_csv(name);
    const auto imbalance = curves->largest_imbalance();
    log << "soil-reaction curves (" << curves->depths().size() << " depths x "
        << curves->n_steps() << " steps) written to " << name
        << "; the pile's balance over the steps: |int p + H_B - H| <= "
        << imbalance.first << " |H|, moments <= " << imbalance.second
        << " |H| L; " << curves->wall_time << " s for the curves" << std::endl;
  }

  void
  WeightlessHeaveWarning::add_rows(const CoupledSolver     &solver,
                                   const CoupledRunContext &context,
                                   std::ostream            &log)
  {
    warn_weightless_heave(solver, context.parameters, log);
  }

  void
  CapacityReport::add_rows(const CoupledSolver     &solver,
                           const CoupledRunContext &context,
                           std::ostream            &log)
  {
    const AllParameters &parameters = context.parameters;
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
                          context.results);
        return;
      }
    const Capacity c =
      capacity_of(solver, parameters, applied_load(solver, parameters));
    report_capacity(c, solver, log, context.results);
    // Without a target the capacity's error bar is the plateau's alone.
    report_normalised_capacity(parameters.rigid_foundation,
                               c.load.name,
                               c.load.value,
                               c.load.unit,
                               c.plateau_error / std::abs(c.load.value),
                               "the plateau's error only",
                               solver.get_steps().size(),
                               context.results,
                               log);
  }

  void
  PlasticFieldOutput::observe(CoupledSolver           &solver,
                              const CoupledRunContext &context)
  {
    start_recording(solver, context);
    if (!recorder)
      return;
    PlasticFieldRecorder &recording = *recorder;
    solver.add_step_observer([&solver, &recording](const LoadStepResult &) {
      recording.observe(solver.get_steps().size());
    });
  }

  void
  PlasticFieldOutput::add_rows(const CoupledSolver     &solver,
                               const CoupledRunContext &context,
                               std::ostream &)
  {
    // On nested meshes the path was not observed: the field of its last
    // step (Plastic field steps other than last are refused there).
    if (!recorder)
      start_recording(solver, context);
    if (recorder)
      recorder->finish(solver.get_steps().size());
  }

  void
  PlasticFieldOutput::write_files(const CoupledSolver &,
                                  const CoupledRunContext &context,
                                  std::ostream            &log)
  {
    if (!context.writes_csv || !recorder)
      return;
    const OutputParameters &output = context.parameters.output;
    const auto              start  = std::chrono::steady_clock::now();
    PlasticSeries           series(output.plastic_field_planes.size());
    for (const PlasticFieldSnapshot &snapshot : recorder->snapshots())
      write_plastic_field_step(
        snapshot, output, context.result_files, series, log);
    write_plastic_field_series_files(series, output, context.result_files, log);
    log << "; "
        << recorder->wall_time() + std::chrono::duration<double>(
                                     std::chrono::steady_clock::now() - start)
                                     .count()
        << " s for the plastic field" << std::endl;
  }

  void
  PlasticFieldOutput::release()
  {
    recorder.reset();
  }

  void
  PlasticFieldOutput::start_recording(const CoupledSolver     &solver,
                                      const CoupledRunContext &context)
  {
    recorder.reset();
    if (solver.n_soil_points() == 0 ||
        !context.parameters.output.writes_plastic_field())
      return;
    recorder =
      std::make_unique<PlasticFieldRecorder>(solver,
                                             *context.harmonic_set,
                                             context.parameters.output);
  }
} // namespace FourierSSI
