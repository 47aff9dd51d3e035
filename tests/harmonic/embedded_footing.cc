// Embedded rigid footing (e/a = 1, alpha = 0.5, nu = 0.25), thesis chapter
// 4.3, from prm/embedded-footing.prm (the bundled scene; only refinement and
// the interface law change here). Verified:
//  - K_H, K_M, K_MH converge under uniform refinement: the observed order
//    from three meshes must be positive and the last increment below 1%
//    (edge singularities at the footing corners limit the order to ~1);
//  - I_MH from the unit-H case equals I_MH from the unit-M case to 1e-6
//    relative (Maxwell-Betti: the assembled system is symmetric, so the
//    only difference is round-off of a direct solve, condition ~1e12 with
//    kn = 1e10 against G = 1e3: 1e-6 leaves a wide margin);
//  - a smooth interface (ks = 0) gives a smaller K_H than a rough one, but
//    finite: the side wall still pushes normally on the soil.
#include "check.h"
#include "stiffness_checks.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/input/harmonic.h>

using namespace FourierSSI;


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};

  const ResultsTable rough =
    test_support::run(test_support::embedded_footing(3, "rough"));
  for (const std::string K : {"K_H", "K_M", "K_MH"})
    {
      const auto   k     = test_support::three_cycles(rough, K, h);
      const double order = test_support::observed_order(k);
      std::cout << " (observed order " << order << ")" << std::endl;
      check::in_range(K + " observed order", order, 0.5, 3.);
      check::small(K + " last relative increment",
                   std::abs(k[2] - k[1]) / std::abs(k[2]),
                   0.01);
    }
  test_support::check_maxwell_betti(rough, h, 3);

  const ResultsTable smooth =
    test_support::run(test_support::embedded_footing(1, "smooth"));
  const double KH_smooth = smooth.get("K_H", h, 0);
  const double KH_rough  = rough.get("K_H", h, 0);
  std::cout << "  K_H smooth " << KH_smooth << " vs rough " << KH_rough
            << std::endl;
  check::that("smooth K_H < rough K_H", KH_smooth < KH_rough);
  check::that("smooth K_H finite and positive",
              std::isfinite(KH_smooth) && KH_smooth > 0.);
  return check::summary();
}
