#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/load_path_output.h>

namespace FourierSSI
{
  void
  LoadStepRows::add_rows(const CoupledSolver     &solver,
                         const CoupledRunContext &context,
                         std::ostream &)
  {
    ResultsTable  &results = context.results;
    const Harmonic any{0, Family::symmetric};
    const auto    &steps = solver.get_steps();
    for (unsigned int s = 0; s < steps.size(); ++s)
      {
        const LoadStepResult &r = steps[s];
        const auto loads = solver.applied_loads(r.load_factor, r.held_fraction);
        const RigidMotion &m    = r.motion;
        const unsigned int step = s + 1;
        results.add("step_load_factor", any, step, r.load_factor, "-");
        results.add("step_vertical_force",
                    any,
                    step,
                    vertical_force_of(loads, r.swipe_force),
                    "kN");
        results.add("step_horizontal_force", any, step, loads[0], "kN");
        results.add("step_moment", any, step, loads[4], "kN.m");
        results.add("step_torque", any, step, loads[5], "kN.m");
        results.add("step_vertical_displacement",
                    any,
                    step,
                    m.vertical_displacement,
                    "m");
        results.add("step_horizontal_displacement",
                    any,
                    step,
                    m.horizontal_displacement,
                    "m");
        results.add("step_rotation", any, step, m.rotation, "rad");
        results.add("step_twist", any, step, m.twist, "rad");
        results.add("step_iterations", any, step, r.iterations, "-");
        results.add("step_residual", any, step, r.residual, "-");
        results.add("step_wall_time", any, step, r.time, "s");
      }
  }

  void
  HeldReactionRows::add_rows(const CoupledSolver     &solver,
                             const CoupledRunContext &context,
                             std::ostream &)
  {
    const Harmonic any{0, Family::symmetric};
    for (const auto &[motion, load] : solver.get_steps().back().held_reactions)
      context.results.add(context.parameters.rigid_foundation.reaction_row(
                            motion),
                          any,
                          solver.get_steps().size(),
                          load,
                          load_unit_of(motion));
  }

  void
  LoadDisplacementCurve::observe(CoupledSolver           &solver,
                                 const CoupledRunContext &context)
  {
    if (!context.writes_csv)
      return;
    const std::string incomplete =
      context.result_files.path_of("load-displacement-incomplete.csv");
    written = false;
    solver.add_step_observer(
      [this, &solver, incomplete](const LoadStepResult &) {
        if (written && since_written.wall_time() < incomplete_curve_interval)
          return;
        solver.write_csv(incomplete);
        since_written.restart();
        written = true;
      });
  }

  void
  LoadDisplacementCurve::write_files(const CoupledSolver     &solver,
                                     const CoupledRunContext &context,
                                     std::ostream            &log)
  {
    if (!context.writes_csv)
      return;
    const std::string curve =
      context.result_files.claim("load-displacement.csv");
    solver.write_csv(curve);
    log << "load-displacement curve written to " << curve << std::endl;
  }

  void
  LastStepField::add_rows(const CoupledSolver     &solver,
                          const CoupledRunContext &context,
                          std::ostream &)
  {
    // The 3D reconstruction sums the harmonics' solutions: the converged
    // total field of the last step, u_h = lambda u_F,h + K_h^-1 c_h.
    HarmonicSet &set       = *context.harmonic_set;
    context.reconstruction = FieldReconstruction();
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        set.problem(h).set_solution(solver.solution(h));
        context.reconstruction.add(set.shared_problem(h));
      }
  }

  void
  LastStepField::write_files(const CoupledSolver     &solver,
                             const CoupledRunContext &context,
                             std::ostream            &log)
  {
    const OutputParameters &output = context.parameters.output;
    if (!context.writes_csv || !output.write_vtu)
      return;
    const bool   elastic_stresses = solver.n_soil_points() == 0;
    HarmonicSet &set              = *context.harmonic_set;
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const std::string name = context.result_files.claim(
          ResultFiles::fill(ResultFiles::harmonic_vtu, set.harmonic(h), 0));
        set.problem(h).write_vtu(name, {}, elastic_stresses);
      }
    log << "VTU per harmonic of the last converged step ("
        << (output.write_stresses && elastic_stresses ?
              "displacement and stress amplitudes" :
              "displacement amplitudes")
        << ") written to " << output.directory << "/solution-n*-cycle0.vtu"
        << std::endl;
  }

  void
  RunResultFiles::write_files(const CoupledSolver &,
                              const CoupledRunContext &context,
                              std::ostream            &log)
  {
    if (!context.writes_csv)
      return;
    write_run_result_files(context.parameters.output,
                           context.reconstruction,
                           context.results,
                           context.result_files,
                           log);
  }

  void
  write_run_result_files(const OutputParameters    &output,
                         const FieldReconstruction &reconstruction,
                         const ResultsTable        &results,
                         ResultFiles               &result_files,
                         std::ostream              &log)
  {
    if (!output.lines.empty())
      {
        const std::string name = result_files.claim("lines-3d.csv");
        reconstruction.write_lines_csv(output.lines,
                                       output.theta_degrees,
                                       name);
        log << "3D reconstruction along " << output.lines.size()
            << " line(s) written to " << name << std::endl;
      }
    if (output.write_3d_vtu)
      {
        const std::string name = result_files.claim("solution-3d.vtu");
        reconstruction.write_revolved_vtu(output.theta_divisions, name);
        log << "revolved 3D field written to " << name << std::endl;
      }
    const std::string name = result_files.claim_results_file();
    results.write_csv(name);
    log << "results written to " << name << std::endl;
  }
} // namespace FourierSSI
