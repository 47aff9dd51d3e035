// Volumetric locking cannot slip through the default settings: the
// bundled embedded footing (prm/embedded-footing.prm, two cycles) with a
// nearly incompressible soil, nu = 0.499, and FE_Q(2) left at the default
// Volumetric strain = auto (bbar for p = 2 and nu >= 0.45) must give K_H,
// K_M, K_MH on its finer cycle within 1 % of FE_Q(4) (which does not lock),
// graded toward the footing edges (test_support::footing_one_cycle(4)).
// Measured (doc/robustness.md): the FE_Q(4) reference is within 0.23 % of a
// 295k-DoF FE_Q(4) run; FE_Q(2) auto is +0.6 % on K_M against it (+0.8 %
// against the 295k run), the discretization error of FE_Q(2) on this mesh
// (+0.57 % at nu = 0.3). The explicit `standard` choice is still solved as
// asked; it locks (+5.6 % on K_M), and is checked to lie outside twice the
// tolerance, so that this comparison can fail.
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/driver/simulator.h>

using namespace FourierSSI;

namespace
{
  const std::string nearly_incompressible =
    "subsection Materials\n set Materials = 0: G=1000, nu=0.499, "
    "alpha=0.5, depth_ref=1; 1: E=1e6, nu=0.2\nend\n";
} // namespace

int
main()
{
  const Harmonic     h{1, Family::symmetric};
  const ResultsTable reference = test_support::run(
    test_support::footing_one_cycle(4) + nearly_incompressible);
  const std::string fe_q2 =
    test_support::bundled_prm("prm/embedded-footing.prm") +
    nearly_incompressible;
  const ResultsTable automatic = test_support::run(fe_q2);
  const ResultsTable standard  = test_support::run(
    fe_q2 +
    "subsection Discretization\n set Volumetric strain = standard\nend\n");
  for (const std::string q : {"K_H", "K_M", "K_MH"})
    {
      const double K4 = reference.get(q, h, 0);
      std::cout << "  " << q << ": FE_Q(4) " << K4 << ", FE_Q(2) auto "
                << automatic.get(q, h, 1) << ", FE_Q(2) standard "
                << standard.get(q, h, 1) << std::endl;
      check::relative(q + ", nu = 0.499, FE_Q(2) default vs FE_Q(4)",
                      automatic.get(q, h, 1),
                      K4,
                      0.01);
    }
  const double locked =
    standard.get("K_M", h, 1) / reference.get("K_M", h, 0) - 1.;
  check::in_range("K_M, nu = 0.499, FE_Q(2) standard: relative excess",
                  locked,
                  0.02,
                  1.);
  return check::summary();
}
