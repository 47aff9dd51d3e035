// Nested meshes for the coupled scenes (plastic soil, coulomb interfaces):
// Discretization/Refinement cycles > 1 as a convergence study of the mesh,
// and the next mesh of both the study and Discretization/Target accuracy,
// refined where the last path's mechanism is (Adaptivity/Strategy = kelly)
// or uniformly (doc/accuracy-vs-time.md, "Coupled scenes").
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/data_out.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/mechanism_indicator.h>
#include <fourier_ssi/driver/coupled_mesh_sequence.h>
#include <fourier_ssi/driver/memory_estimate.h>
#include <fourier_ssi/estimation/sequence_error_estimate.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/mesh/adaptivity.h>
#include <fourier_ssi/mesh/discretization_design.h>
#include <iomanip>
#include <limits>

namespace FourierSSI
{
  CoupledMeshSequence::CoupledMeshSequence(
    CoupledSceneRun                    &run,
    const CoupledRunContext            &context,
    Triangulation<2>                   &triangulation,
    ScenePlan                          &plan,
    const std::set<types::boundary_id> &interface_ids,
    std::string                        &target_not_reached)
    : run(run)
    , context(context)
    , parameters(context.parameters)
    , communicator(context.communicator)
    , triangulation(triangulation)
    , plan(plan)
    , interface_ids(interface_ids)
    , harmonic_set(context.harmonic_set)
    , results(context.results)
    , result_files(context.result_files)
    , reconstruction(context.reconstruction)
    , target_not_reached(target_not_reached)
  {}

  double
  CoupledMeshSequence::cell_growth(const Triangulation<2> &next) const
  {
    // A member's DoFs scale from the current one's by the cell count
    // (the decision is made before the next mesh is set up).
    return static_cast<double>(next.n_active_cells()) /
           triangulation.n_active_cells();
  }

  void
  CoupledMeshSequence::next_coupled_mesh(const unsigned int member,
                                         Triangulation<2>  &next)
  {
    next.clear();
    if (parameters.adaptivity.strategy != RefinementStrategy::kelly)
      {
        write_coupled_mesh(member - 1, Vector<float>());
        DiscretizationDesign::build_plastic_member(parameters,
                                                   member,
                                                   interface_ids,
                                                   next);
        return;
      }
    const Vector<float> indicator =
      mechanism_indicators(*harmonic_set, run.last_solver());
    write_coupled_mesh(member - 1, indicator);
    next.copy_triangulation(triangulation);
    RefinementIndicator refinement(next);
    refinement.add(indicator);
    // A one-cell slice stays one cell in z, as its uniform members do.
    refinement.refine(next,
                      parameters.adaptivity.refine_fraction,
                      interface_ids,
                      DiscretizationDesign::is_one_cell_slice(parameters.mesh) ?
                        RefinementCase<2>::cut_x :
                        RefinementCase<2>::isotropic_refinement);
  }

  double
  CoupledMeshSequence::coupled_mesh_error(
    const std::vector<double> &values) const
  {
    const bool adaptive =
      parameters.adaptivity.strategy == RefinementStrategy::kelly;
    return estimate_sequence_error(values,
                                   one_halving_ratio,
                                   adaptive ? adaptive_member_ratio :
                                              minimum_ratio)
      .absolute;
  }

  void
  CoupledMeshSequence::check_next_cycle_fits(const unsigned int      cycle,
                                             const Triangulation<2> &next) const
  {
    // The coupled tangent is one LU over all harmonics: their DoFs
    // together are what Maximum DoFs bounds.
    const double dofs = cell_growth(next) * coupled_dofs();
    AssertThrow(dofs <= parameters.adaptivity.maximum_dofs,
                ExcMessage("Discretization/Refinement cycles: the mesh of "
                           "cycle " +
                           std::to_string(cycle) + " (" +
                           std::to_string(next.n_active_cells()) +
                           " cells, about " +
                           std::to_string(static_cast<long long>(dofs)) +
                           " DoFs over all harmonics) exceeds Adaptivity/"
                           "Maximum DoFs = " +
                           std::to_string(static_cast<long long>(
                             parameters.adaptivity.maximum_dofs)) +
                           "; ask fewer cycles or a smaller Refine fraction"));
    check_memory_fits(estimate_run_memory(parameters, next, plan),
                      available_memory_on_all_ranks(communicator));
  }

  void
  CoupledMeshSequence::adopt_coupled_mesh(const Triangulation<2> &next)
  {
    // The fields on the current mesh go before it changes under their DoF
    // handlers.
    run.release();
    reconstruction = FieldReconstruction();
    harmonic_set.reset();
    triangulation.clear();
    triangulation.copy_triangulation(next);
  }

  void
  CoupledMeshSequence::write_coupled_mesh(const unsigned int   cycle,
                                          const Vector<float> &indicator)
  {
    if (!context.writes_csv || !parameters.output.write_vtu)
      return;
    const unsigned int n_cells = triangulation.n_active_cells();
    Vector<float>      material(n_cells), level(n_cells);
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        material(cell->active_cell_index()) = cell->material_id();
        level(cell->active_cell_index())    = cell->level();
      }
    const Vector<float> refined_by =
      indicator.size() == n_cells ? indicator : Vector<float>(n_cells);
    DataOut<2> data_out;
    data_out.attach_triangulation(triangulation);
    data_out.add_data_vector(material, "material_id");
    data_out.add_data_vector(level, "refinement_level");
    data_out.add_data_vector(refined_by, "mechanism_indicator");
    data_out.build_patches();
    const std::string name = result_files.claim(ResultFiles::fill(
      "mesh-cycle{cycle}.vtu", {0, Family::symmetric}, cycle));
    AtomicFile        file(name);
    data_out.write_vtu(file.stream());
    file.commit();
  }

  void
  CoupledMeshSequence::record_coupled_cycle(const unsigned int cycle,
                                            const CoupledGoal &goal,
                                            const double       wall_time,
                                            std::ostream      &log)
  {
    const Harmonic any{0, Family::symmetric};
    const double   dofs = coupled_dofs();
    log << "cycle " << cycle << ": " << triangulation.n_active_cells()
        << " cells, " << static_cast<long long>(dofs)
        << " DoFs over all harmonics, " << run.goal_prefix() << goal.name
        << " = " << std::setprecision(7) << goal.value << " " << goal.unit
        << ", " << std::setprecision(3) << wall_time << std::setprecision(6)
        << " s" << std::endl;
    results.add("cycle_" + run.goal_prefix() + goal.name,
                any,
                cycle,
                goal.value,
                goal.unit);
    results.add("cycle_cells", any, cycle, triangulation.n_active_cells(), "-");
    results.add("cycle_dofs", any, cycle, dofs, "-");
    results.add("cycle_wall_time", any, cycle, wall_time, "s");
  }

  void
  CoupledMeshSequence::solve_cycles(std::ostream &log)
  {
    const unsigned int  n_cycles = parameters.discretization.refinement_cycles;
    std::vector<double> values;
    CoupledGoal         goal;
    Timer               run_timer;
    double              last_cycle_time = 0.;
    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        if (cycle > 0)
          {
            Triangulation<2> next;
            next_coupled_mesh(cycle, next);
            check_next_cycle_fits(cycle, next);
            adopt_coupled_mesh(next);
          }
        Timer cycle_timer;
        goal = run.solve(log);
        values.push_back(goal.value);
        last_cycle_time = cycle_timer.wall_time();
        record_coupled_cycle(cycle, goal, last_cycle_time, log);
      }
    write_coupled_mesh(n_cycles - 1, Vector<float>());
    estimate_wall_time = run_timer.wall_time() - last_cycle_time;
    // Cycles refine the mesh only: the truncation is not studied.
    const bool axisymmetric = highest_harmonic(plan.harmonics) == 0;
    report_coupled_error(goal,
                         values.size(),
                         coupled_mesh_error(values),
                         axisymmetric ?
                           0. :
                           std::numeric_limits<double>::quiet_NaN(),
                         axisymmetric ?
                           "none (n = 0 only: an axisymmetric problem)" :
                           "NOT estimated (Refinement cycles refine the mesh; "
                           "Discretization/Target accuracy also halves n_max)",
                         log);
    run.write_files(log);
  }
} // namespace FourierSSI
