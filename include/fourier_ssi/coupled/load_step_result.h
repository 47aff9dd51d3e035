/**
 * The record of one converged load step of the coupled solvers, whatever
 * nonlinear sources the scene has: what the load path measured (LoadStep)
 * and each source's state counts, zero for a source the scene does not
 * have. One record, one log line and one row of load-displacement.csv for
 * every coupled run; each source adds its own part to the line and its own
 * columns to the row, and only if the scene has it.
 */
#ifndef fourier_ssi_load_step_result_h
#define fourier_ssi_load_step_result_h

#include <array>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/coupled/nonlinear_soil_points.h>
#include <fourier_ssi/input/parameters.h>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  /**
   * One converged load step: the load path's record, the plastic soil's
   * counts over every (point, theta) sample (SoilYieldCounts) and the
   * nonlinear interfaces'.
   */
  struct LoadStepResult : LoadStep, SoilYieldCounts
  {
    /** Interface (point, theta) samples sticking, slipping, open. */
    ContactCounts contact = {{0, 0, 0}};
    /** `contact` interfaces: Uzawa updates of the multipliers (0 without). */
    unsigned int multiplier_updates = 0;
    /** Largest f(t) of the nonlinear interfaces [kPa] (<= 0 admissible). */
    double largest_interface_yield_value = 0.;
    /**
     * Resultant of the interface traction change on the rigid foundation's
     * material (NonlinearInterfacePoints::foundation_resultant): force
     * (x, y, z) [kN] and moment about the origin (x, y, z) [kN m].
     */
    std::array<double, 6> resultant = {{0., 0., 0., 0., 0., 0.}};
    /** Harmonics solved in this step (grows with Maximum harmonic). */
    unsigned int n_harmonics = 0;
    /** The nonlinear interfaces at every (point, theta) (empty without). */
    InterfaceSnapshot interface_state;
  };

  /** The nonlinear sources of a run: which parts its records have. */
  struct RecordedSources
  {
    bool soil = false;
    /** The nonlinear interfaces (null: none), for their log part. */
    const NonlinearInterfacePoints *interfaces = nullptr;
  };

  /**
   * The log line of a converged step: the applied loads of the scene
   * (V and H always, M and T where it applies them) with the motions they
   * work on, the held reactions, the iterations, each source's counts, the
   * harmonics solved and the wall time.
   */
  void
  write_step_line(std::ostream                    &log,
                  const unsigned int               step,
                  const bool                       holding,
                  const LoadStepResult            &result,
                  const RigidFoundationParameters &foundation,
                  const RecordedSources           &sources);

  /**
   * load-displacement.csv: per converged step the leading columns
   * (load_step_csv_header), the soil's (elastic, plastic, max_yield_kPa)
   * and the interfaces' (stick, slip, open) where the run has them, then
   * harmonics, time_s, held_fraction, a column per held reaction and
   * converged = 1.
   */
  void
  write_load_path_csv(const std::string                 &filename,
                      const std::vector<LoadStepResult> &steps,
                      const RigidFoundationParameters   &foundation,
                      const RecordedSources             &sources);

  /** The interface state of every step (for the state CSV and VTU). */
  std::vector<InterfaceSnapshot>
  interface_states(const std::vector<LoadStepResult> &steps);
} // namespace FourierSSI

#endif
