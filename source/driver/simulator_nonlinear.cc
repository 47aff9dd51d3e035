// The driver's path for scenes with nonlinear (coulomb) interfaces: the
// harmonics are coupled through theta, so they are solved together by
// CoupledSolver on one HarmonicSet (doc/nonlinear-interfaces.md).
#include <chrono>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/interface_state_surface.h>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/harmonic/distributed_linear_system.h>
#include <fourier_ssi/input/problem_checks.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  void
  Simulator::solve_nonlinear_interfaces(std::ostream &log)
  {
    check_coupled_path_supported(parameters, "a coulomb interface");
    std::unique_ptr<CoupledSolver> solver;
    CoupledCurveRun                run;
    run.goal_prefix = "end_load_";
    run.solve       = [&](std::ostream &out) {
      solver.reset();
      solver            = solve_coupled_curve(out, false);
      const auto &steps = solver->get_steps();
      AssertThrow(!steps.empty(),
                  ExcMessage("Discretization/Target accuracy: no converged "
                                   "step"));
      const NamedLoad load =
        conjugate_load(solver->applied_loads(steps.back().load_factor,
                                             steps.back().held_fraction),
                       parameters.rigid_foundation,
                       parameters.load_path.motion);
      return CoupledGoal{load.name,
                         load.unit,
                         load.value,
                         0.,
                         static_cast<unsigned int>(steps.size())};
    };
    run.release     = [&]() { solver.reset(); };
    run.add_rows    = [&](std::ostream &) { add_interface_rows(*solver); };
    run.write_files = [&](std::ostream &out) {
      write_interface_files(*solver, out);
    };
    run.last_solver = [&]() -> const CoupledSolver & { return *solver; };
    if (parameters.discretization.target_accuracy > 0. ||
        parameters.discretization.refinement_cycles > 1)
      {
        solve_coupled_on_meshes(log, run);
        return;
      }
    solver = solve_coupled_curve(log, true);
    run.add_rows(log);
    run.write_files(log);
  }

  void
  Simulator::add_interface_rows(const CoupledSolver &solver)
  {
    add_load_step_rows(solver);
    keep_last_step(solver);
    add_held_reaction_rows(solver);
  }

  void
  Simulator::write_interface_files(const CoupledSolver &solver,
                                   std::ostream        &log)
  {
    check_interface_state_steps(solver);
    if (!writes_csv())
      return;
    {
      write_load_displacement_csv(solver, log);
      const std::string state = result_files.claim("interface-state.csv");
      solver.write_interface_state_csv(state);
      log << "interface state (point x theta x step) written to " << state
          << std::endl;
      write_last_step_vtu(true, log);
      if (parameters.output.write_3d_vtu)
        {
          const std::string vtu = result_files.claim("interface-state-3d.vtu");
          solver.write_interface_state_vtu(vtu);
          log << "interface state of the last step (3D points) written to "
              << vtu << std::endl;
        }
      write_interface_state_3d(solver, log);
    }
    // Lines 3D, the revolved 3D VTU and the results, as a linear run.
    write_output(log);
  }

  void
  Simulator::check_interface_state_steps(const CoupledSolver &solver) const
  {
    const std::vector<unsigned int> &chosen =
      parameters.output.interface_state_steps;
    const auto n_steps = static_cast<unsigned int>(solver.get_steps().size());
    if (!parameters.output.interface_state_3d || chosen.empty())
      return;
    AssertThrow(chosen.back() <= n_steps,
                ExcMessage("Output/Interface state steps: step " +
                           std::to_string(chosen.back()) +
                           " lies beyond the load path, which has " +
                           std::to_string(n_steps) + " converged steps"));
  }

  void
  Simulator::write_interface_state_3d(const CoupledSolver &solver,
                                      std::ostream        &log)
  {
    if (!parameters.output.interface_state_3d)
      return;
    const auto                start = std::chrono::steady_clock::now();
    std::vector<unsigned int> steps = parameters.output.interface_state_steps;
    if (steps.empty())
      steps = {static_cast<unsigned int>(solver.get_steps().size())};
    std::vector<std::pair<double, std::string>> series;
    log << "interface state in 3D (quads of point x theta sample) of";
    for (const unsigned int step : steps)
      {
        const std::string   name = interface_state_3d_name(step);
        const ContactCounts counts =
          solver.write_interface_state_surface(step, result_files.claim(name));
        series.emplace_back(step, name);
        log << (step == steps.front() ? " step " : ", step ") << step << " ("
            << counts[0] << '/' << counts[1] << '/' << counts[2]
            << " stick/slip/open)";
      }
    write_pvd_series(series, result_files.claim(interface_state_3d_series()));
    log << " written to " << parameters.output.directory
        << "/interface-state-3d-step*.vtu and interface-state-3d.pvd; "
        << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
             .count()
        << " s" << std::endl;
  }

  void
  Simulator::make_distributed_harmonic_set()
  {
    // Every rank owns some harmonics, serial systems (MPI_COMM_SELF), and
    // shares the cores of its node with the other ranks.
    // (A serial run does not start MPI: no communicator to ask.)
    const unsigned int n_ranks =
      Utilities::MPI::job_supports_mpi() ?
        Utilities::MPI::n_mpi_processes(communicator) :
        1;
    const unsigned int threads =
      parameters.discretization.concurrent_harmonics > 0 ?
        parameters.discretization.concurrent_harmonics :
        std::max(1u, MultithreadInfo::n_cores() / n_ranks);
    harmonic_set = std::make_unique<HarmonicSet>(parameters,
                                                 plan.harmonics,
                                                 *triangulation,
                                                 plan.loads,
                                                 MPI_COMM_SELF,
                                                 threads);
    harmonic_set->distribute_over(communicator);
    harmonic_set->setup_and_assemble();
    harmonic_set->factorize();
  }

  void
  Simulator::log_harmonic_distribution(std::ostream &log) const
  {
    const unsigned int n_ranks = harmonic_set->n_owning_ranks();
    if (n_ranks == 1)
      return;
    log << "harmonics distributed over " << n_ranks << " MPI ranks:";
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        log << (r == 0 ? " rank " : "; rank ") << r;
        for (unsigned int h = 0; h < harmonic_set->size(); ++h)
          if (harmonic_set->owner(h) == r)
            log << ' ' << harmonic_set->harmonic(h).name();
      }
    log << std::endl;
  }

  void
  Simulator::write_last_step_vtu(const bool elastic_stresses, std::ostream &log)
  {
    if (!parameters.output.write_vtu)
      return;
    for (unsigned int h = 0; h < harmonic_set->size(); ++h)
      {
        const std::string name = result_files.claim(ResultFiles::fill(
          ResultFiles::harmonic_vtu, harmonic_set->harmonic(h), 0));
        harmonic_set->problem(h).write_vtu(name, {}, elastic_stresses);
      }
    log << "VTU per harmonic of the last converged step ("
        << (parameters.output.write_stresses && elastic_stresses ?
              "displacement and stress amplitudes" :
              "displacement amplitudes")
        << ") written to " << parameters.output.directory
        << "/solution-n*-cycle0.vtu" << std::endl;
  }
} // namespace FourierSSI
