#include <atomic>
#include <cmath>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/tria.h>
#include <dlfcn.h>
#include <exception>
#include <filesystem>
#include <fourier_ssi/adaptivity.h>
#include <fourier_ssi/command_line.h>
#include <fourier_ssi/goal_estimator.h>
#include <fourier_ssi/harmonic_problem.h>
#include <fourier_ssi/input_checks.h>
#include <fourier_ssi/scene_plan.h>
#include <fourier_ssi/simulator.h>
#include <iomanip>
#include <thread>

namespace FourierSSI
{
  namespace
  {
    /** What solving one harmonic produced, merged in order afterwards. */
    struct HarmonicOutcome
    {
      std::shared_ptr<HarmonicProblem> problem;
      std::vector<Vector<double>>      unit_solutions;
      struct Row
      {
        std::string quantity;
        double      value;
        std::string unit;
      };
      std::vector<Row> rows;
      /** Phase times: setup, cells, interfaces, solve, estimate [s]. */
      std::array<double, 5> times = {{0., 0., 0., 0., 0.}};
      /** Goal strategy: the DWR indicators and estimated goal error. */
      Vector<float>            goal_indicators;
      double                   goal_error = -1.;
      std::string              goal_values;
      std::string              log;
      std::vector<std::string> files;
      std::exception_ptr       error;
    };

    /**
     * Solve one harmonic and post-process it. Runs in a worker thread: it
     * reads the shared mesh and the previous cycles' results only.
     */
    void
    solve_harmonic(const AllParameters     &parameters,
                   const Harmonic          &harmonic,
                   const Triangulation<2>  &triangulation,
                   const LoadDecomposition &loads,
                   const MPI_Comm           communicator,
                   const unsigned int       cycle,
                   const ResultsTable      &previous,
                   const bool               write_files,
                   const GoalEstimator     *goal_estimator,
                   HarmonicOutcome         &outcome)
    {
      const std::string &directory = parameters.output.directory;
      {
        auto problem_pointer = std::make_shared<HarmonicProblem>(
          parameters, harmonic, triangulation, &loads, communicator);
        outcome.problem          = problem_pointer;
        HarmonicProblem &problem = *problem_pointer;
        Timer            timer;
        problem.setup_system();
        const double t_setup = timer.wall_time();
        timer.restart();
        problem.assemble_system();
        const double t_interface = problem.time_interface_assembly;
        const double t_assembly  = timer.wall_time() - t_interface;
        timer.restart();
        // A stiffness scene solves its load and the unit-H and unit-M loads
        // with one factorization.
        const bool coefficients =
          parameters.rigid_foundation.stiffness_coefficients &&
          harmonic.n == 1 && harmonic.family == Family::symmetric &&
          problem.get_foundation();
        FoundationCoefficients c;
        const SolverReport     report =
          coefficients ?
                problem.solve_with_unit_loads(c, &outcome.unit_solutions) :
                problem.solve();
        const double t_solve    = timer.wall_time();
        double       t_estimate = 0.;

        const auto add =
          [&](const std::string &q, const double v, const std::string &unit) {
            outcome.rows.push_back({q, v, unit});
          };
        const double n_dofs = problem.get_dof_handler().n_dofs();
        add("n_cells", triangulation.n_active_cells(), "-");
        add("n_dofs", n_dofs, "-");
        add("n_axis_nodes", problem.n_axis_nodes, "-");
        add("solver_iterations", report.iterations, "-");
        add("solver_relative_residual", report.relative_residual, "-");
        add("strain_energy",
            problem.strain_energy(problem.get_solution()),
            "kJ");

        std::ostringstream line;
        line << "cycle " << cycle << ", " << harmonic.name() << ": " << n_dofs
             << " dofs, " << report.method;
        if (report.iterations > 0)
          line << " (" << report.iterations << " it.)";
        line << ", residual " << std::setprecision(2)
             << report.relative_residual;

        if (!parameters.boundary_conditions.dirichlet.empty())
          {
            const Vector<double> reactions = problem.nodal_reactions();
            for (const auto &[id, e] : parameters.boundary_conditions.dirichlet)
              {
                const BoundaryResultant R =
                  problem.boundary_resultant(id, reactions);
                const std::string b = "_boundary_" + std::to_string(id);
                add("reaction_force" + b, R.force, "kN");
                add("reaction_moment" + b, R.moment, "kN.m");
                add("reaction_work" + b, R.work, "kJ");
                if (R.force != 0. || R.moment != 0.)
                  line << "\n    reactions on boundary " << id << ": force "
                       << std::setprecision(6) << R.force << " kN, moment "
                       << R.moment << " kN.m";
              }
          }
        if (const RigidFoundation *foundation = problem.get_foundation())
          {
            const RigidMotion m = foundation->motion(problem.get_solution());
            add("foundation_horizontal_displacement",
                m.horizontal_displacement,
                "m");
            add("foundation_rotation", m.rotation, "rad");
            add("foundation_vertical_displacement",
                m.vertical_displacement,
                "m");
            add("foundation_twist", m.twist, "rad");
            if (coefficients)
              {
                if (goal_estimator)
                  {
                    timer.restart();
                    const GoalEstimate g =
                      goal_estimator->estimate(harmonic,
                                               triangulation,
                                               problem,
                                               outcome.unit_solutions,
                                               c);
                    t_estimate += timer.wall_time();
                    outcome.goal_indicators = g.indicators;
                    outcome.goal_error      = g.goal_error;
                    add("goal_error_K_H", g.relative_error[0], "-");
                    add("goal_error_K_M", g.relative_error[1], "-");
                    add("goal_error_K_MH", g.relative_error[2], "-");
                    add("goal_error", g.goal_error, "-");
                    add("goal_cell_share", g.cell_share, "-");
                    add("enriched_n_dofs", g.enriched_dofs, "-");
                    add("K_H_enriched", g.enriched.K_H, "-");
                    add("K_M_enriched", g.enriched.K_M, "-");
                    add("K_MH_enriched", g.enriched.K_MH, "-");
                    line << "\n    goal (" << parameters.adaptivity.goal
                         << "): estimated relative error K_H "
                         << std::setprecision(2) << g.relative_error[0]
                         << ", K_M " << g.relative_error[1] << ", K_MH "
                         << g.relative_error[2] << "; FE_Q(4) on this mesh ("
                         << g.enriched_dofs << " dofs): K_H "
                         << std::setprecision(7) << g.enriched.K_H << ", K_M "
                         << g.enriched.K_M << ", K_MH " << g.enriched.K_MH;
                    std::ostringstream v;
                    v << ", K_H " << std::setprecision(7) << c.K_H << ", K_M "
                      << c.K_M << ", K_MH " << c.K_MH;
                    outcome.goal_values = v.str();
                  }
                add("I_H", c.I_H, "-");
                add("I_M", c.I_M, "-");
                add("I_MH_from_H", c.I_MH_from_H, "-");
                add("I_MH_from_M", c.I_MH_from_M, "-");
                add("K_H", c.K_H, "-");
                add("K_M", c.K_M, "-");
                add("K_MH", c.K_MH, "-");
                line << "\n    stiffness: K_H " << std::setprecision(6) << c.K_H
                     << ", K_M " << c.K_M << ", K_MH " << c.K_MH
                     << " (I_MH from H " << c.I_MH_from_H << ", from M "
                     << c.I_MH_from_M << ")";
              }
            line << "\n    foundation: U_h " << std::setprecision(6)
                 << m.horizontal_displacement << " m, Theta " << m.rotation
                 << " rad, W " << m.vertical_displacement << " m, Phi "
                 << m.twist << " rad";
          }
        if (parameters.exact_solution.enabled)
          {
            const ErrorNorms e = problem.compute_errors();
            add("error_l2", e.l2, "m.m^1.5");
            add("error_h1_seminorm", e.h1_seminorm, "m.m^0.5");
            add("relative_error_l2", e.l2 / e.l2_exact, "-");
            add("relative_error_h1", e.h1_seminorm / e.h1_exact, "-");
            line << ", L2 error " << std::setprecision(4) << e.l2
                 << ", H1 error " << e.h1_seminorm;
            if (cycle > 0)
              {
                const double rate_l2 = std::log2(
                  previous.get("error_l2", harmonic, cycle - 1) / e.l2);
                const double rate_h1 = std::log2(
                  previous.get("error_h1_seminorm", harmonic, cycle - 1) /
                  e.h1_seminorm);
                add("rate_l2", rate_l2, "-");
                add("rate_h1", rate_h1, "-");
                line << " (rates " << std::setprecision(3) << rate_l2 << ", "
                     << rate_h1 << ")";
              }
          }
        outcome.log   = line.str();
        outcome.times = {
          {t_setup, t_assembly, t_interface, t_solve, t_estimate}};

        if (write_files && parameters.output.write_vtu)
          {
            const std::string name = directory + "/solution-n" +
                                     std::to_string(harmonic.n) + "-" +
                                     to_string(harmonic.family) + "-cycle" +
                                     std::to_string(cycle) + ".vtu";
            for (const std::string &file : problem.write_vtu(name))
              outcome.files.push_back(file);
          }
        // Rank 0 writes the CSV files (each rank writes its VTU piece).
        const bool write_csv =
          write_files && (!Utilities::MPI::job_supports_mpi() ||
                          Utilities::MPI::this_mpi_process(communicator) == 0);
        if (write_csv && problem.get_interfaces() &&
            parameters.output.write_interface_tractions)
          for (const types::boundary_id id :
               problem.get_interfaces()->boundary_ids())
            {
              const std::string name =
                directory + "/interface-" + std::to_string(id) + "-n" +
                std::to_string(harmonic.n) + "-" + to_string(harmonic.family) +
                "-cycle" + std::to_string(cycle) + ".csv";
              outcome.files.push_back(name);
              problem.get_interfaces()->write_csv(id,
                                                  problem.get_solution(),
                                                  name);
            }
      }

      // Keep the solution for the 3D reconstruction, not the matrix.
      outcome.problem->free_system();
    }

    /**
     * While harmonics run concurrently, each one's BLAS calls (inside the
     * direct solver) must stay on its own thread: OpenBLAS's thread pool
     * serializes concurrent callers (measured on prm/wind-pressure.prm, 14
     * harmonics on 2 cores: 0.61 s with it vs 0.30 s without, against
     * 0.52 s on one thread). Found at run time, so a different BLAS simply
     * leaves this out.
     */
    class SingleThreadedBlas
    {
    public:
      SingleThreadedBlas()
      {
        set = reinterpret_cast<void (*)(int)>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
        const auto get = reinterpret_cast<int (*)()>(
          dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
        if (set && get)
          {
            previous = get();
            set(1);
          }
        else
          set = nullptr;
      }

      ~SingleThreadedBlas()
      {
        if (set)
          set(previous);
      }

    private:
      void (*set)(int) = nullptr;
      int previous     = 1;
    };

    /**
     * Run the harmonics on up to `n_threads` threads: they are independent
     * systems on the same (read-only) mesh.
     */
    std::vector<HarmonicOutcome>
    solve_harmonics(const AllParameters         &parameters,
                    const std::vector<Harmonic> &harmonics,
                    const Triangulation<2>      &triangulation,
                    const LoadDecomposition     &loads,
                    const MPI_Comm               communicator,
                    const unsigned int           cycle,
                    const ResultsTable          &previous,
                    const bool                   write_files,
                    const GoalEstimator         *goal_estimator,
                    const unsigned int           n_threads)
    {
      std::vector<HarmonicOutcome> outcomes(harmonics.size());
      std::atomic<unsigned int>    next(0);
      const auto                   work = [&]() {
        for (unsigned int i = next++; i < harmonics.size(); i = next++)
          try
            {
              solve_harmonic(parameters,
                             harmonics[i],
                             triangulation,
                             loads,
                             communicator,
                             cycle,
                             previous,
                             write_files,
                             goal_estimator,
                             outcomes[i]);
            }
          catch (...)
            {
              outcomes[i].error = std::current_exception();
            }
      };
      if (n_threads <= 1)
        work();
      else
        {
          const SingleThreadedBlas single_threaded_blas;
          std::vector<std::thread> threads;
          for (unsigned int t = 0; t < n_threads; ++t)
            threads.emplace_back(work);
          for (auto &thread : threads)
            thread.join();
        }
      return outcomes;
    }
  } // namespace

  Simulator::Simulator(const AllParameters &parameters,
                       const MPI_Comm       communicator)
    : parameters(parameters)
    , communicator(communicator)
  {}

  ResultsTable
  Simulator::run(std::ostream &log, const bool write_files)
  {
    ResultsTable             results;
    std::vector<std::string> written;
    const std::string       &directory = parameters.output.directory;
    // Rank 0 writes the CSV files (each rank writes its VTU piece).
    const bool write_csv =
      write_files && (!Utilities::MPI::job_supports_mpi() ||
                      Utilities::MPI::this_mpi_process(communicator) == 0);
    try
      {
        if (write_files)
          std::filesystem::create_directories(directory);
        reconstruction = FieldReconstruction();
        triangulation.clear();
        std::unique_ptr<RefinementIndicator> indicator;
        const std::string &strategy = parameters.adaptivity.strategy;
        std::unique_ptr<GoalEstimator> goal_estimator;
        if (strategy == "goal")
          goal_estimator = std::make_unique<GoalEstimator>(parameters);
        std::set<types::boundary_id> interface_ids;
        for (const auto &[id, law] : parameters.interfaces.laws)
          interface_ids.insert(id);
        parameters.mesh.build(triangulation);
        refine_a_priori(triangulation, parameters.adaptivity, interface_ids);
        for (const auto &cell : triangulation.active_cell_iterators())
          parameters.materials.get(cell->material_id()); // throws if missing
        const ScenePlan plan = plan_scene(parameters, triangulation);
        for (const std::string &line : plan.log_lines)
          log << line << std::endl;
        for (const std::string &line :
             check_scene_before_solve(parameters, triangulation, plan))
          log << line << std::endl;

        for (unsigned int cycle = 0;
             cycle < parameters.discretization.refinement_cycles;
             ++cycle)
          {
            if (cycle > 0)
              {
                // Release the previous cycle's fields before the mesh
                // changes under their DoF handlers.
                reconstruction = FieldReconstruction();
                if (strategy == "kelly" || strategy == "goal")
                  indicator->refine(triangulation,
                                    parameters.adaptivity.refine_fraction,
                                    interface_ids);
                else
                  triangulation.refine_global(1);
              }
            indicator = std::make_unique<RefinementIndicator>(triangulation);
            // A distributed system's collective MPI calls must not
            // interleave on one communicator: one harmonic at a time then.
            const bool distributed =
              Utilities::MPI::job_supports_mpi() &&
              Utilities::MPI::n_mpi_processes(communicator) > 1;
            const unsigned int n_threads = std::min<unsigned int>(
              plan.harmonics.size(),
              distributed ? 1 :
              parameters.discretization.concurrent_harmonics > 0 ?
                            parameters.discretization.concurrent_harmonics :
                            MultithreadInfo::n_cores());
            Timer                        cycle_timer;
            std::vector<HarmonicOutcome> outcomes =
              solve_harmonics(parameters,
                              plan.harmonics,
                              triangulation,
                              plan.loads,
                              communicator,
                              cycle,
                              results,
                              write_files,
                              goal_estimator.get(),
                              n_threads);
            const double cycle_time = cycle_timer.wall_time();
            for (const HarmonicOutcome &outcome : outcomes)
              written.insert(written.end(),
                             outcome.files.begin(),
                             outcome.files.end());
            // Per-cycle record (summed over the harmonics): DoFs, phase
            // times, and the estimated goal error of the goal strategy.
            double                cycle_dofs       = 0.;
            std::array<double, 5> cycle_times      = {{0., 0., 0., 0., 0.}};
            double                cycle_goal_error = -1.;
            std::string           cycle_goal_values;
            for (unsigned int i = 0; i < outcomes.size(); ++i)
              {
                HarmonicOutcome &outcome  = outcomes[i];
                const Harmonic  &harmonic = plan.harmonics[i];
                if (outcome.error)
                  try
                    {
                      std::rethrow_exception(outcome.error);
                    }
                  catch (const std::exception &e)
                    {
                      // Say which harmonic and cycle failed.
                      AssertThrow(false,
                                  ExcMessage("cycle " + std::to_string(cycle) +
                                             ", " + harmonic.name() + ": " +
                                             one_line_message(e)));
                    }
                for (const auto &row : outcome.rows)
                  results.add(
                    row.quantity, harmonic, cycle, row.value, row.unit);
                log << outcome.log << std::endl;
                Timer timer;
                if (strategy == "kelly")
                  {
                    // The scene's own load may be zero: the unit-H and
                    // unit-M fields also steer the mesh.
                    indicator->add_kelly(outcome.problem->get_dof_handler(),
                                         outcome.problem->get_solution());
                    for (const auto &field : outcome.unit_solutions)
                      indicator->add_kelly(outcome.problem->get_dof_handler(),
                                           field);
                  }
                if (outcome.goal_indicators.size() > 0)
                  {
                    indicator->add(outcome.goal_indicators);
                    cycle_goal_error =
                      std::max(cycle_goal_error, outcome.goal_error);
                    cycle_goal_values = outcome.goal_values;
                  }
                outcome.times[4] += timer.wall_time();
                const std::array<std::string, 5> names = {
                  {"time_setup",
                   "time_assembly",
                   "time_interface_assembly",
                   "time_solve",
                   "time_estimate"}};
                for (unsigned int k = 0; k < 5; ++k)
                  {
                    results.add(
                      names[k], harmonic, cycle, outcome.times[k], "s");
                    cycle_times[k] += outcome.times[k];
                  }
                cycle_dofs += outcome.problem->get_dof_handler().n_dofs();
                reconstruction.add(outcome.problem);
              }
            std::ostringstream summary;
            summary << "cycle " << cycle << " summary: " << cycle_dofs
                    << " dofs, " << plan.harmonics.size() << " harmonic(s) on "
                    << n_threads << " thread(s), wall " << std::setprecision(3)
                    << cycle_time << " s";
            if (cycle_goal_error >= 0.)
              summary << ", estimated goal error " << std::setprecision(2)
                      << cycle_goal_error << cycle_goal_values;
            summary << "; summed over harmonics [s]: setup "
                    << std::setprecision(3) << cycle_times[0] << ", assembly "
                    << cycle_times[1] << ", interface assembly "
                    << cycle_times[2] << ", solve " << cycle_times[3]
                    << ", estimate " << cycle_times[4];
            log << summary.str() << std::endl;
            // Stop once the estimated goal error meets the tolerance.
            if (cycle_goal_error >= 0. &&
                cycle_goal_error < parameters.adaptivity.goal_tolerance)
              {
                log << "goal tolerance " << parameters.adaptivity.goal_tolerance
                    << " reached: stop after cycle " << cycle << std::endl;
                break;
              }
          }
        if (write_csv && !parameters.output.lines.empty())
          {
            const std::string name = directory + "/lines-3d.csv";
            written.push_back(name);
            reconstruction.write_lines_csv(parameters.output.lines,
                                           parameters.output.theta_degrees,
                                           name);
            log << "3D reconstruction along " << parameters.output.lines.size()
                << " line(s) written to " << name << std::endl;
          }
        if (write_csv && parameters.output.write_3d_vtu)
          {
            const std::string name = directory + "/solution-3d.vtu";
            written.push_back(name);
            reconstruction.write_revolved_vtu(parameters.output.theta_divisions,
                                              name);
            log << "revolved 3D field written to " << name << std::endl;
          }
        if (write_csv)
          {
            const std::string name =
              directory + "/" + parameters.output.results_file;
            written.push_back(name);
            results.write_csv(name);
            log << "results written to " << name << std::endl;
          }
      }
    catch (...)
      {
        for (const std::string &file : written)
          std::filesystem::remove(file);
        throw;
      }
    return results;
  }
} // namespace FourierSSI
