// The two sparse direct back ends give the same answers: CHOLMOD's
// supernodal Cholesky (Linear solver/Method = direct, the default) and
// UMFPACK's LU (direct-lu, the earlier default), on the bundled embedded
// footing (rough, kn = ks = 1e10) with a scene load H = 100, M = 50 and the
// stiffness coefficients (one factorization shared by the three right-hand
// sides), FE_Q(2) and FE_Q(4) with point grading (hanging nodes, rigid-body
// and interface constraints together).
// Both solvers are backward stable, so each result carries a round-off
// error that grows with the condition number, cond ~ 0.28 kn (measured in
// tests/harmonic/robust_penalty.cc): a forward-error bound cond * eps = 6e-7 at
// kn = 1e10. Measured: 1e-9 ... 1e-8. Two checks, on K_H, K_M, K_MH and the
// foundation motion under the scene load:
//  - kn = 1e10 (the scene): Cholesky vs LU within the bound 6e-7;
//  - kn = 1e8: within 6e-9, the same bound scaled with kn. This one fails
//    if the difference were anything but round-off (a wrong factor, a lost
//    constraint), since those do not shrink with kn.
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/driver/simulator.h>

using namespace FourierSSI;

namespace
{
  std::string
  scene(const std::string &method,
        const unsigned int degree,
        const std::string &kn)
  {
    return test_support::footing_one_cycle(degree) +
           "subsection Rigid foundation\n set Horizontal force = 100\n"
           " set Moment = 50\nend\n"
           "subsection Linear solver\n set Method = " +
           method + "\nend\n" +
           "subsection Interfaces\n set Interfaces = 5: kn=" + kn +
           ", ks=" + kn + "\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};
  for (const std::string kn : {"1e10", "1e8"})
    for (const unsigned int degree : {2u, 4u})
      {
        const ResultsTable cholesky =
          test_support::run(scene("direct", degree, kn));
        const ResultsTable lu =
          test_support::run(scene("direct-lu", degree, kn));
        const double      bound = 0.28 * std::stod(kn) * 2.2e-16;
        const std::string at =
          " (FE_Q(" + std::to_string(degree) + "), kn = " + kn + ")";
        for (const std::string q : {"K_H",
                                    "K_M",
                                    "K_MH",
                                    "foundation_horizontal_displacement",
                                    "foundation_rotation"})
          check::relative(q + ": Cholesky vs LU" + at,
                          cholesky.get(q, h, 0),
                          lu.get(q, h, 0),
                          bound);
      }
  return check::summary();
}
