#include <deal.II/base/timer.h>
#include <filesystem>
#include <fourier_ssi/coupled/linearisation_choice.h>
#include <fourier_ssi/driver/coupled_mesh_sequence.h>
#include <fourier_ssi/driver/coupled_tangent_run.h>
#include <fourier_ssi/driver/input_checks.h>
#include <fourier_ssi/driver/interface_load_path_run.h>
#include <fourier_ssi/driver/load_path_output.h>
#include <fourier_ssi/driver/memory_estimate.h>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/mesh/discretization_design.h>
#include <iomanip>
#include <regex>

namespace FourierSSI
{
  Simulator::Simulator(const AllParameters &parameters,
                       const MPI_Comm       communicator)
    : parameters(parameters)
    , communicator(communicator)
  {}

  ResultsTable
  Simulator::run(std::ostream &log, const bool write_files_)
  {
    start_run(write_files_);
    const bool had_directory = output_directory_exists();
    try
      {
        // An earlier run's results go first, also if this input is
        // refused.
        remove_stale_results();
        prepare_output_directory();
        make_mesh();
        make_plan(log);
        check_run_fits_in_memory(log);
        switch (plan.run_mode)
          {
            case RunMode::plastic_soil:
            case RunMode::interface_swipe:
            case RunMode::interface_load_path:
              solve_coupled(log);
              break;
            case RunMode::linear_target:
              solve_to_target(log);
              report_foundation_stiffness(log);
              write_output(log);
              break;
            case RunMode::linear_cycles:
              solve_refinement_cycles(log);
              report_foundation_stiffness(log);
              write_output(log);
              break;
          }
      }
    catch (...)
      {
        discard_results(had_directory);
        throw;
      }
    return results;
  }

  void
  Simulator::start_run(const bool write_files_)
  {
    write_files  = write_files_;
    results      = ResultsTable();
    result_files = write_files ? ResultFiles(parameters.output) : ResultFiles();
    goal_histories.clear();
    estimate_wall_time = 0.;
    target_not_reached.clear();
  }

  bool
  Simulator::output_directory_exists() const
  {
    return decided_on_rank_0<bool>([&]() {
      return !write_files ||
             std::filesystem::exists(parameters.output.directory);
    });
  }

  void
  Simulator::prepare_output_directory() const
  {
    const std::string path_error = decided_on_rank_0<std::string>(
      [&]() { return output_path_error(parameters.output); });
    AssertThrow(path_error.empty(), ExcMessage(path_error));
    if (!write_files)
      return;
    // What the checks cannot foresee (a folder the file system refuses
    // even to root, such as one under /proc) gets the entry's one line,
    // not the file system's exception text.
    std::error_code error;
    std::filesystem::create_directories(parameters.output.directory, error);
    AssertThrow(!error,
                ExcMessage("Output/Directory: '" + parameters.output.directory +
                           "' cannot be created: " + error.message()));
  }

  void
  Simulator::check_run_fits_in_memory(std::ostream &log) const
  {
    // A run that cannot fit stops here, not after minutes of swapping.
    const MemoryEstimate estimate =
      estimate_run_memory(parameters, *triangulation, plan);
    const double available =
      decided_on_rank_0<double>([]() { return available_memory(); });
    check_memory_fits(estimate, available);
    const std::string line = describe_large_estimate(estimate, available);
    if (!line.empty())
      log << line << std::endl;
  }

  void
  Simulator::solve_refinement_cycles(std::ostream &log)
  {
    const unsigned int n_cycles = parameters.discretization.refinement_cycles;
    if (n_cycles == 1)
      solve_coarser_member(log);
    unsigned int cycle = 0;
    for (; cycle < n_cycles; ++cycle)
      {
        if (cycle > 0)
          refine_mesh();
        solve_harmonics(cycle);
        collect_cycle(cycle, log);
        record_goal_values();
        if (goal_tolerance_reached(cycle, log))
          break;
      }
    report_error_estimates(std::min(cycle, n_cycles - 1), log);
  }

  void
  Simulator::discard_results(const bool had_directory)
  {
    // A failed run leaves no result file and no output folder it created
    // itself (the README's promise: no output at all for bad input).
    result_files.remove_claimed();
    const std::filesystem::path directory = parameters.output.directory;
    std::error_code             ignored;
    if (!had_directory && std::filesystem::is_empty(directory, ignored))
      std::filesystem::remove(directory, ignored);
  }


  bool
  Simulator::writes_csv() const
  {
    // Rank 0 writes the CSV files (each rank writes its VTU piece).
    return write_files && (!Utilities::MPI::job_supports_mpi() ||
                           Utilities::MPI::this_mpi_process(communicator) == 0);
  }

  template <typename T>
  T
  Simulator::decided_on_rank_0(const std::function<T()> &decide) const
  {
    if (!Utilities::MPI::job_supports_mpi() ||
        Utilities::MPI::n_mpi_processes(communicator) == 1)
      return decide();
    const T value =
      Utilities::MPI::this_mpi_process(communicator) == 0 ? decide() : T();
    return Utilities::MPI::broadcast(communicator, value, 0);
  }

  void
  Simulator::remove_stale_results() const
  {
    if (!write_files)
      return;
    // Rank 0 clears the folder (every rank's VTU pieces), the others wait
    // before they write theirs.
    if (writes_csv())
      result_files.remove_stale();
    if (uses_distributed_solve(parameters.solver, communicator))
      MPI_Barrier(communicator);
  }

  void
  Simulator::make_mesh()
  {
    reconstruction = FieldReconstruction();
    harmonic_set.reset();
    triangulation->clear();
    interface_ids.clear();
    for (const auto &[id, law] : parameters.interfaces.laws)
      interface_ids.insert(id);
    // A coupled scene with a target refines its own mesh
    // (CoupledMeshSequence::solve_to_target); the FE_Q(4) design is for the
    // linear scenes.
    if (run_mode_of(parameters) == RunMode::linear_target)
      DiscretizationDesign::build_member(parameters,
                                         0,
                                         interface_ids,
                                         *triangulation);
    else
      {
        build_mesh(parameters.mesh, *triangulation);
        refine_a_priori(*triangulation, parameters.adaptivity, interface_ids);
      }
    for (const auto &cell : triangulation->active_cell_iterators())
      parameters.materials.get(cell->material_id()); // throws if missing
  }

  void
  Simulator::make_plan(std::ostream &log)
  {
    choose_interface_linearisation(parameters, *triangulation);
    plan = plan_scene(parameters, *triangulation);
    for (const std::string &line : plan.log_lines)
      log << line << std::endl;
    if (plan.run_mode == RunMode::interface_load_path)
      log << describe_interface_linearisation(parameters) << std::endl;
    // Checks that can be made before anything is assembled (throw on bad
    // input, return warnings).
    for (const std::string &line :
         check_scene_before_solve(parameters, *triangulation, plan))
      log << line << std::endl;
    goal_estimator.reset();
    // A coupled path refuses the goal strategy (check_coupled_path_supported)
    // before it would need the linear goals' stiffness coefficients.
    if (parameters.adaptivity.strategy == RefinementStrategy::goal &&
        !parameters.coupled())
      goal_estimator =
        std::make_unique<GoalEstimator>(parameters, plan.harmonics);
  }

  void
  Simulator::refine_mesh()
  {
    // Release the previous cycle's fields before the mesh changes under
    // their DoF handlers.
    reconstruction = FieldReconstruction();
    harmonic_set.reset();
    outcomes.clear();
    if (parameters.adaptivity.strategy == RefinementStrategy::global)
      triangulation->refine_global(1);
    else
      indicator->refine(*triangulation,
                        parameters.adaptivity.refine_fraction,
                        interface_ids);
  }

  void
  Simulator::solve_harmonics(const unsigned int cycle)
  {
    Timer timer;
    try
      {
        solve_harmonics_on(
          *triangulation, cycle, cores, harmonic_set, outcomes);
      }
    catch (const std::exception &e)
      {
        fail_cycle(cycle, outcomes, e);
      }
    cycle_wall_time = timer.wall_time();
  }

  void
  Simulator::solve_harmonics_on(const Triangulation<2>       &mesh,
                                const unsigned int            cycle,
                                const unsigned int            n_cores,
                                std::unique_ptr<HarmonicSet> &set,
                                std::vector<HarmonicOutcome> &solved) const
  {
    set = std::make_unique<HarmonicSet>(
      parameters,
      plan.harmonics,
      mesh,
      plan.loads,
      communicator,
      parameters.discretization.concurrent_harmonics,
      n_cores);
    solved = std::vector<HarmonicOutcome>(set->size());
    set->for_each([&](const unsigned int i) {
      solve_harmonic(*set, mesh, i, cycle, solved[i]);
    });
  }

  void
  Simulator::fail_cycle(const unsigned int                  cycle,
                        const std::vector<HarmonicOutcome> &solved,
                        const std::exception               &e)
  {
    // The harmonics that succeeded wrote files: removed by run().
    for (const HarmonicOutcome &outcome : solved)
      result_files.claim_paths(outcome.files);
    AssertThrow(false,
                ExcMessage("cycle " + std::to_string(cycle) + ", " +
                           one_line_message(e)));
  }

  void
  Simulator::solve_harmonic(HarmonicSet            &set,
                            const Triangulation<2> &mesh,
                            const unsigned int      i,
                            const unsigned int      cycle,
                            HarmonicOutcome        &outcome) const
  {
    HarmonicProblem   &problem = set.problem(i);
    std::ostringstream unused;
    TimerOutput timer(unused, TimerOutput::never, TimerOutput::wall_times);
    {
      TimerOutput::Scope scope(timer, "setup");
      problem.setup_system();
    }
    {
      TimerOutput::Scope scope(timer, "assembly");
      problem.assemble_system();
    }
    {
      TimerOutput::Scope scope(timer, "solve");
      outcome.solution = solve_loads(problem);
    }
    {
      TimerOutput::Scope scope(timer, "postprocess");
      HarmonicReport    &report = outcome.report;
      Postprocessors::discretization(outcome.solution, cycle, report);
      Postprocessors::reactions(parameters, outcome.solution, report);
      Postprocessors::foundation(parameters, outcome.solution, report);
      if (parameters.exact_solution.enabled)
        Postprocessors::error_norms(outcome.solution, cycle, results, report);
    }
    if (goal_estimator && outcome.solution.has_coefficients)
      {
        TimerOutput::Scope scope(timer, "estimate");
        outcome.goal     = goal_estimator->estimate(set.harmonic(i),
                                                mesh,
                                                problem,
                                                outcome.solution.unit_solutions,
                                                outcome.solution.coefficients);
        outcome.has_goal = true;
        Postprocessors::goal_estimate(outcome.goal,
                                      name_of(parameters.adaptivity.goal),
                                      outcome.report);
      }
    if (!estimate_only)
      {
        TimerOutput::Scope scope(timer, "output");
        outcome.files = write_harmonic_files(outcome.solution, cycle);
      }
    outcome.times = timer.get_summary_data(TimerOutput::total_wall_time);
    // The interface part of the assembly is timed inside it.
    outcome.times["interface assembly"] = problem.time_interface_assembly;
    outcome.times["assembly"] -= problem.time_interface_assembly;
    // Keep the solution for the 3D reconstruction, not the matrix.
    problem.free_system();
  }

  HarmonicSolution
  Simulator::solve_loads(HarmonicProblem &problem) const
  {
    HarmonicSolution solution;
    solution.problem         = &problem;
    const Harmonic &harmonic = problem.get_operator().get_harmonic();
    solution.has_coefficients =
      parameters.rigid_foundation.enabled &&
      parameters.rigid_foundation.stiffness_coefficients && harmonic.n == 1 &&
      harmonic.family == Family::symmetric;
    solution.has_axial_stiffness =
      parameters.rigid_foundation.enabled &&
      parameters.rigid_foundation.stiffness_matrix && harmonic.n == 0;
    solution.report =
      solution.has_coefficients ?
        problem.solve_with_unit_loads(solution.coefficients,
                                      &solution.unit_solutions) :
        problem.solve();
    if (solution.has_axial_stiffness)
      solution.axial_stiffness = problem.foundation_axial_stiffness();
    return solution;
  }

  std::vector<std::string>
  Simulator::write_harmonic_files(const HarmonicSolution &solution,
                                  const unsigned int      cycle) const
  {
    std::vector<std::string> files;
    if (!write_files)
      return files;
    const HarmonicProblem &problem  = *solution.problem;
    const Harmonic        &harmonic = problem.get_operator().get_harmonic();
    if (parameters.output.write_vtu)
      {
        // A stiffness scene's fields are its unit-H and unit-M solutions.
        std::vector<std::pair<std::string, const Vector<double> *>> extra;
        if (solution.unit_solutions.size() == 2)
          extra = {{"unit_H_", &solution.unit_solutions[0]},
                   {"unit_M_", &solution.unit_solutions[1]}};
        // Claimed before it is written, so that an interrupt removes it
        // (its rank pieces once the writer has named them).
        const std::string name = result_files.claim(
          ResultFiles::fill(ResultFiles::harmonic_vtu, harmonic, cycle));
        for (const std::string &file : problem.write_vtu(name, extra))
          files.push_back(file);
        result_files.claim_paths(files);
      }
    if (writes_csv() && problem.get_interfaces() &&
        parameters.output.write_interface_tractions)
      for (const types::boundary_id id :
           problem.get_interfaces()->boundary_ids())
        {
          const std::string name = result_files.claim(ResultFiles::fill(
            ResultFiles::interface_tractions_csv, harmonic, cycle, id));
          files.push_back(name);
          problem.get_interfaces()->write_csv(id, problem.get_solution(), name);
        }
    return files;
  }

  void
  Simulator::collect_cycle(const unsigned int cycle, std::ostream &log)
  {
    indicator = std::make_unique<RefinementIndicator>(*triangulation);
    // The phases of a harmonic's pipeline, in order (TimerOutput sections).
    const std::vector<std::string> phases = {"setup",
                                             "assembly",
                                             "interface assembly",
                                             "solve",
                                             "postprocess",
                                             "estimate",
                                             "output"};
    std::map<std::string, double>  cycle_times;
    double                         cycle_dofs = 0.;
    for (unsigned int i = 0; i < outcomes.size(); ++i)
      {
        HarmonicOutcome &outcome  = outcomes[i];
        const Harmonic  &harmonic = harmonic_set->harmonic(i);
        const auto      &problem  = harmonic_set->problem(i);
        result_files.claim_paths(outcome.files);
        for (const auto &row : outcome.report.rows)
          results.add(row.quantity, harmonic, cycle, row.value, row.unit);
        log << outcome.report.log.str() << std::endl;
        if (parameters.adaptivity.strategy == RefinementStrategy::kelly)
          {
            // The scene's own load may be zero: the unit-H and unit-M
            // fields also steer the mesh.
            indicator->add_kelly(problem.get_dof_handler(),
                                 problem.get_solution());
            for (const auto &field : outcome.solution.unit_solutions)
              indicator->add_kelly(problem.get_dof_handler(), field);
          }
        if (outcome.has_goal)
          indicator->add(outcome.goal.indicators);
        for (const std::string &phase : phases)
          {
            const double t    = outcome.times[phase];
            std::string  name = std::string("time_") +
                               std::regex_replace(phase, std::regex(" "), "_");
            results.add(name, harmonic, cycle, t, "s");
            cycle_times[phase] += t;
          }
        cycle_dofs += problem.get_dof_handler().n_dofs();
        reconstruction.add(harmonic_set->shared_problem(i));
      }
    // DoFs as an integer: the stream may carry an earlier precision.
    log << "cycle " << cycle
        << " summary: " << static_cast<long long>(cycle_dofs) << " dofs, "
        << outcomes.size() << " harmonic(s) on " << harmonic_set->n_threads()
        << " thread(s), wall " << std::setprecision(3) << cycle_wall_time
        << " s; summed over harmonics [s]:";
    const char *separator = " ";
    for (const std::string &phase : phases)
      {
        log << separator << phase << " " << std::setprecision(3)
            << cycle_times[phase];
        separator = ", ";
      }
    log << std::endl;
  }

  bool
  Simulator::goal_tolerance_reached(const unsigned int cycle,
                                    std::ostream      &log) const
  {
    for (const HarmonicOutcome &outcome : outcomes)
      if (outcome.has_goal)
        {
          log << "cycle " << cycle << " goal estimate: relative error "
              << std::setprecision(2) << outcome.goal.goal_error << " ("
              << name_of(parameters.adaptivity.goal) << "), K_H "
              << std::setprecision(7) << outcome.solution.coefficients.K_H
              << ", K_M " << outcome.solution.coefficients.K_M << ", K_MH "
              << outcome.solution.coefficients.K_MH << std::endl;
          if (outcome.goal.goal_error < parameters.adaptivity.goal_tolerance)
            {
              log << "goal tolerance " << parameters.adaptivity.goal_tolerance
                  << " reached: stop after cycle " << cycle << std::endl;
              return true;
            }
        }
    return false;
  }

  void
  Simulator::write_output(std::ostream &log)
  {
    if (!writes_csv())
      return;
    write_run_result_files(
      parameters.output, reconstruction, results, result_files, log);
  }

  CoupledRunContext
  Simulator::coupled_context()
  {
    return CoupledRunContext{parameters,
                             communicator,
                             *triangulation,
                             plan,
                             harmonic_set,
                             results,
                             result_files,
                             reconstruction,
                             writes_csv()};
  }

  void
  Simulator::solve_coupled(std::ostream &log)
  {
    std::unique_ptr<CoupledSceneRun> run;
    if (plan.run_mode == RunMode::interface_load_path)
      run = std::make_unique<InterfaceLoadPathRun>(coupled_context());
    else
      run = std::make_unique<CoupledTangentRun>(coupled_context());
    if (plan.meshes == MeshSequence::one_mesh)
      {
        run->run_on_one_mesh(log);
        return;
      }
    CoupledMeshSequence meshes(*run,
                               coupled_context(),
                               *triangulation,
                               plan,
                               interface_ids,
                               target_not_reached);
    if (plan.meshes == MeshSequence::refinement_cycles)
      {
        meshes.solve_cycles(log);
        return;
      }
    if (parameters.discretization.refinement_cycles != 1)
      log << "Discretization/Refinement cycles = "
          << parameters.discretization.refinement_cycles
          << ": replaced by the nested meshes of Discretization/Target "
             "accuracy"
          << std::endl;
    meshes.solve_to_target(log);
  }
} // namespace FourierSSI
