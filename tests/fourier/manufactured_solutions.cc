// Manufactured solutions for n = 0, 1, 2, 3 in both families, on the unit
// square r in [0,1], z in [0,1] that touches the axis.
// The amplitudes and body forces come from tests/support/mms_solutions.h, generated
// by doc/derivations/manufactured_solutions.py from the full 3D equilibrium
// in cylindrical coordinates (independent of the B operator in the code).
// The exact amplitudes are prescribed on r = 1, z = 0, z = 1; on the axis
// only the axis conditions act. Wrong axis conditions would pin the solution
// to wrong values or leave it singular, and the rates would collapse.
// Assertion: observed rates p+1 (L2) and p (H1), +-0.2 (the optimal
// orders of FE_Q(p) for a smooth solution, with margin), on the
// last three of four refinements (the first step, from a 2x2 mesh for
// p = 4, is pre-asymptotic: rates 4.2-4.8 there).
#include "check.h"
#include "mms_solutions.h"
#include "test_support.h"

#include <fourier_ssi/fourier/harmonic.h>

using namespace FourierSSI;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n_cycles = 5;
  for (const unsigned int degree : {2u, 4u})
    for (unsigned int k = 0; k < mms::n_solutions; ++k)
      {
        const mms::ManufacturedSolution &s = mms::solutions[k];
        const Harmonic                   harmonic{s.n,
                                s.symmetric ? Family::symmetric :
                                                                Family::antisymmetric};
        const std::string prm = test_support::manufactured_solution_prm(
          s, to_string(harmonic.family), degree, n_cycles);
        const ResultsTable results = test_support::run(prm);
        for (unsigned int cycle = 2; cycle < n_cycles; ++cycle)
          test_support::check_optimal_rates(
            results, harmonic, degree, cycle, 0.2);
      }
  return check::summary();
}
