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
 *      `design_member_ratio(nu, slip_wedges)`, measured, not derived; see
 *      there.
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
  /** Assumed ratio of one halving of h (see above). */
  constexpr double one_halving_ratio = 0.65;

  /**
   * The assumed member ratio of the Target accuracy family, by the largest
   * Poisson's ratio nu of the scene's materials and whether the scene has
   * a slip wedge (the end of a smooth interface,
   * DiscretizationDesign::slip_wedge_points):
   *   0.4 for nu <  locking_poisson_ratio (0.45, material.h) without,
   *   0.6 for nu >= locking_poisson_ratio, or with a slip wedge.
   * Measured, not derived. With two values the estimate is |d| r/(1-r)
   * and the truth |d| rho/(1-rho), rho = e_1/e_0 the member 0 -> 1 error
   * ratio, so the effectivity is (r/(1-r)) / (rho/(1-rho)) (eq. (2) of
   * doc/accuracy-vs-time.md), >= 0.8 (at most 20 % under-reported) for
   * rho <= 0.45 at r = 0.4 and rho <= 0.65 at r = 0.6. Measured rho
   * (benchmarks/accuracy-on-demand/effectivity.md, "member ratios"):
   *  - nu < 0.45: 0.17 ... 0.28 on the footings, 0.34 ... 0.38 on the
   *    flexible pile, 0.43 on the rigid pile (rough, L/d = 15; three
   *    members, inferred), 0.03 ... 0.17 on Table 4.1: with 0.4 the
   *    effectivity is 0.89 ... 3.2 (Table 4.1: up to 20);
   *  - nu = 0.49: 0.27 ... 0.39 on the template footing (e/a = 1), 0.53
   *    on the shallow one (e/a = 0.5, K_M), 0.45 ... 0.46 on the rough
   *    piles, 0.57 ... 0.63 on the rigid smooth pile (L/d = 15, inferred):
   *    0.4 printed down to 0.39 of the truth there. With 0.6: 0.88 ...
   *    4.1 (Table 4.1's nu = 0.49 column: 7.3 ... 16.5).
   * Near incompressibility slows the first members, not the corners (the
   * Williams exponent of the embedded footing's corner, 0.60 at nu = 0.25
   * and 0.55 at 0.49, predicts rho = 0.08 and 0.10): the dilatation's
   * stiffness lambda/mu = 2 nu/(1 - 2 nu), 49 at nu = 0.49 and 1.7 at
   * 0.25, enters the displacement element's error constant (locking,
   * Babuska & Suri 1992) until h resolves it; the threshold is the one at
   * which FE_Q(2) switches to B-bar. One ratio for all, 0.6, would
   * over-report the nu = 0.25 footings up to 7x and Table 4.1 up to 45x.
   * Smooth interfaces: with their slip wedges graded deeper
   * (slip_wedge_extra_levels) the smooth footings converge at rho = 0.20
   * ... 0.26, but the smooth flexible pile at nu = 0.25 at 0.58 ... 0.61
   * (three members, inferred; 0.46 ... 0.49 before the deeper grading),
   * which 0.4 printed at 0.42 ... 0.48 of the truth. With 0.6: 0.96 ...
   * 1.09 there, 4.3 ... 6.0 on the smooth footings.
   */
  double
  design_member_ratio(const double largest_poisson_ratio,
                      const bool   slip_wedges);

  /**
   * The ratio floor of adaptive members (Adaptivity/Strategy = kelly on a
   * coupled scene, mechanism_indicator.h), also their assumed ratio. Such a
   * member refines the few cells where the mechanism is, and its error falls
   * by a ratio that rises as the singular part is resolved: on the rough
   * footing (Refine fraction 0.6) the capacity's differences fell by 0.55,
   * 0.55 while its errors against Eason & Shield's N_c fell by 0.56, 0.58,
   * 0.60, so an observed ratio under-reported (effectivity 0.88 ... 0.91).
   * Not below one halving's slowest ratio, then (doc/accuracy-vs-time.md,
   * "Coupled scenes").
   */
  constexpr double adaptive_member_ratio = one_halving_ratio;

  /**
   * Eq. (1) for the last of `values` (at least two, nested meshes, coarse
   * to fine); `assumed_ratio` where r cannot be observed, and r no smaller
   * than `ratio_floor`.
   */
  SequenceErrorEstimate
  estimate_sequence_error(const std::vector<double> &values,
                          const double               assumed_ratio,
                          const double ratio_floor = minimum_ratio);
} // namespace FourierSSI

#endif
