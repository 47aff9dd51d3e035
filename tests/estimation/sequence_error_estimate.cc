// The error of a value on nested meshes from the values on the coarser ones
// (include/fourier_ssi/estimation/sequence_error_estimate.h, eq. (1)): checked on
// sequences whose limit is known, Q_k = Q + C r^k.
//  - r in [0.25, 1): eq. (1) is exact for a geometric sequence (the tail
//    sum), so the estimate equals the true error to round-off (1e-9,
//    differences of values of order 1 lose about 1e-15 / (C r^k)).
//  - r below the floor 0.25: the estimate uses 0.25, an over-estimate by
//    (0.25 / 0.75) / (r / (1 - r)), never an under-estimate.
//  - two values, or differences that do not fall: the assumed ratio.
//  - the assumed member ratio of the Target accuracy family by Poisson's
//    ratio, design_member_ratio(nu), against the slowest member ratios
//    rho = e_1/e_0 measured on each side of the threshold nu = 0.45
//    (benchmarks/accuracy-on-demand/effectivity.md, "member ratios"): on a
//    geometric sequence with ratio rho, the two-value estimate must be at
//    least 0.8 of the true error (the reliability bound of issue 14: at
//    most 20 % under-reported); round-off only, so the bound is exact.
#include "check.h"

#include <cmath>
#include <fourier_ssi/estimation/sequence_error_estimate.h>
#include <string>
#include <tuple>
#include <vector>

using namespace FourierSSI;

namespace
{
  std::vector<double>
  geometric(const double       limit,
            const double       c,
            const double       r,
            const unsigned int n)
  {
    std::vector<double> values;
    for (unsigned int k = 0; k < n; ++k)
      values.push_back(limit + c * std::pow(r, k));
    return values;
  }
} // namespace

int
main()
{
  for (const double r : {0.25, 0.4, 0.63, 0.9})
    {
      const std::vector<double>   q = geometric(10., 0.5, r, 4);
      const SequenceErrorEstimate e =
        estimate_sequence_error(q, one_halving_ratio);
      const double true_error = std::abs(q.back() - 10.);
      check::relative("geometric r = " + std::to_string(r) + ": estimate",
                      e.absolute,
                      true_error,
                      1e-9);
      check::relative("geometric r = " + std::to_string(r) + ": relative",
                      e.relative,
                      true_error / std::abs(q.back()),
                      1e-9);
      check::relative("observed ratio", e.ratio, r, 1e-9);
      check::that("asymptotic", e.asymptotic);
    }
  {
    // A fast fall (r = 0.1) is estimated with the floor 0.25: 3x the truth.
    const std::vector<double>   q = geometric(-8., -1., 0.1, 3);
    const SequenceErrorEstimate e =
      estimate_sequence_error(q, one_halving_ratio);
    const double true_error = std::abs(q.back() + 8.);
    check::relative("r = 0.1: estimate / error = (1/3) / (1/9)",
                    e.absolute / true_error,
                    3.,
                    1e-9);
  }
  {
    // Two values: the assumed ratio of a design member at nu = 0.25, 0.4
    // -> error estimate = |d| 0.4 / 0.6 (eq. (1) with r = 0.4; round-off).
    const SequenceErrorEstimate e =
      estimate_sequence_error({2., 1.5}, design_member_ratio(0.25, false));
    check::relative("two values, assumed 0.4: |d| 2/3",
                    e.absolute,
                    0.5 * 0.4 / 0.6,
                    1e-15);
    check::that("two values: not asymptotic", !e.asymptotic);
  }
  check::relative("nu = 0.44: r = 0.4",
                  design_member_ratio(0.44, false),
                  0.4,
                  0.);
  check::relative("nu = 0.45: r = 0.6",
                  design_member_ratio(0.45, false),
                  0.6,
                  0.);
  check::relative("nu = 0.49: r = 0.6",
                  design_member_ratio(0.49, false),
                  0.6,
                  0.);
  check::relative("nu = 0.25, slip wedge: r = 0.6",
                  design_member_ratio(0.25, true),
                  0.6,
                  0.);
  // Slowest measured member ratio of each class: the estimate from members
  // 0 and 1 of Q_k = Q + C rho^k against the truth |Q_1 - Q|.
  for (const auto &[nu, wedges, rho, where] :
       std::vector<std::tuple<double, bool, double, std::string>>{
         {0.25, false, 0.429, "rigid pile, rough, L/d = 15"},
         {0.49, true, 0.652, "rigid pile, smooth, L/d = 15"},
         {0.25, true, 0.614, "flexible pile, smooth, alpha = 1"}})
    {
      const std::vector<double>   q = geometric(10., 0.5, rho, 2);
      const SequenceErrorEstimate e =
        estimate_sequence_error(q, design_member_ratio(nu, wedges));
      check::in_range("nu = " + std::to_string(nu) +
                        ", rho = " + std::to_string(rho) + " (" + where +
                        "): estimate / error in [0.8, 5]",
                      e.absolute / std::abs(q.back() - 10.),
                      0.8,
                      5.);
    }
  {
    // The fastest smooth class under the slip-wedge ratio 0.6: the smooth
    // embedded footing (rho = 0.20 on K_M) is over-reported 6.0x, above
    // the issue's sharpness goal of 5x (doc/accuracy-vs-time.md, "The slip
    // wedge graded deeper"): only its reliability is asserted here, and
    // the over-report itself, (0.6/0.4)/(0.2/0.8) = 6, to round-off.
    const std::vector<double>   q = geometric(10., 0.5, 0.20, 2);
    const SequenceErrorEstimate e =
      estimate_sequence_error(q, design_member_ratio(0.25, true));
    check::relative("smooth footing, rho = 0.20: estimate / error = 6",
                    e.absolute / std::abs(q.back() - 10.),
                    6.,
                    1e-9);
  }
  {
    // Differences that change sign: not asymptotic, the assumed ratio.
    const SequenceErrorEstimate e =
      estimate_sequence_error({1., 1.2, 1.1}, one_halving_ratio);
    check::relative("sign change: |d| 0.65 / 0.35",
                    e.absolute,
                    0.1 * 0.65 / 0.35,
                    1e-12);
    check::that("sign change: not asymptotic", !e.asymptotic);
  }
  return check::summary();
}
