/**
 * The output every coupled load path has, as postprocessors
 * (coupled_run_postprocessor.h): the rows of its converged steps and held
 * reactions, load-displacement.csv, the last converged step as every
 * harmonic's field, and the run's results.csv.
 */
#ifndef fourier_ssi_load_path_output_h
#define fourier_ssi_load_path_output_h

#include <deal.II/base/timer.h>
#include <fourier_ssi/driver/coupled_run_postprocessor.h>

namespace FourierSSI
{
  /**
   * The rows of results.csv per converged load step (cycle = step number):
   * the applied loads [kN, kN.m], the foundation motion [m, rad],
   * iterations, residual and wall time.
   */
  class LoadStepRows : public CoupledRunPostprocessor
  {
  public:
    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;
  };

  /**
   * The rows <reaction_row> of the held reactions (the loads that hold
   * Rigid foundation/Held motions, a probe's H and M) at the last step.
   */
  class HeldReactionRows : public CoupledRunPostprocessor
  {
  public:
    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;
  };

  /**
   * load-displacement.csv and its log line. While the path runs, its
   * converged steps so far are kept in load-displacement-incomplete.csv
   * (rewritten whole after a step, at most every
   * incomplete_curve_interval), so that a run stopped from outside (a
   * time limit's SIGTERM, Ctrl-C) leaves the curve it had; the scene run
   * removes it when the path finishes (coupled_scene_run.cc).
   */
  class LoadDisplacementCurve : public CoupledRunPostprocessor
  {
  public:
    void
    observe(CoupledSolver &solver, const CoupledRunContext &context) override;

    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;

    /**
     * Seconds between two writes of the incomplete curve: its rewrite
     * costs milliseconds, a step of a plastic run a tenth of a second to
     * minutes.
     */
    static constexpr double incomplete_curve_interval = 2.;

  private:
    /** Wall time of the last write of the incomplete curve [s]. */
    Timer since_written;
    bool  written = false;
  };

  /**
   * The last converged step as every harmonic's solution (the 3D
   * reconstruction; collective under mpirun: the owner of each harmonic
   * sends its field), and with Output/Write vtu each harmonic's amplitudes
   * through the per-harmonic writer, with the stresses C eps(u) where the
   * soil is elastic (the stress of plastic soil is not C eps(u)).
   */
  class LastStepField : public CoupledRunPostprocessor
  {
  public:
    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;

    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;
  };

  /** The run's last files: lines-3d.csv, solution-3d.vtu, results.csv. */
  class RunResultFiles : public CoupledRunPostprocessor
  {
  public:
    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;
  };

  /**
   * Output/Lines 3D along the reconstruction, Output/Write 3D vtu of it
   * revolved, then results.csv, each with its log line (rank 0 writes
   * them; linear and coupled runs alike).
   */
  void
  write_run_result_files(const OutputParameters    &output,
                         const FieldReconstruction &reconstruction,
                         const ResultsTable        &results,
                         ResultFiles               &result_files,
                         std::ostream              &log);
} // namespace FourierSSI

#endif
