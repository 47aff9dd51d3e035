/**
 * The output of a load path on the coupled tangent (plastic soil, or a
 * swipe through nonlinear interfaces) as postprocessors
 * (coupled_run_postprocessor.h): the plastic and contact state per step,
 * the pile's soil-reaction curves, the capacity, the plastic field, and
 * the warning of a weightless foundation that heaves.
 */
#ifndef fourier_ssi_plastic_soil_output_h
#define fourier_ssi_plastic_soil_output_h

#include <fourier_ssi/coupled/plastic_field_recorder.h>
#include <fourier_ssi/driver/coupled_run_postprocessor.h>
#include <fourier_ssi/postprocess/soil_reaction_curves.h>
#include <memory>

namespace FourierSSI
{
  /**
   * Per converged step: the harmonics solved (where they grow), the soil's
   * plastic samples and largest yield value, the interfaces' stick, slip
   * and open samples and largest yield value, each where the scene has it.
   */
  class PlasticStateRows : public CoupledRunPostprocessor
  {
  public:
    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;
  };

  /**
   * Output/Soil reaction depths: the curves recorded after every converged
   * step, the pile's balance of them (doc/soil-reaction-curves.md 2) as
   * rows, soil-reaction-curves.csv.
   */
  class SoilReactionOutput : public CoupledRunPostprocessor
  {
  public:
    void
    observe(CoupledSolver &solver, const CoupledRunContext &context) override;

    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;

    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;

  private:
    std::unique_ptr<SoilReactionCurves> curves;
  };

  /**
   * A foundation with no vertical load on it (no Vertical force or Held
   * vertical force, w not held or driven, no Body force) is weightless:
   * pushed sideways over dilatant or frictional soil it rises, which a real
   * caisson or footing under its own weight does not. Warned (one log
   * line), not refused: the path is the one the input asks for.
   */
  class WeightlessHeaveWarning : public CoupledRunPostprocessor
  {
  public:
    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;
  };

  /**
   * A displacement-controlled path's capacity (load_path_capacity.h): rows
   * capacity_<load> with its plateau's rise and error and a log line; a
   * direction probe's point (probe_H, probe_M); the capacity
   * normalisation with the plateau's error alone as its bar (nested meshes
   * add theirs, with the mesh and harmonic errors).
   */
  class CapacityReport : public CoupledRunPostprocessor
  {
  public:
    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;
  };

  /**
   * Output/Plastic field steps of plastic soil: the field of the chosen
   * steps, recorded after every converged step (on nested meshes the last
   * step of the last mesh only), completed after the path (a chosen step
   * beyond it stops the run with one line before any result is written; a
   * collective under mpirun), then its VTU files and .pvd series.
   */
  class PlasticFieldOutput : public CoupledRunPostprocessor
  {
  public:
    void
    observe(CoupledSolver &solver, const CoupledRunContext &context) override;

    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;

    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;

    void
    release() override;

  private:
    /** The recorder, none without soil points or a file to write. */
    void
    start_recording(const CoupledSolver     &solver,
                    const CoupledRunContext &context);

    std::unique_ptr<PlasticFieldRecorder> recorder;
  };
} // namespace FourierSSI

#endif
