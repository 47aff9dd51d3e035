// What every coupled (nonlinear) scene shares in the driver: the load path
// of CoupledSolver on the scene's HarmonicSet, and its per-step rows, held
// reactions, last step and load-displacement.csv. The scene kinds
// (nonlinear interfaces, plastic soil) add theirs in simulator_nonlinear.cc
// and simulator_soil.cc.
#include <deal.II/base/timer.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/cyclic_output.h>
#include <fourier_ssi/driver/simulator.h>

namespace FourierSSI
{
  namespace
  {
    /**
     * Runs the solver's load steps; if one fails, the converged steps are
     * written to `incomplete_curve` (unless empty; the name marks them as
     * such) before the error goes on.
     */
    void
    run_keeping_converged_steps(CoupledSolver     &solver,
                                std::ostream      &log,
                                const std::string &incomplete_curve)
    {
      try
        {
          solver.run(log);
        }
      catch (const std::exception &)
        {
          if (!incomplete_curve.empty() && !solver.get_steps().empty())
            solver.write_csv(incomplete_curve);
          throw;
        }
    }
  } // namespace

  std::unique_ptr<CoupledSolver>
  Simulator::solve_coupled_curve(
    std::ostream                               &log,
    const bool                                  keep_incomplete,
    const std::function<void(CoupledSolver &)> &before_run)
  {
    Timer timer;
    make_distributed_harmonic_set();
    log << "assembled and factorized " << harmonic_set->size()
        << " harmonics in " << timer.wall_time() << " s" << std::endl;
    log_harmonic_distribution(log);
    auto solver = std::make_unique<CoupledSolver>(*harmonic_set, parameters);
    if (before_run)
      before_run(*solver);
    run_keeping_converged_steps(*solver,
                                log,
                                keep_incomplete && writes_csv() ?
                                  result_files.path_of(
                                    "load-displacement-incomplete.csv") :
                                  "");
    log << "coupled solve: " << solver->get_steps().size() << " steps in "
        << timer.wall_time() << " s" << std::endl;
    return solver;
  }

  void
  Simulator::write_load_displacement_csv(const CoupledSolver &solver,
                                         std::ostream        &log)
  {
    const std::string curve = result_files.claim("load-displacement.csv");
    solver.write_csv(curve);
    log << "load-displacement curve written to " << curve << std::endl;
    write_cyclic_output(solver, parameters, result_files, results, log);
  }

  void
  Simulator::add_load_step_rows(const CoupledSolver &solver)
  {
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
  Simulator::add_held_reaction_rows(const CoupledSolver &solver)
  {
    const Harmonic any{0, Family::symmetric};
    for (const auto &[motion, load] : solver.get_steps().back().held_reactions)
      results.add(parameters.rigid_foundation.reaction_row(motion),
                  any,
                  solver.get_steps().size(),
                  load,
                  load_unit_of(motion));
  }

  void
  Simulator::keep_last_step(const CoupledSolver &solver)
  {
    // The 3D reconstruction sums the harmonics' solutions: the converged
    // total field of the last step, u_h = lambda u_F,h + K_h^-1 c_h.
    reconstruction = FieldReconstruction();
    for (unsigned int h = 0; h < harmonic_set->size(); ++h)
      {
        harmonic_set->problem(h).set_solution(solver.solution(h));
        reconstruction.add(harmonic_set->shared_problem(h));
      }
  }
} // namespace FourierSSI
