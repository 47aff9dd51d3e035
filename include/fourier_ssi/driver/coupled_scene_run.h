/**
 * A coupled scene run: the load path of CoupledSolver on the scene's
 * HarmonicSet, and its output as postprocessors. One implementation per
 * kind of coupled run (interface_load_path_run.h, coupled_tangent_run.h)
 * says what its goal value is and which postprocessors write its output;
 * the driver walks the meshes (one, Refinement cycles or Target accuracy)
 * and asks the run to solve on each.
 *
 *   run_on_one_mesh:  solve_path (set assembled and factorized, observers
 *                     attached, CoupledSolver::run) -> add_rows -> write_files
 *   on nested meshes: for each mesh { solve -> goal value; release }, then
 *                     add_rows and write_files of the last mesh's path
 */
#ifndef fourier_ssi_coupled_scene_run_h
#define fourier_ssi_coupled_scene_run_h

#include <fourier_ssi/driver/coupled_run_context.h>
#include <fourier_ssi/driver/coupled_run_postprocessor.h>
#include <memory>
#include <ostream>
#include <string>

namespace FourierSSI
{
  class CoupledSolver;

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

  class CoupledSceneRun
  {
  public:
    explicit CoupledSceneRun(const CoupledRunContext &context);

    virtual ~CoupledSceneRun();

    /**
     * The load path on the scene's own mesh, its rows and files; the
     * converged steps of a path that fails are written to
     * load-displacement-incomplete.csv (marked by the name; not claimed: a
     * failed run removes its results, not this record).
     */
    void
    run_on_one_mesh(std::ostream &log);

    /**
     * The load path on the current mesh and plan.harmonics for its goal
     * value; the solver is kept for the rows, the files and the next mesh.
     */
    CoupledGoal
    solve(std::ostream &log);

    /** The solver released (before the mesh or the harmonic set changes). */
    void
    release();

    /**
     * Load path/Maximum harmonic of the paths solved from now on: a target
     * studies the truncation of grown harmonics with a lower one and
     * raises it where the truncation is too large
     * (coupled_mesh_sequence.h). Only the solver sees it; the scene's
     * parameters keep what the user set.
     */
    void
    set_maximum_harmonic(const unsigned int maximum_harmonic);

    /** The parameters the load path is solved with. */
    const AllParameters &
    get_solver_parameters() const;

    /** The rows of the last path (results.csv, log lines). */
    void
    add_rows(std::ostream &log);

    /** The files of the last path, results.csv last. */
    void
    write_files(std::ostream &log);

    /** The solver of the last path: where the next mesh refines. */
    const CoupledSolver &
    last_solver() const;

    /** Row name of the goal: "capacity_", "end_" or "end_load_". */
    virtual std::string
    goal_prefix() const = 0;

    /** The goal is a capacity: its plateau's error counts. */
    virtual bool
    has_plateau() const = 0;

  protected:
    /** The goal value of a converged path. */
    virtual CoupledGoal
    goal_of(const CoupledSolver &solver) const = 0;

    const CoupledRunContext  context;
    CoupledRunPostprocessors postprocessors;

  private:
    /**
     * The harmonic set assembled and factorized, then the load path; the
     * postprocessors observe it where `on_one_mesh`.
     */
    void
    solve_path(std::ostream &log, const bool on_one_mesh);

    /**
     * Under mpirun each rank owns whole harmonics
     * (HarmonicSet::distribute_over), serial systems on cores / ranks
     * threads.
     */
    void
    make_harmonic_set();

    /** Which rank owns which harmonic (several ranks only). */
    void
    log_harmonic_distribution(std::ostream &log) const;

    /** The scene's parameters with this run's Maximum harmonic. */
    AllParameters                  solver_parameters;
    std::unique_ptr<CoupledSolver> solver;
  };
} // namespace FourierSSI

#endif
