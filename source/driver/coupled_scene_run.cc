// What every coupled scene run shares: the load path of CoupledSolver on the
// scene's HarmonicSet, with its postprocessors asked in order.
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>
#include <filesystem>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/coupled_scene_run.h>

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

  CoupledSceneRun::CoupledSceneRun(const CoupledRunContext &context)
    : context(context)
    , solver_parameters(context.parameters)
  {}

  CoupledSceneRun::~CoupledSceneRun() = default;

  void
  CoupledSceneRun::run_on_one_mesh(std::ostream &log)
  {
    solve_path(log, true);
    add_rows(log);
    write_files(log);
  }

  CoupledGoal
  CoupledSceneRun::solve(std::ostream &log)
  {
    solve_path(log, false);
    return goal_of(*solver);
  }

  void
  CoupledSceneRun::release()
  {
    postprocessors.release();
    solver.reset();
  }

  void
  CoupledSceneRun::add_rows(std::ostream &log)
  {
    postprocessors.add_rows(*solver, context, log);
  }

  void
  CoupledSceneRun::write_files(std::ostream &log)
  {
    postprocessors.write_files(*solver, context, log);
  }

  void
  CoupledSceneRun::set_maximum_harmonic(const unsigned int maximum_harmonic)
  {
    release();
    solver_parameters.load_path.maximum_harmonic = maximum_harmonic;
  }

  const AllParameters &
  CoupledSceneRun::get_solver_parameters() const
  {
    return solver_parameters;
  }

  const CoupledSolver &
  CoupledSceneRun::last_solver() const
  {
    return *solver;
  }

  void
  CoupledSceneRun::solve_path(std::ostream &log, const bool on_one_mesh)
  {
    // The solver goes before the set it works on is replaced.
    release();
    Timer timer;
    make_harmonic_set();
    log << "assembled and factorized " << context.harmonic_set->size()
        << " harmonics in " << timer.wall_time() << " s" << std::endl;
    log_harmonic_distribution(log);
    solver =
      std::make_unique<CoupledSolver>(*context.harmonic_set, solver_parameters);
    if (on_one_mesh)
      postprocessors.observe(*solver, context);
    const std::string incomplete_curve =
      on_one_mesh && context.writes_csv ?
        context.result_files.path_of("load-displacement-incomplete.csv") :
        "";
    run_keeping_converged_steps(*solver, log, incomplete_curve);
    // The path finished: the curve of its steps so far (LoadDisplacementCurve
    // keeps it while the path runs) is no record of anything now, also if
    // the output is refused later.
    if (!incomplete_curve.empty())
      std::filesystem::remove(incomplete_curve);
    log << "coupled solve: " << solver->get_steps().size() << " steps in "
        << timer.wall_time() << " s" << std::endl;
  }

  void
  CoupledSceneRun::make_harmonic_set()
  {
    // Every rank owns some harmonics, serial systems (MPI_COMM_SELF), and
    // shares the cores of its node with the other ranks.
    // (A serial run does not start MPI: no communicator to ask.)
    const unsigned int n_ranks =
      Utilities::MPI::job_supports_mpi() ?
        Utilities::MPI::n_mpi_processes(context.communicator) :
        1;
    const AllParameters &parameters = context.parameters;
    const unsigned int   threads =
      parameters.discretization.concurrent_harmonics > 0 ?
          parameters.discretization.concurrent_harmonics :
          std::max(1u, MultithreadInfo::n_cores() / n_ranks);
    context.harmonic_set = std::make_unique<HarmonicSet>(parameters,
                                                         context.plan.harmonics,
                                                         context.triangulation,
                                                         context.plan.loads,
                                                         MPI_COMM_SELF,
                                                         threads);
    context.harmonic_set->distribute_over(context.communicator);
    context.harmonic_set->setup_and_assemble();
    context.harmonic_set->factorize();
  }

  void
  CoupledSceneRun::log_harmonic_distribution(std::ostream &log) const
  {
    const HarmonicSet &set     = *context.harmonic_set;
    const unsigned int n_ranks = set.n_owning_ranks();
    if (context.parameters.distributes_coupled_tangent())
      log << "coupled Newton tangent: one matrix distributed over " << n_ranks
          << " MPI rank(s), each the block rows of its harmonics, factorized "
             "by MUMPS (Linear solver/Distributed = always)"
          << std::endl;
    if (n_ranks == 1)
      return;
    log << "harmonics distributed over " << n_ranks << " MPI ranks:";
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        log << (r == 0 ? " rank " : "; rank ") << r;
        for (unsigned int h = 0; h < set.size(); ++h)
          if (set.owner(h) == r)
            log << ' ' << set.harmonic(h).name();
      }
    log << std::endl;
  }
} // namespace FourierSSI
