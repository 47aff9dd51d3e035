// Kelly adaptive refinement on the embedded footing (prm/embedded-footing.prm,
// rough interface on base and side, rigid footing by constraints). The run
// exercises, together, hanging nodes, interface pairs refined alike on both
// sides (a pairing error would abort the run) and the rigid-body constraints.
// The unit-H and unit-M solutions steer the mesh. Reference for K_H, K_M:
// Richardson extrapolation of three uniform meshes (observed order ~1.3).
// Assertion: after 4 Kelly cycles the errors of K_H and K_M are below those of
// ONE uniform refinement, with fewer DoFs than that uniform mesh - adaptivity
// must pay for itself, or it is a toy.
#include "check.h"
#include "stiffness_checks.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/input/harmonic.h>

using namespace FourierSSI;

namespace
{
  std::string
  scene(const std::string &strategy, const unsigned int cycles)
  {
    return test_support::embedded_footing(cycles) +
           test_support::entries("Adaptivity", {{"Strategy", strategy}});
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};
  const ResultsTable uniform = test_support::run(scene("global", 3));
  const ResultsTable kelly   = test_support::run(scene("kelly", 5));
  for (const std::string K : {"K_H", "K_M"})
    {
      const auto   k     = test_support::three_cycles(uniform, K, h);
      const double order = test_support::observed_order(k);
      const double reference =
        k[2] + (k[2] - k[1]) / (std::pow(2., order) - 1.);
      const double error_uniform_1 = std::abs(k[1] - reference) / reference;
      const double error_kelly =
        std::abs(kelly.get(K, h, 4) - reference) / reference;
      std::cout << "; reference " << reference << ", uniform cycle 1 error "
                << error_uniform_1 << " (" << uniform.get("n_dofs", h, 1)
                << " DoFs), Kelly cycle 4 error " << error_kelly << " ("
                << kelly.get("n_dofs", h, 4) << " DoFs)" << std::endl;
      check::that(K + ": Kelly beats one uniform refinement",
                  error_kelly < error_uniform_1);
    }
  check::that("Kelly uses fewer DoFs than one uniform refinement",
              kelly.get("n_dofs", h, 4) < uniform.get("n_dofs", h, 1));
  check::relative("Kelly: I_MH from H vs from M (hanging nodes + interface)",
                  kelly.get("I_MH_from_H", h, 4),
                  kelly.get("I_MH_from_M", h, 4),
                  1e-6);
  return check::summary();
}
