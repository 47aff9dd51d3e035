// Exact elasticity solutions per family; derivations in
// doc/theory.md.
//
// 1. Pure bending of a circular cylinder (Saint-Venant; Timoshenko & Goodier
//    sec. 102): with kappa = M/(E I) the field
//      u_x = -kappa/2 (z^2 + nu (x^2 - y^2)), u_y = -kappa nu x y,
//      u_z = kappa x z
//    has n = 1 symmetric amplitudes U = -kappa/2 (z^2 + nu r^2), V = kappa r z,
//    W = kappa/2 (z^2 - nu r^2); the antisymmetric family is the same field
//    turned by 90 degrees (W -> -W). The only stress is sigma_zz = E kappa x,
//    applied here as the end traction t_z = E kappa r. The amplitudes are
//    quadratic, so FE_Q(2) and FE_Q(4) must reproduce them to round-off on a
//    distorted mesh: tolerance 1e-10 relative (a few thousand DoFs, direct
//    solver, condition number ~1e4).  Solid (touching the axis) and hollow.
// 2. Lame thick cylinder, plane strain, internal pressure p (n = 0):
//      u = A r + B / r, B = p a^2 b^2 / (2 G (b^2 - a^2)),
//      A = p a^2 / (2 (lambda + G) (b^2 - a^2)).
//    Not polynomial: rates must be p+1 (L2) and p (H1) within 0.2 (asymptotic
//    range reached after one refinement on this smooth solution).
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/input/harmonic.h>

using namespace FourierSSI;

namespace
{
  std::string
  bending_prm(const unsigned int degree,
              const std::string &family,
              const double       r_inner)
  {
    return "subsection Discretization\n set Harmonics = 1\n set Family = " +
           family + "\n set Polynomial degree = " + std::to_string(degree) +
           "\nend\n"
           "subsection Mesh\n set R breakpoints = " +
           std::to_string(r_inner) +
           ", 1\n set R cells = 3\n set Z breakpoints = 0, 2\n"
           " set Z cells = 5\n set Distortion = 0.2\nend\n" +
           test_support::bending_conditions(family);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const unsigned int degree : {2u, 4u})
    for (const std::string family : {"symmetric", "antisymmetric"})
      for (const double r_inner : {0., 0.5})
        {
          const std::string what = std::string("bending, ") + family +
                                   (r_inner > 0 ? ", hollow" : ", solid") +
                                   ", p=" + std::to_string(degree);
          const ResultsTable results =
            test_support::run(bending_prm(degree, family, r_inner));
          const Harmonic h{1, family_from_string(family)};
          check::small(what + ": relative L2 error",
                       results.get("relative_error_l2", h, 0),
                       1e-10);
          check::small(what + ": relative H1 error",
                       results.get("relative_error_h1", h, 0),
                       1e-9);
        }

  // Lame cylinder a = 1, b = 2, p = 100 kPa, E = 1e5 kPa, nu = 0.3.
  const double      a = 1, b = 2, p = 100, E = 1e5, nu = 0.3;
  const double      G = E / (2 * (1 + nu)), lambda = 2 * G * nu / (1 - 2 * nu);
  const double      B = p * a * a * b * b / (2 * G * (b * b - a * a));
  const double      A = p * a * a / (2 * (lambda + G) * (b * b - a * a));
  const std::string U = test_support::full_precision(A) + "*r + " +
                        test_support::full_precision(B) + "/r";
  for (const unsigned int degree : {2u, 4u})
    {
      const std::string prm =
        "subsection Discretization\n set Harmonics = 0\n"
        " set Polynomial degree = " +
        std::to_string(degree) +
        "\n set Refinement cycles = 4\nend\n"
        "subsection Mesh\n set R breakpoints = 1, 2\n set R cells = 2\n"
        " set Z breakpoints = 0, 0.5\n set Z cells = 1\nend\n"
        "subsection Materials\n set Materials = 0: E=1e5, nu=0.3\nend\n"
        "subsection Boundary conditions\n set Dirichlet = 2: v=0; 3: v=0\n"
        " set Traction = 0: r=100\nend\n"
        "subsection Exact solution\n set Enabled = true\n set U = " +
        U + "\nend\n";
      const ResultsTable results = test_support::run(prm);
      const Harmonic     h{0, Family::symmetric};
      for (unsigned int cycle = 2; cycle < 4; ++cycle)
        test_support::check_optimal_rates(results, h, degree, cycle, 0.2);
    }
  return check::summary();
}
