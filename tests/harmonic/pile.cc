// Laterally loaded flexible pile (thesis chapter 6) from prm/pile.prm:
// L/d = 10, Ep/Es = 1000, Gibson soil (alpha = 1), rough interface on the
// shaft and base, H and M through a rigid head cap. Verified:
//  - K_H, K_M, K_MH converge under refinement (last relative increment
//    below 0.5%, an engineering accuracy; measured 0.02%);
//  - I_MH from unit H equals I_MH from unit M to 1e-6 (Maxwell-Betti,
//    same reasoning as tests/harmonic/embedded_footing.cc);
//  - smooth (ks = 0) gives a smaller K_H than rough.
// This scene also exercises interface lines that meet the axis and an
// L-shaped interface around a flexible body (a regression test: repeated
// node indices once corrupted the sparsity pattern there).
#include "check.h"
#include "stiffness_checks.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/input/harmonic.h>

using namespace FourierSSI;

namespace
{
  std::string
  scene(const std::string &interface, const unsigned int cycles)
  {
    return test_support::bundled_prm("prm/pile.prm",
                                     {{"Global refinements", "0"},
                                      {"Interfaces", "5: " + interface}}) +
           test_support::entries(
             "Discretization", {{"Refinement cycles", std::to_string(cycles)}});
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};
  const ResultsTable               rough = test_support::run(scene("rough", 3));
  for (const std::string K : {"K_H", "K_M", "K_MH"})
    {
      const auto k = test_support::three_cycles(rough, K, h);
      std::cout << std::endl;
      check::small(K + " last relative increment",
                   std::abs(k[2] - k[1]) / std::abs(k[2]),
                   0.005);
    }
  test_support::check_maxwell_betti(rough, h, 3);
  const ResultsTable smooth = test_support::run(scene("smooth", 1));
  std::cout << "  K_H smooth " << smooth.get("K_H", h, 0) << " vs rough "
            << rough.get("K_H", h, 0) << std::endl;
  check::that("smooth K_H < rough K_H",
              smooth.get("K_H", h, 0) < rough.get("K_H", h, 0));
  return check::summary();
}
