// The iterative solver path (CG + Trilinos ML AMG with the per-component
// constant near-null space) against the direct one on the Lame cylinder
// (n = 0) and the pure-bending cylinder (n = 1), p = 2, ~10k-40k DoFs so that
// ML builds several levels. CG stops at a relative residual of 1e-12, so the
// strain energy (quadratic in the error) must agree with the direct
// solution's to 1e-8 relative. Iteration counts (33-53 measured) are checked
// against a generous bound of 500 only: they depend on the ML version.
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/input/harmonic.h>
#include <tuple>

using namespace FourierSSI;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                lame =
    "subsection Discretization\n set Harmonics = 0\n set Refinement cycles = "
    "2\nend\n"
    "subsection Mesh\n set R breakpoints = 1, 2\n set R cells = 32\n"
    " set Z breakpoints = 0, 0.5\n set Z cells = 16\nend\n"
    "subsection Materials\n set Materials = 0: E=1e5, nu=0.3\nend\n"
    "subsection Boundary conditions\n set Dirichlet = 2: v=0; 3: v=0\n"
    " set Traction = 0: r=100\nend\n";
  const std::string bending =
    "subsection Discretization\n set Harmonics = 1\n set Refinement cycles = "
    "2\nend\n"
    "subsection Mesh\n set R breakpoints = 0, 1\n set R cells = 16\n"
    " set Z breakpoints = 0, 2\n set Z cells = 32\n set Distortion = 0.2\nend\n"
    "subsection Materials\n set Materials = 0: E=1e5, nu=0.3\nend\n"
    "subsection Boundary conditions\n set Dirichlet = 2: u=0, v=0, w=0\n"
    " set Traction = 3: z=100*r\nend\n";
  const std::string cg =
    "subsection Linear solver\n set Method = cg-amg\n set Tolerance = 1e-12\n"
    "end\n";
  for (const auto &[name, prm, h] :
       {std::make_tuple("Lame n=0", lame, Harmonic{0, Family::symmetric}),
        std::make_tuple("bending n=1",
                        bending,
                        Harmonic{1, Family::symmetric})})
    {
      const ResultsTable direct    = test_support::run(prm);
      const ResultsTable iterative = test_support::run(prm + cg);
      for (unsigned int c = 0; c < 2; ++c)
        {
          const std::string what =
            std::string(name) + ", cycle " + std::to_string(c);
          check::relative(what + ": strain energy cg-amg vs direct",
                          iterative.get("strain_energy", h, c),
                          direct.get("strain_energy", h, c),
                          1e-8);
          check::in_range(what + ": cg iterations",
                          iterative.get("solver_iterations", h, c),
                          1,
                          500);
        }
    }
  return check::summary();
}
