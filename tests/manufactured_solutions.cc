// Manufactured solutions for n = 0, 1, 2, 3 in both families, on the unit
// square r in [0,1], z in [0,1] that touches the axis.
// The amplitudes and body forces come from tests/mms_solutions.h, generated
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

#include <fourier_ssi/harmonic.h>
#include <regex>

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
        const std::string                U = test_support::with_constants(s.U),
                          V                = test_support::with_constants(s.V),
                          W                = test_support::with_constants(s.W);
        const std::string all              = "u=" + U + ", v=" + V + ", w=" + W;
        const std::string prm =
          "subsection Discretization\n set Harmonics = " + std::to_string(s.n) +
          "\n set Family = " + to_string(harmonic.family) +
          "\n set Polynomial degree = " + std::to_string(degree) +
          "\n set Refinement cycles = " + std::to_string(n_cycles) +
          "\nend\n"
          "subsection Mesh\n set R cells = " +
          std::to_string(degree == 2 ? 4 : 2) +
          "\n set Z cells = " + std::to_string(degree == 2 ? 4 : 2) +
          "\n set Distortion = 0.15\nend\n"
          "subsection Materials\n set Materials = 0: E=1e5, nu=0.3\nend\n"
          "subsection Boundary conditions\n set Dirichlet = 1: " +
          all + "; 2: " + all + "; 3: " + all +
          "\nend\n"
          "subsection Body force\n set Radial = " +
          test_support::with_constants(s.f_r) +
          "\n set Axial = " + test_support::with_constants(s.f_z) +
          "\n set Circumferential = " +
          test_support::with_constants(s.f_theta) +
          "\nend\n"
          "subsection Exact solution\n set Enabled = true\n set U = " +
          U + "\n set V = " + V + "\n set W = " + W + "\nend\n";
        const ResultsTable results = test_support::run(prm);
        for (unsigned int cycle = 2; cycle < n_cycles; ++cycle)
          {
            const std::string what = harmonic.name() +
                                     ", p=" + std::to_string(degree) +
                                     ", cycle " + std::to_string(cycle);
            check::in_range(what + ": L2 rate",
                            results.get("rate_l2", harmonic, cycle),
                            degree + 1 - 0.2,
                            degree + 1 + 0.2);
            check::in_range(what + ": H1 rate",
                            results.get("rate_h1", harmonic, cycle),
                            degree - 0.2,
                            degree + 0.2);
          }
      }
  return check::summary();
}
