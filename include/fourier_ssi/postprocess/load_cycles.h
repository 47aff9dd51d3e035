/**
 * The loops of a cyclic load path (Load path/Targets; doc/cyclic-loading.md):
 * per cycle the peak loads, the secant stiffness, the dissipated energy (the
 * loop's area), the damping ratio and the foundation's motion where the load
 * passes zero, from the converged steps of the path.
 *
 * Cycle j (from 1) starts at the end of segment 2j - 1 (turning point A),
 * reverses at the end of segment 2j (B) and ends at the end of segment
 * 2j + 1 (A'): Targets = a, -a, a is one cycle. With F the load conjugate
 * to the controlled motion u:
 *   secant stiffness  k = (F_A' - F_B) / (u_A' - u_B),
 *   dissipated energy W_d = closed integral of F du over A -> B -> A' -> A
 *                     (the trapezoid rule over the steps, the polygon closed
 *                     by the chord A' -> A, zero under displacement
 *                     control where u_A' = u_A),
 *   stored energy     W_s = F_a u_a / 2, F_a = |F_A' - F_B| / 2,
 *                     u_a = |u_A' - u_B| / 2,
 *   damping ratio     xi = W_d / (4 pi W_s), each with its error from the
 *                     steps (Richardson: the loop at every other step),
 * and the motions at zero load interpolated linearly between the two steps
 * of segment 2j + 1 where F changes sign (none if it does not).
 */
#ifndef fourier_ssi_load_cycles_h
#define fourier_ssi_load_cycles_h

#include <fourier_ssi/harmonic/rigid_motion.h>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  /** One converged state of the path, as the loops read it. */
  struct CyclePoint
  {
    /** 0: the state before the first segment; k: a step of segment k. */
    unsigned int segment = 0;
    /** The controlled motion u [m or rad] and its conjugate load F. */
    double motion = 0., load = 0.;
    /** The foundation's whole rigid motion. */
    RigidMotion rigid;
  };

  struct LoadCycle
  {
    /** F at the turning points A' (the end) and B [kN or kNm]. */
    double end_load = 0., reversal_load = 0.;
    /** u at A' and B [m or rad]. */
    double end_motion = 0., reversal_motion = 0.;
    /** The extreme loads over the cycle's steps. */
    double largest_load = 0., smallest_load = 0.;
    double secant_stiffness = 0.;
    /** W_d and W_s [kJ: kN m or kNm rad]. */
    double dissipated_energy = 0., stored_energy = 0.;
    double damping_ratio = 0.;
    /**
     * The error of W_d and xi from the steps of the path (the trapezoid's
     * h^2: a third of the change when every other step is dropped); the
     * mesh and harmonic errors of F are not in it.
     */
    double dissipated_energy_error = 0., damping_ratio_error = 0.;
    /** The load passes zero on the cycle's last segment. */
    bool        passes_zero_load = false;
    RigidMotion at_zero_load;
  };

  /** The names and units the table and the log use. */
  struct CycleQuantities
  {
    /** "H" and "kN"; "horizontal" and "m". */
    std::string load, load_unit, motion, motion_unit;
  };

  /**
   * The complete cycles of `path` (its points in order, every segment's
   * steps with their segment number; the first point the state before
   * segment 1).
   */
  std::vector<LoadCycle>
  load_cycles(const std::vector<CyclePoint> &path);

  /** load-cycles.csv: one row per cycle, the columns named with units. */
  void
  write_load_cycles(std::ostream                 &out,
                    const std::vector<LoadCycle> &cycles,
                    const CycleQuantities        &names);

  /** One log line per cycle. */
  void
  log_load_cycles(std::ostream                 &log,
                  const std::vector<LoadCycle> &cycles,
                  const CycleQuantities        &names);
} // namespace FourierSSI

#endif
