/**
 * The driver, in the shape of deal.II's step-6: make the mesh and the scene
 * plan (the harmonics the loads need, the effects to simulate); for each
 * refinement cycle, set up, assemble and solve every harmonic (a
 * HarmonicSet, harmonics concurrently), post-process each one, estimate and
 * refine; write the output. Files are written only for a run that succeeds;
 * a failure removes what this run wrote, and a run starts by removing the
 * result files an earlier run left in its output directory, so nothing
 * stale or partial is left looking like a result.
 */
#ifndef fourier_ssi_simulator_h
#define fourier_ssi_simulator_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/plastic_field_recorder.h>
#include <fourier_ssi/driver/result_files.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/estimation/goal_estimator.h>
#include <fourier_ssi/estimation/sequence_error_estimate.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/mesh/adaptivity.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <fourier_ssi/postprocess/field_reconstruction.h>
#include <fourier_ssi/postprocess/harmonic_postprocessors.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <fourier_ssi/postprocess/soil_reaction_curves.h>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <set>

namespace FourierSSI
{
  class CoupledSolver;

  class Simulator
  {
  public:
    /**
     * On a communicator of more than one rank each harmonic's linear system
     * is distributed (the mesh and postprocessing are replicated); only rank
     * 0 writes the CSV files, every rank its piece of the VTU output.
     */
    explicit Simulator(const AllParameters &parameters,
                       const MPI_Comm       communicator = MPI_COMM_SELF);

    /**
     * The cores a run may use (0, the default: the node's cores shared
     * among the MPI ranks). Decides, e.g., whether two members of a target
     * run are solved side by side.
     */
    void
    set_cores(const unsigned int n_cores)
    {
      cores = n_cores;
    }

    /** Run everything; returns the scalar results (also written as CSV). */
    ResultsTable
    run(std::ostream &log, const bool write_files = true);

    /** The harmonics of the last cycle, summed in 3D (after run()). */
    const FieldReconstruction &
    get_reconstruction() const
    {
      return reconstruction;
    }

    /** The mesh of the last cycle (after run()). */
    const Triangulation<2> &
    get_triangulation() const
    {
      return *triangulation;
    }

    /**
     * Empty, or the one line saying that Discretization/Target accuracy was
     * not reached (after run(); the front end exits non-zero with it unless
     * Adaptivity/Allow unconverged is set).
     */
    const std::string &
    unmet_target() const
    {
      return target_not_reached;
    }

  private:
    /** What one harmonic produced in a cycle, merged in harmonic order. */
    struct HarmonicOutcome
    {
      HarmonicSolution         solution;
      HarmonicReport           report;
      GoalEstimate             goal;
      bool                     has_goal = false;
      std::vector<std::string> files;
      /** Phase wall times of this harmonic (sections of a TimerOutput). */
      std::map<std::string, double> times;
    };

    /**
     * A decision that reads the file system, made on rank 0 and sent to
     * every rank: ranks that see the disk at different moments (one rank
     * creating the output folder while another checks it) must not take
     * different branches, or the one that goes on waits forever.
     */
    template <typename T>
    T
    decided_on_rank_0(const std::function<T()> &decide) const;

    void
    check_output_paths() const;

    /**
     * A goal value of one harmonic (K_H, a foundation motion, a reaction)
     * on each nested mesh solved so far, coarse to fine.
     */
    struct GoalHistory
    {
      Harmonic            harmonic;
      std::string         quantity;
      std::string         unit;
      std::vector<double> values;
    };

    /** Resets what a run accumulates and opens its catalogue of files. */
    void
    start_run(const bool write_files);

    /** The output folder exists before the run (decided on rank 0). */
    bool
    output_directory_exists() const;

    void
    remove_stale_results() const;

    /** Checks the output paths and creates the folder. */
    void
    prepare_output_directory() const;

    /**
     * Rigid foundation/Capacity normalisation: the capacity `name` =
     * `value` [unit] as NAME = |value| / FORCE, with its relative error bar
     * and what the bar contains (log line, rows capacity_normalised and
     * capacity_normalised_error).
     */
    void
    report_normalised_capacity(const std::string &name,
                               const double       value,
                               const std::string &unit,
                               const double       relative_error,
                               const std::string &error_parts,
                               const unsigned int row,
                               std::ostream      &log);

    /** Stops with one line if the run's estimated memory exceeds the free. */
    void
    check_run_fits_in_memory() const;

    /**
     * A linear scene on Refinement cycles meshes (the coarser member first
     * for an error bar when there is one cycle); stops early where the goal
     * tolerance is met.
     */
    void
    solve_refinement_cycles(std::ostream &log);

    /**
     * After a failure: removes the result files the run claimed and the
     * output folder if the run created it and left it empty.
     */
    void
    discard_results(const bool had_directory);

    void
    make_mesh();

    void
    make_plan(std::ostream &log);

    void
    refine_mesh();

    /**
     * A scene with a nonlinear (coulomb) interface: every harmonic assembled
     * and factorized once, the load steps of CoupledSolver, the
     * load-displacement CSV and results.csv (simulator_nonlinear.cc).
     */
    void
    solve_nonlinear_interfaces(std::ostream &log);
    /** load-displacement.csv of the coupled solver, and its log line. */
    void
    write_load_displacement_csv(const CoupledSolver &solver, std::ostream &log);

    /**
     * The rows of results.csv per converged load step of the coupled
     * solver (cycle = step number): the applied loads [kN, kN.m], the
     * foundation motion [m, rad], iterations, residual and wall time.
     */
    void
    add_load_step_rows(const CoupledSolver &solver);

    /**
     * The rows <reaction_row> of a coupled run's held reactions (the loads
     * that hold Rigid foundation/Held motions, a probe's H and M) at its
     * last converged step.
     */
    void
    add_held_reaction_rows(const CoupledSolver &solver);

    /**
     * The last converged step of the coupled solver as every harmonic's
     * solution (3D and per-harmonic output). Collective under mpirun: the
     * owner of each harmonic sends its field.
     */
    void
    keep_last_step(const CoupledSolver &solver);

    /**
     * Output/Write vtu of a coupled run: each harmonic's amplitudes of the
     * last converged step (keep_last_step()) through the per-harmonic
     * writer, with the stresses C eps(u) if `elastic_stresses`.
     */
    void
    write_last_step_vtu(const bool elastic_stresses, std::ostream &log);

    /**
     * The HarmonicSet of a coupled solve (coulomb interface, plastic soil),
     * assembled and factorized: under mpirun each rank owns whole harmonics
     * (HarmonicSet::distribute_over), serial systems on cores / ranks
     * threads (simulator_nonlinear.cc).
     */
    void
    make_distributed_harmonic_set();
    /** Which rank owns which harmonic (several ranks only). */
    void
    log_harmonic_distribution(std::ostream &log) const;

    /**
     * A scene with plastic soil (Soil plasticity/Laws): the load steps of
     * CoupledSolver on one HarmonicSet (simulator_soil.cc).
     */
    void
    solve_plastic_soil(std::ostream &log);

    /**
     * The HarmonicSet of plan.harmonics on the current mesh and the load
     * path of the CoupledSolver on it; with keep_incomplete, the converged
     * steps of a path that fails are written to
     * load-displacement-incomplete.csv (marked by the name; not claimed: a
     * failed run removes its results, not this record).
     */
    std::unique_ptr<CoupledSolver>
    solve_coupled_curve(
      std::ostream                               &log,
      const bool                                  keep_incomplete,
      const std::function<void(CoupledSolver &)> &before_run = nullptr);

    /**
     * Output/Soil reaction depths: the curves' recorder, fed by the
     * solver after every converged step.
     */
    void
    record_soil_reactions(CoupledSolver &solver);

    /**
     * Output/Plastic field steps of plastic soil: the recorder, fed by the
     * solver after every converged step (none without soil points or
     * without a plastic-field file to write).
     */
    void
    record_plastic_field(CoupledSolver &solver);

    /**
     * The plastic field's VTU files and .pvd series, after the path: a
     * chosen step beyond it stops the run with one line before any result
     * is written (finish_plastic_field, on every rank).
     */
    void
    finish_plastic_field(const CoupledSolver &solver);
    void
    write_plastic_field(std::ostream &log);

    /** A plastic curve's rows (steps, plastic state, capacity). */
    void
    add_plastic_rows(const CoupledSolver &solver, std::ostream &log);

    /** Its CSV files and results.csv. */
    void
    write_plastic_files(const CoupledSolver &solver, std::ostream &log);

    /**
     * Plastic soil on a sequence of nested meshes: Target accuracy (the
     * capacity on the scene's mesh refined until its estimated error, mesh
     * + harmonic truncation + plateau, is below the target;
     * doc/soil-plasticity.md section 8c) or Refinement cycles > 1 (a
     * convergence study of the mesh).
     */
    void
    solve_plastic_soil_on_meshes(std::ostream &log);

    /** The goal value of a coupled load path on one mesh. */
    struct CoupledGoal
    {
      /** The load that works on the controlled motion: H, V, M or T. */
      std::string name, unit;
      double      value = 0.;
      /** The rise to the asymptote (capacity runs; 0 otherwise). */
      double plateau_error = 0.;
      /** Converged steps: the row (cycle) of the goal in results.csv. */
      unsigned int steps = 0;
    };

    /**
     * What the target loop needs from a coupled solver: solve the curve on
     * the current mesh and plan.harmonics (the solver kept), release it
     * (before the mesh or the set change), its rows and files.
     */
    struct CoupledCurveRun
    {
      std::function<CoupledGoal(std::ostream &)> solve;
      std::function<void()>                      release;
      std::function<void(std::ostream &)>        add_rows, write_files;
      /** The solver of the last solve(): where the next mesh refines. */
      std::function<const CoupledSolver &()> last_solver;
      /** Row name of the goal: "capacity_" or "end_load_". */
      std::string goal_prefix;
      /** The goal is a capacity: its plateau error counts. */
      bool plateau = false;
    };

    /**
     * Discretization/Target accuracy on a coupled scene
     * (simulator_coupled_target.cc, doc/soil-plasticity.md section 8c).
     */
    void
    solve_coupled_to_target(std::ostream &log, CoupledCurveRun &run);

    /**
     * Target accuracy if one is set (the Refinement cycles it replaces
     * said so in the log), else the Refinement cycles.
     */
    void
    solve_coupled_on_meshes(std::ostream &log, CoupledCurveRun &run);

    /**
     * Discretization/Refinement cycles > 1 on a coupled scene: the path on
     * the scene's mesh, then on each refinement of it (next_coupled_mesh),
     * the goal printed per cycle and its error from the cycles' geometric
     * tail; the last cycle's rows and files.
     */
    void
    solve_coupled_cycles(std::ostream &log, CoupledCurveRun &run);

    /** A cycle's log line and rows (goal, cells, DoFs, wall time). */
    void
    record_coupled_cycle(const unsigned int     cycle,
                         const CoupledCurveRun &run,
                         const CoupledGoal     &goal,
                         const double           wall_time,
                         std::ostream          &log);

    /**
     * The mesh after the current one, aside in `next`: with Adaptivity/
     * Strategy = kelly the current mesh with the Refine fraction of the
     * mechanism's indicator refined (mechanism_indicator.h), else the
     * uniform member `member` of the scene's mesh (build_plastic_member).
     * The current mesh is written (mesh-cycle<member - 1>.vtu) with the
     * indicator that refined it.
     */
    void
    next_coupled_mesh(const CoupledCurveRun &run,
                      const unsigned int     member,
                      Triangulation<2>      &next);

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
    adopt_coupled_mesh(CoupledCurveRun &run, const Triangulation<2> &next);

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
    next_coupled_member(CoupledCurveRun             &run,
                        const int                    member,
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
     * takes more than half the target.
     */
    CoarsestMember
    coarsest_member_harmonics(CoupledCurveRun       &run,
                              CoupledTargetProgress &progress,
                              const bool             growth,
                              std::ostream          &log);

    /**
     * The mesh error from the members so far: true if the target is met,
     * or cannot be by a finer mesh (then the reason in target_not_reached).
     */
    bool
    coupled_target_settled(const CoupledCurveRun &run,
                           const int              member,
                           CoupledTargetProgress &progress,
                           std::ostream          &log);

    /**
     * The goal values on the current mesh with the harmonics n <= n_max /
     * 4 and n_max / 2 (those that keep n = 1 and differ), into `known`
     * (n_max -> value; the ones already there are not solved again).
     */
    void
    solve_fewer_harmonics(CoupledCurveRun                &run,
                          std::map<unsigned int, double> &known,
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
     * plan.harmonics to n <= 2 n_max in the same families (true), or one
     * line in target_not_reached when that would exceed Maximum DoFs.
     */
    bool
    double_harmonics(CoupledCurveRun &run,
                     const double     target,
                     const double     truncation,
                     std::ostream    &log);

    /**
     * The goal's error bar: log line and rows (NaN: not estimated;
     * `harmonic_source` says how the harmonic part was found, or why not).
     * The target's rows only with a target.
     */
    void
    report_coupled_error(CoupledCurveRun   &run,
                         const CoupledGoal &goal,
                         const unsigned int n_meshes,
                         const double       mesh_error,
                         const double       harmonic_error,
                         const std::string &harmonic_source,
                         std::ostream      &log);

    /** Its rows and the last step as every harmonic's solution. */
    void
    add_interface_rows(const CoupledSolver &solver);

    /** Its CSV files, then write_output() (3D lines, VTU, results). */
    void
    write_interface_files(const CoupledSolver &solver, std::ostream &log);

    /**
     * Output/Interface state steps beyond the path: one line, on every
     * rank, before any result file is written.
     */
    void
    check_interface_state_steps(const CoupledSolver &solver) const;

    /**
     * Output/Interface state 3D: the chosen steps' revolved interface
     * surfaces, their .pvd series and one log line.
     */
    void
    write_interface_state_3d(const CoupledSolver &solver, std::ostream &log);

    /** Set up, assemble, solve and post-process every harmonic. */
    void
    solve_harmonics(const unsigned int cycle);

    /**
     * Discretization/Target accuracy, members 0 (the current mesh) and 1
     * (`next`, from side_by_side_mesh()) at once, each on half of the cores (a
     * lone harmonic leaves cores idle, and the design always needs two members
     * before it can estimate anything); then both are collected in order and
     * member 1 is the current mesh. Same values as one after the other: the
     * assembly does not depend on its thread count.
     */
    void
    solve_two_members(std::unique_ptr<Triangulation<2>> next,
                      std::ostream                     &log);

    /** The designed mesh of `member` (discretization_design.h), aside. */
    std::unique_ptr<Triangulation<2>>
    member_mesh(const unsigned int member) const;

    /**
     * The designed mesh of `member` if both work bounds allow it (Mesh/
     * Maximum DoFs while it is built, Adaptivity/Maximum DoFs by the cell
     * growth); otherwise nullptr, with the target reported unmet.
     */
    std::unique_ptr<Triangulation<2>>
    member_mesh_within_limits(const unsigned int member, std::ostream &log);

    /** Cells of `next` over the current mesh's: how its DoFs scale. */
    double
    cell_growth(const Triangulation<2> &next) const;

    /** The largest DoF count of the current mesh's solved harmonics. */
    double
    solved_dofs() const;

    /**
     * target_not_reached = "... not reached: ... the next mesh (about N
     * DoFs) exceeds Adaptivity/Maximum DoFs"; logged.
     */
    void
    target_unmet_at_limit(const unsigned int      member,
                          const double            dofs,
                          const Triangulation<2> &next,
                          std::ostream           &log);

    /** "Discretization/Target accuracy ... not reached: ... with N DoFs". */
    std::string
    target_unmet_beginning(const unsigned int member) const;

    /** As target_unmet_at_limit, the next mesh refused by Mesh/Maximum DoFs. */
    void
    target_unmet_at_mesh_limit(const unsigned int member,
                               const std::string &limit,
                               std::ostream      &log);

    /** set_cores(), or the node's cores shared among the MPI ranks. */
    unsigned int
    available_cores() const;

    /** How many harmonics run at once on the available cores. */
    unsigned int
    harmonics_at_once() const;

    /**
     * Member 1's mesh if members 0 and 1 fit side by side
     * (solve_two_members()), else null.
     */
    std::unique_ptr<Triangulation<2>>
    side_by_side_mesh() const;

    /**
     * solve_harmonics() on any mesh: a new HarmonicSet on `n_cores` cores
     * (0: the rank's share) and what each harmonic produced; throws on the
     * first failure (the files written so far stay in `solved`).
     */
    void
    solve_harmonics_on(const Triangulation<2>       &mesh,
                       const unsigned int            cycle,
                       const unsigned int            n_cores,
                       std::unique_ptr<HarmonicSet> &set,
                       std::vector<HarmonicOutcome> &solved) const;

    /** Keep the files of `solved` for removal; throw "cycle N, <e>". */
    void
    fail_cycle(const unsigned int                  cycle,
               const std::vector<HarmonicOutcome> &solved,
               const std::exception               &e);

    /** One harmonic of `set` on `mesh`; runs on a worker thread. */
    void
    solve_harmonic(HarmonicSet            &set,
                   const Triangulation<2> &mesh,
                   const unsigned int      i,
                   const unsigned int      cycle,
                   HarmonicOutcome        &outcome) const;

    /**
     * The scene load, and on the stiffness harmonic the unit-H and unit-M
     * loads with the same factorization.
     */
    HarmonicSolution
    solve_loads(HarmonicProblem &problem) const;

    /** VTU and interface CSV files of one harmonic; returns the names. */
    std::vector<std::string>
    write_harmonic_files(const HarmonicSolution &solution,
                         const unsigned int      cycle) const;

    /**
     * Rows, log lines, refinement indicators and the 3D reconstruction of
     * the cycle, in harmonic order (independent of the thread count).
     */
    void
    collect_cycle(const unsigned int cycle, std::ostream &log);

    /**
     * Discretization/Target accuracy: solve the members of the designed
     * family (discretization_design.h) until the estimated error of every
     * goal value is below the target or the next member would exceed
     * Adaptivity/Maximum DoFs.
     */
    void
    solve_to_target(std::ostream &log);

    /**
     * A run on one mesh of its own: solve the mesh coarsened once (every
     * refinement undone by one level) for the goal values only, so that
     * the answer has an error estimate (no rows, log lines or files).
     */
    void
    solve_coarser_member(std::ostream &log);

    /** Append this cycle's goal values (the quantities goal_rows() picks). */
    void
    record_goal_values();

    /** The ratio eq. (1) assumes where it cannot observe one. */
    double
    assumed_ratio() const;

    /**
     * The estimated relative error of every goal value from its nested
     * values (eq. (1) of sequence_error_estimate.h); the largest one.
     */
    double
    largest_estimated_error() const;

    /**
     * The error of one goal value against which the target is tested:
     * relative to the value itself, except for the coupling term K_MH,
     * whose error is relative to sqrt(K_H K_M) of the same harmonic (the
     * scale of the H-M block: |K_MH| <= sqrt(K_H K_M) for a positive
     * definite K). A coupling near zero (a surface disc at nu -> 0.5)
     * then meets a target its own relative error never could.
     */
    double
    goal_error(const GoalHistory &history) const;

    /**
     * Log "K_H = 10.7993 +- 2.1e-05 (rel)" per goal value and write the
     * rows <quantity>_error (relative) under the last cycle.
     */
    void
    report_error_estimates(const unsigned int cycle, std::ostream &log);

    /** True if the goal strategy's estimate meets its tolerance. */
    bool
    goal_tolerance_reached(const unsigned int cycle, std::ostream &log) const;

    /**
     * Rigid foundation/Stiffness matrix: the 6x6 matrix at the reference
     * point from the last mesh's K_V, K_T, K_H, K_M, K_MH with their error
     * estimates; logged and written (foundation-stiffness.csv, the SubDyn
     * SSI file; simulator_stiffness.cc).
     */
    void
    report_foundation_stiffness(std::ostream &log);

    /** The last mesh's value of a goal row of `harmonic`; throws if none. */
    double
    last_value(const std::string &quantity, const Harmonic &harmonic) const;

    /** Its estimated relative error; NaN if not estimated. */
    double
    estimated_error(const std::string &quantity,
                    const Harmonic    &harmonic) const;

    void
    write_output(std::ostream &log);

    bool
    writes_csv() const;

    /**
     * The run's own copy: the mesh-dependent choices
     * (choose_interface_linearisation) are written into it once the first
     * mesh exists.
     */
    AllParameters  parameters;
    const MPI_Comm communicator;
    /** The cores this simulator may use (0: the rank's share). */
    unsigned int cores       = 0;
    bool         write_files = true;
    /** A solve made only for the error estimate: no files. */
    bool                     estimate_only = false;
    std::vector<GoalHistory> goal_histories;
    /** Wall time of the solves made only for the error estimate [s]. */
    double      estimate_wall_time = 0.;
    std::string target_not_reached;
    /**
     * The current mesh, owned here: the reconstruction's DoF handlers live
     * on it. On the heap so that a mesh solved aside (solve_two_members())
     * can become the current one without moving the object its DoF
     * handlers point to.
     */
    std::unique_ptr<Triangulation<2>> triangulation =
      std::make_unique<Triangulation<2>>();
    std::set<types::boundary_id>         interface_ids;
    ScenePlan                            plan;
    std::unique_ptr<GoalEstimator>       goal_estimator;
    std::unique_ptr<HarmonicSet>         harmonic_set;
    std::vector<HarmonicOutcome>         outcomes;
    std::unique_ptr<RefinementIndicator> indicator;
    double                               cycle_wall_time = 0.;
    ResultsTable                         results;
    FieldReconstruction                  reconstruction;
    /** The result files of this run (removed again if it fails). */
    ResultFiles result_files;
    /** Output/Soil reaction depths: the curves of the load path. */
    std::unique_ptr<SoilReactionCurves>   reaction_curves;
    std::unique_ptr<PlasticFieldRecorder> plastic_field;
  };
} // namespace FourierSSI

#endif
