/**
 * A coupled scene on nested meshes, the scene run (coupled_scene_run.h)
 * solving its load path on each: Discretization/Refinement cycles > 1 as a
 * convergence study of the mesh, or Discretization/Target accuracy, the
 * goal value (the capacity, the load at the end of the path or the work of
 * the loads) on nested members of the scene's own mesh with its error from
 * the members, the harmonic truncation and the plateau
 * (doc/soil-plasticity.md section 8c). The next mesh is refined where the
 * last path's mechanism is (Adaptivity/Strategy = kelly) or uniformly
 * (doc/accuracy-vs-time.md, "Coupled scenes").
 */
#ifndef fourier_ssi_coupled_mesh_sequence_h
#define fourier_ssi_coupled_mesh_sequence_h

#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/driver/coupled_scene_run.h>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace FourierSSI
{
  class CoupledMeshSequence
  {
  public:
    /**
     * The sequence changes the mesh (`triangulation`, the context's) and,
     * to study the harmonic truncation, the plan's harmonics; a target
     * that is not met leaves its one line in `target_not_reached`.
     */
    CoupledMeshSequence(CoupledSceneRun                    &run,
                        const CoupledRunContext            &context,
                        Triangulation<2>                   &triangulation,
                        ScenePlan                          &plan,
                        const std::set<types::boundary_id> &interface_ids,
                        std::string                        &target_not_reached);

    /**
     * Discretization/Target accuracy on a coupled scene
     * (doc/soil-plasticity.md section 8c).
     */
    void
    solve_to_target(std::ostream &log);

    /**
     * Discretization/Refinement cycles > 1 on a coupled scene: the path on
     * the scene's mesh, then on each refinement of it (next_coupled_mesh),
     * the goal printed per cycle and its error from the cycles' geometric
     * tail; the last cycle's rows and files.
     */
    void
    solve_cycles(std::ostream &log);

  private:
    /** A cycle's log line and rows (goal, cells, DoFs, wall time). */
    void
    record_coupled_cycle(const unsigned int cycle,
                         const CoupledGoal &goal,
                         const double       wall_time,
                         std::ostream      &log);

    /**
     * The mesh after the current one, aside in `next`: with Adaptivity/
     * Strategy = kelly the current mesh with the Refine fraction of the
     * mechanism's indicator refined (mechanism_indicator.h), else the
     * uniform member `member` of the scene's mesh (build_plastic_member).
     * The current mesh is written (mesh-cycle<member - 1>.vtu) with the
     * indicator that refined it.
     */
    void
    next_coupled_mesh(const unsigned int member, Triangulation<2> &next);

    /**
     * The mesh error of the last of a coupled run's goal values on nested
     * meshes: the geometric tail, with one halving's ratio assumed, and
     * never below adaptive_member_ratio on adaptive members.
     */
    double
    coupled_mesh_error(const std::vector<double> &values) const;

    /**
     * One line if cycle `cycle`'s mesh `next` would exceed Adaptivity/
     * Maximum DoFs (all harmonics) or the memory.
     */
    void
    check_next_cycle_fits(const unsigned int      cycle,
                          const Triangulation<2> &next) const;

    /** The solver and the set released, `next` the current mesh. */
    void
    adopt_coupled_mesh(const Triangulation<2> &next);

    /**
     * mesh-cycle<cycle>.vtu: the current mesh's cells with their material
     * id, refinement level and the indicator given (empty: zero).
     */
    void
    write_coupled_mesh(const unsigned int   cycle,
                       const Vector<float> &indicator);

    /** What the coupled target loop knows after each member. */
    struct CoupledTargetProgress
    {
      /** The goal of each member on these harmonics, and its wall time. */
      std::vector<double> mesh_values, member_times;
      /** Member 0's goal per n_max solved (the truncation sequence). */
      std::map<unsigned int, double> known;
      CoupledGoal                    goal;
      double                         harmonic_error = 0., mesh_error = 0.;

      double
      relative(const double error) const
      {
        return error / std::abs(goal.value);
      }
    };

    /**
     * The next member's mesh, if its DoFs and memory fit (else false, the
     * reason in target_not_reached); the solver and set released.
     */
    bool
    next_coupled_member(const int                    member,
                        const CoupledTargetProgress &progress,
                        std::ostream                &log);

    /** After member 0: go on, solve it again with doubled harmonics, stop. */
    enum class CoarsestMember
    {
      solved,
      solve_again,
      stop
    };

    /**
     * Member 0's harmonic truncation error; doubles the harmonics where it
     * takes more than half the target, or where n_max = 2 cannot show the
     * truncation of a lateral response.
     */
    CoarsestMember
    coarsest_member_harmonics(CoupledTargetProgress &progress,
                              std::ostream          &log);

    /**
     * The solution adds harmonics: Load path/Maximum harmonic (the run's,
     * which a target may raise) above the listed ones.
     */
    bool
    grows() const;

    /**
     * The n_max whose truncation the target estimates: the Maximum
     * harmonic with growth, else the highest listed harmonic.
     */
    unsigned int
    truncated_n_max() const;

    /**
     * The mesh error from the members so far: true if the target is met,
     * or cannot be by a finer mesh (then the reason in target_not_reached).
     */
    bool
    coupled_target_settled(const int              member,
                           CoupledTargetProgress &progress,
                           std::ostream          &log);

    /**
     * The goal values on the current mesh with the harmonics n <= n_max /
     * 4 and n_max / 2 (those that keep n = 1 and differ), into `known`
     * (n_max -> value; the ones already there are not solved again); with
     * growth, the runs that grow up to n_max / 4 and n_max / 2.
     */
    void
    solve_fewer_harmonics(std::map<unsigned int, double> &known,
                          std::ostream                   &log);

    /** The DoFs of all harmonics of the set (one coupled LU). */
    double
    coupled_dofs() const;

    /** target_not_reached = the one line "... not reached: why"; logged. */
    void
    target_unmet(const double       target,
                 const std::string &why,
                 std::ostream      &log);

    /**
     * plan.harmonics to n <= 2 n_max in the same families, with growth
     * the run's Maximum harmonic to 2 n_max (true), or one line in
     * target_not_reached when that would exceed Maximum DoFs or the
     * memory.
     */
    bool
    double_harmonics(const double       target,
                     const std::string &reason,
                     std::ostream      &log);

    /**
     * The goal's error bar: log line and rows (NaN: not estimated;
     * `harmonic_source` says how the harmonic part was found, or why not).
     * The target's rows only with a target.
     */
    void
    report_coupled_error(const CoupledGoal &goal,
                         const unsigned int n_meshes,
                         const double       mesh_error,
                         const double       harmonic_error,
                         const std::string &harmonic_source,
                         std::ostream      &log);

    /** Cells of `next` over the current mesh's: how its DoFs scale. */
    double
    cell_growth(const Triangulation<2> &next) const;

    CoupledSceneRun                    &run;
    const CoupledRunContext             context;
    const AllParameters                &parameters;
    const MPI_Comm                      communicator;
    Triangulation<2>                   &triangulation;
    ScenePlan                          &plan;
    const std::set<types::boundary_id> &interface_ids;
    std::unique_ptr<HarmonicSet>       &harmonic_set;
    ResultsTable                       &results;
    ResultFiles                        &result_files;
    FieldReconstruction                &reconstruction;
    std::string                        &target_not_reached;
    /** Wall time of the solves made only for the error estimate [s]. */
    double estimate_wall_time = 0.;
  };
} // namespace FourierSSI

#endif
