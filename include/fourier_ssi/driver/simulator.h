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
#include <fourier_ssi/driver/coupled_mesh_sequence.h>
#include <fourier_ssi/driver/coupled_run_context.h>
#include <fourier_ssi/driver/coupled_scene_run.h>
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
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <set>

namespace FourierSSI
{
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
     * Stops with one line if the run's estimated memory exceeds the free;
     * prints the estimate if it is large.
     */
    void
    check_run_fits_in_memory(std::ostream &log) const;

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
     * A coupled scene (plastic soil, coulomb interfaces): the scene run of
     * its run mode (coupled_scene_run.h) on the meshes of its plan, one
     * mesh, Refinement cycles or Target accuracy.
     */
    void
    solve_coupled(std::ostream &log);

    /** What a coupled scene run works on: this simulator's state. */
    CoupledRunContext
    coupled_context();

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

    /**
     * The designed mesh of `member` if both work bounds allow it (Mesh/
     * Maximum DoFs while it is built, Adaptivity/Maximum DoFs by the cell
     * growth); otherwise nullptr, with the target reported unmet.
     */
    std::unique_ptr<Triangulation<2>>
    member_mesh_within_limits(const unsigned int member, std::ostream &log);

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
    /**
     * Mutable: the harmonics' writers (const, on worker threads) claim
     * their files as they write them; ResultFiles::claim takes a lock.
     */
    mutable ResultFiles result_files;
  };
} // namespace FourierSSI

#endif
