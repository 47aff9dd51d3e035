/**
 * The error of a goal value (K_H, a foundation motion, a reaction) from
 * its values on a sequence of nested meshes, the last one being the answer.
 *
 * On nested meshes whose error falls by a steady ratio r per member,
 *   Q - Q_k = sum_{j > k} d_j,  d_j = Q_j - Q_{j-1},  d_{j+1} = r d_j,
 * so the error of the last value is the geometric tail
 *   |Q - Q_k| = |d_k| r / (1 - r)                                  (1)
 * (Aitken's Delta^2 extrapolation, written as an error). r is observed
 * from the last two differences, r = d_k / d_{k-1}. Reliability comes
 * first (an under-reported error is worse than a loose one), so:
 *  - r is used no smaller than `minimum_ratio` (a fast observed fall of one
 *    step need not repeat on the next one);
 *  - with only two values, or when the last two differences change sign or
 *    do not fall (r <= 0 or r >= 1: not yet asymptotic), r is the slowest
 *    ratio the sequence's refinement step can have, `assumed_ratio`, and
 *    the estimate is marked `asymptotic = false`:
 *    - one halving of h (global cycles, a user's mesh against its coarsening
 *      by one level): the slowest order measured on the scenes, h^0.7 at a
 *      smooth-interface slip wedge (doc/accuracy-vs-time.md), 2^-0.7 = 0.62,
 *      taken as `one_halving_ratio` = 0.65;
 *    - a member of the Target accuracy family (discretization_design.h),
 *      `design_member_ratio` = 0.4: measured, not derived. The member
 *      0 -> 1 error ratio e_1/e_0 of the accuracy study (8 cases: rough
 *      and smooth, footing and pile, alpha = 0 ... 1, nu = 0.25 and 0.49;
 *      24 goal values) lies in 0.17 ... 0.39, and in 0.03 ... 0.17 on the
 *      30 scenes of Table 4.1. With two values the estimate is
 *      |d| r/(1-r) and the truth |d| rho/(1-rho), so a ratio r above the
 *      largest rho never under-reports: 0.4 against rho = 0.39 (rough
 *      embedded footing, nu = 0.49, K_MH) gives effectivity 1.03, and
 *      over-reports the fast cases by (0.4/0.6)/(rho/(1-rho)): 3.2 at
 *      rho = 0.17, 5 at rho = 0.12 (doc/accuracy-vs-time.md, effectivity
 *      table). The earlier 0.5 was the slowest rate reasoned from one
 *      halving at order 1.14 (2^-1.14 = 0.45); it over-reported by 1.5x
 *      more everywhere and the measured ratios never came near it.
 */
#ifndef fourier_ssi_sequence_error_estimate_h
#define fourier_ssi_sequence_error_estimate_h

#include <string>
#include <vector>

namespace FourierSSI
{
  struct SequenceErrorEstimate
  {
    /** Estimated |Q - Q_k| in the value's unit, and relative to |Q_k|. */
    double absolute = 0.;
    double relative = 0.;
    /** The ratio r used in (1). */
    double ratio = 0.;
    /** False: fewer than three values, or r observed outside (0, 1). */
    bool asymptotic = false;
  };

  /** Ratio floor in (1): a step may fall faster than the next one. */
  constexpr double minimum_ratio = 0.25;
  /** Assumed ratios of the two kinds of sequence (see above). */
  constexpr double one_halving_ratio   = 0.65;
  constexpr double design_member_ratio = 0.4;

  /**
   * Eq. (1) for the last of `values` (at least two, nested meshes, coarse
   * to fine); `assumed_ratio` where r cannot be observed.
   */
  SequenceErrorEstimate
  estimate_sequence_error(const std::vector<double> &values,
                          const double               assumed_ratio);
} // namespace FourierSSI

#endif
