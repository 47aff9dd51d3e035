// The Newton globalisation of every coupled solver (safeguarded_newton.h) on
// the textbook case where plain Newton diverges: R(x) = atan(x), whose
// Newton step x <- x - atan(x) (1 + x^2) overshoots ever further from any
// |x0| > 1.3917 (the root of 2 x = (1 + x^2) atan(x)). From x0 = 3:
//  (1) plain Newton (full steps only) diverges: |x| > 1e3 within 5 steps;
//  (2) the soil's setting (no non-improving step, halving down to 1/16)
//      reaches |x| < 1e-12 within 30 updates (measured 5), and a full step
//      that raises |R| is followed at once by a new smallest |R| (at most 1
//      update in a row without one);
//  (3) the interfaces' setting (4 non-improving steps, down to 2^-16)
//      reaches it too, within 40 updates (measured 9), with at most 5
//      updates in a row without a new smallest |R| (the full step from the
//      best and 4 more, then the line search);
//  (4) along an ascent direction (the Newton step negated) no step length
//      lowers |R|: update() returns false and leaves the best iterate
//      (x0) and its evaluation in place.
#include "check.h"

#include <algorithm>
#include <cmath>
#include <fourier_ssi/coupled/safeguarded_newton.h>

using namespace FourierSSI;

namespace
{
  struct Evaluation
  {
    double residual      = 0.;
    double residual_norm = 0.;
  };


  Evaluation
  evaluate(double &x)
  {
    return {std::atan(x), std::abs(std::atan(x))};
  }

  double
  newton_step(const Evaluation &e, const double &x)
  {
    return -e.residual * (1. + x * x);
  }

  void
  move(const double alpha, const double &dx, double &x)
  {
    x += alpha * dx;
  }

  /** R(x) = atan(x) for SafeguardedNewton; `sign` -1 turns the step uphill. */
  struct ArctanSteps
  {
    using State      = double;
    using Evaluation = ::Evaluation;
    using Direction  = double;

    double sign = 1.;

    Evaluation
    evaluate(double &x) const
    {
      return ::evaluate(x);
    }

    double
    direction(const Evaluation &e, const double &x) const
    {
      return sign * newton_step(e, x);
    }

    void
    move(const double alpha, const double &dx, double &x) const
    {
      ::move(alpha, dx, x);
    }
  };

  using Newton = SafeguardedNewton<ArctanSteps>;

  /** Updates until |x| < 1e-12 (or `most`); the |R| after each. */
  std::vector<double>
  solve(const Newton::Settings &settings,
        const unsigned int      most,
        double                 &x,
        bool                   &failed)
  {
    const ArctanSteps   steps;
    Newton              newton(settings, steps);
    Evaluation          e = evaluate(x);
    std::vector<double> norms;
    failed = false;
    while (std::abs(x) >= 1e-12 && norms.size() < most)
      {
        if (!newton.update(x, e))
          {
            failed = true;
            break;
          }
        norms.push_back(e.residual_norm);
      }
    return norms;
  }

  /** The longest run of updates whose |R| is not below every one before. */
  unsigned int
  longest_without_best(const std::vector<double> &norms)
  {
    unsigned int longest = 0, since_best = 0;
    double       best = std::atan(3.);
    for (const double norm : norms)
      if (norm < best)
        best = norm, since_best = 0;
      else
        longest = std::max(longest, ++since_best);
    return longest;
  }
} // namespace

int
main()
{
  // (1)
  double x = 3.;
  for (unsigned int k = 0; k < 5; ++k)
    x += newton_step(evaluate(x), x);
  check::in_range("(1) plain Newton from 3: |x| after 5 steps",
                  std::abs(x),
                  1e3,
                  1e300);

  // (2)
  bool failed                    = false;
  x                              = 3.;
  const std::vector<double> soil = solve({0, 1. / 16., 20}, 30, x, failed);
  check::that("(2) no failure", !failed);
  check::small("(2) |x| at the end", x, 1e-12);
  check::in_range("(2) updates", soil.size(), 1, 30);
  check::in_range("(2) longest run of updates without a new best |R|",
                  longest_without_best(soil),
                  0,
                  1);

  // (3)
  x = 3.;
  const std::vector<double> faces =
    solve({4, 1. / 65536., 1000}, 40, x, failed);
  check::that("(3) no failure", !failed);
  check::small("(3) |x| at the end", x, 1e-12);
  check::in_range("(3) updates", faces.size(), 1, 40);
  check::in_range("(3) longest run of updates without a new best |R|",
                  longest_without_best(faces),
                  0,
                  5);

  // (4)
  const ArctanSteps uphill{-1.};
  Newton            ascent({0, 1. / 16., 20}, uphill);
  x                 = 3.;
  Evaluation e      = evaluate(x);
  const bool first  = ascent.update(x, e); // the full (ascent) step
  const bool second = ascent.update(x, e); // no length lowers |R|
  check::that("(4) the full step is taken", first);
  check::that("(4) then no descent is found", !second);
  check::relative("(4) back at the best iterate", x, 3., 0.);
  check::relative("(4) with its evaluation",
                  e.residual_norm,
                  std::atan(3.),
                  0.);
  return check::summary();
}
