// Hard-case stability (doc/robustness.md): frictionless interfaces.
//  - Embedded footing (prm/embedded-footing.prm, one mesh level) with a
//    smooth interface (kn = 1e10, ks = 0) on base and side: the horizontal
//    mode is held only by the normal springs of the side wall, so K_H must
//    be finite, positive and below the rough value; K_M likewise; the solver
//    residual stays below 1e-10 and I_MH from H equals I_MH from M to 1e-6.
//  - A vanishing but non-zero friction (ks = 1e-6) gives the smooth answer
//    to 1e-6 relative (continuity of the limit ks -> 0).
// The genuinely singular case -- a smooth SURFACE footing under H, nothing
// holding it sideways -- is a program-level bad-input test:
// tests/prm/bad_smooth_surface_footing.prm (exit code 1, one line
// containing 'singular').
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/input/harmonic.h>

using namespace FourierSSI;


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};
  const ResultsTable               smooth =
    test_support::run(test_support::embedded_footing(1, "kn=1e10, ks=0"));
  const ResultsTable almost =
    test_support::run(test_support::embedded_footing(1, "kn=1e10, ks=1e-6"));
  const ResultsTable rough =
    test_support::run(test_support::embedded_footing(1, "kn=1e10, ks=1e10"));
  const double KH = smooth.get("K_H", h, 0), KM = smooth.get("K_M", h, 0);
  std::cout << "  smooth: K_H " << KH << ", K_M " << KM << ", K_MH "
            << smooth.get("K_MH", h, 0) << "; rough: K_H "
            << rough.get("K_H", h, 0) << ", K_M " << rough.get("K_M", h, 0)
            << std::endl;
  check::that("smooth K_H, K_M finite and positive",
              std::isfinite(KH) && KH > 0 && std::isfinite(KM) && KM > 0);
  check::that("smooth K_H < rough K_H, smooth K_M < rough K_M",
              KH < rough.get("K_H", h, 0) && KM < rough.get("K_M", h, 0));
  check::small("smooth: solver relative residual",
               smooth.get("solver_relative_residual", h, 0),
               1e-10);
  check::relative("smooth: I_MH from H vs from M",
                  smooth.get("I_MH_from_H", h, 0),
                  smooth.get("I_MH_from_M", h, 0),
                  1e-6);
  check::relative("ks = 1e-6 vs ks = 0: K_H",
                  almost.get("K_H", h, 0),
                  KH,
                  1e-6);
  check::relative("ks = 1e-6 vs ks = 0: K_M",
                  almost.get("K_M", h, 0),
                  KM,
                  1e-6);
  return check::summary();
}
