// Minimal checking helpers for the fourier-ssi test programs: every check
// prints the computed value, the reference and the tolerance, so a log shows
// the numbers and not only pass/fail.
#ifndef fourier_ssi_tests_check_h
#define fourier_ssi_tests_check_h

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

namespace check
{
  inline int &
  n_failed()
  {
    static int n = 0;
    return n;
  }

  inline int &
  n_passed()
  {
    static int n = 0;
    return n;
  }

  /** |value - reference| <= tolerance * max(|reference|, floor). */
  inline void
  relative(const std::string &what,
           const double       value,
           const double       reference,
           const double       tolerance,
           const double       floor = 0.)
  {
    const double scale = std::max(std::abs(reference), floor);
    const double error = std::abs(value - reference) / (scale > 0 ? scale : 1.);
    const bool   ok    = std::isfinite(value) && error <= tolerance;
    std::cout << (ok ? "  ok   " : "  FAIL ") << what << ": "
              << std::setprecision(10) << value << " vs " << reference
              << " (rel. error " << std::setprecision(3) << error << ", tol "
              << tolerance << ")" << std::endl;
    (ok ? n_passed() : n_failed())++;
  }

  /** |value| <= bound. */
  inline void
  small(const std::string &what, const double value, const double bound)
  {
    const bool ok = std::isfinite(value) && std::abs(value) <= bound;
    std::cout << (ok ? "  ok   " : "  FAIL ") << what << ": "
              << std::setprecision(4) << value << " (bound " << bound << ")"
              << std::endl;
    (ok ? n_passed() : n_failed())++;
  }

  /** lower <= value <= upper. */
  inline void
  in_range(const std::string &what,
           const double       value,
           const double       lower,
           const double       upper)
  {
    const bool ok = std::isfinite(value) && value >= lower && value <= upper;
    std::cout << (ok ? "  ok   " : "  FAIL ") << what << ": "
              << std::setprecision(6) << value << " in [" << lower << ", "
              << upper << "]" << std::endl;
    (ok ? n_passed() : n_failed())++;
  }

  /** Exact equality of counts (factorizations, harmonics, cells). */
  inline void
  equal(const std::string &what, const long value, const long reference)
  {
    const bool ok = value == reference;
    std::cout << (ok ? "  ok   " : "  FAIL ") << what << ": " << value
              << " (expected " << reference << ")" << std::endl;
    (ok ? n_passed() : n_failed())++;
  }

  inline void
  that(const std::string &what, const bool condition)
  {
    std::cout << (condition ? "  ok   " : "  FAIL ") << what << std::endl;
    (condition ? n_passed() : n_failed())++;
  }

  /** Print the closing line and return the exit code for main(). */
  inline int
  summary()
  {
    std::cout << n_passed() << " passed, " << n_failed() << " failed"
              << std::endl;
    return n_failed() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
} // namespace check

#endif
