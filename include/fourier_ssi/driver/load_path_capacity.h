/**
 * The capacity of a displacement-controlled load path: the plateau of the
 * curve, the load that works on the controlled motion at the last step, how
 * much it rose over the last tenth of the controlled path and the plateau's
 * error (the rise to the asymptote of the last three steps,
 * capacity_plateau.h). A plateau rises little; the mesh and harmonic
 * errors need other meshes (Target accuracy, doc/soil-plasticity.md 8c).
 */
#ifndef fourier_ssi_load_path_capacity_h
#define fourier_ssi_load_path_capacity_h

#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <functional>
#include <ostream>
#include <string>

namespace FourierSSI
{
  class CoupledSolver;

  struct Capacity
  {
    NamedLoad load;
    double    rise = 0., plateau_error = 0.;
  };

  /** A load read at each converged step. */
  using LoadAtStep = std::function<NamedLoad(const LoadStepResult &)>;

  /** The applied load that works on the controlled motion. */
  LoadAtStep
  applied_load(const CoupledSolver &solver, const AllParameters &parameters);

  /**
   * A direction probe's H (or M): the load on the foundation along the
   * probe (probe_H, probe_M), not the drive.
   */
  LoadAtStep
  probe_load(const FoundationMotion motion, const AllParameters &parameters);

  /**
   * The load whose capacity Target accuracy estimates: the applied load on
   * the controlled motion, or for a direction probe the probe's own load on
   * it (probe_H when u is driven, probe_M when the rotation is).
   */
  LoadAtStep
  goal_load(const CoupledSolver &solver, const AllParameters &parameters);

  /** The capacity of a displacement-controlled curve of >= 2 steps. */
  Capacity
  capacity_of(const CoupledSolver &solver,
              const AllParameters &parameters,
              const LoadAtStep    &load_at);

  /** A displacement-controlled curve of >= 2 steps: it has a capacity. */
  bool
  has_capacity(const CoupledSolver &solver, const AllParameters &parameters);

  /**
   * Rigid foundation/Capacity normalisation: the capacity `name` = `value`
   * [unit] as NAME = |value| / FORCE, with its relative error bar and what
   * the bar contains (log line, rows capacity_normalised and
   * capacity_normalised_error in row `row`).
   */
  void
  report_normalised_capacity(const RigidFoundationParameters &foundation,
                             const std::string               &name,
                             const double                     value,
                             const std::string               &unit,
                             const double                     relative_error,
                             const std::string               &error_parts,
                             const unsigned int               row,
                             ResultsTable                    &results,
                             std::ostream                    &log);
} // namespace FourierSSI

#endif
