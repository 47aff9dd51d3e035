// Checks shared by the tests of a rigid foundation's stiffness coefficients
// under uniform refinement (embedded footing, pile, adaptive refinement).
#ifndef fourier_ssi_tests_stiffness_checks_h
#define fourier_ssi_tests_stiffness_checks_h

#include "check.h"

#include <array>
#include <cmath>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <iostream>
#include <string>

namespace test_support
{
  /** K on cycles 0, 1, 2 of a run refined uniformly, printed. */
  inline std::array<double, 3>
  three_cycles(const FourierSSI::ResultsTable &results,
               const std::string              &K,
               const FourierSSI::Harmonic     &h)
  {
    const std::array<double, 3> k = {
      {results.get(K, h, 0), results.get(K, h, 1), results.get(K, h, 2)}};
    std::cout << "  " << K << ": " << k[0] << ", " << k[1] << ", " << k[2];
    return k;
  }

  /** Observed order of convergence of three uniformly refined values. */
  inline double
  observed_order(const std::array<double, 3> &k)
  {
    return std::log2((k[1] - k[0]) / (k[2] - k[1]));
  }

  /**
   * Maxwell-Betti: I_MH from the unit-H case equals I_MH from the unit-M
   * case to 1e-6 relative on each cycle (the assembled system is symmetric,
   * so the only difference is round-off of a direct solve; the reason for
   * the tolerance is in each test's header).
   */
  inline void
  check_maxwell_betti(const FourierSSI::ResultsTable &results,
                      const FourierSSI::Harmonic     &h,
                      const unsigned int              n_cycles,
                      const std::string              &what = "")
  {
    for (unsigned int c = 0; c < n_cycles; ++c)
      check::relative(what + "I_MH from H vs from M, cycle " +
                        std::to_string(c),
                      results.get("I_MH_from_H", h, c),
                      results.get("I_MH_from_M", h, c),
                      1e-6);
  }
} // namespace test_support

#endif
