// Hard-case stability (doc/robustness.md): near-incompressible soil, nu = 0.49,
// 0.499, 0.4999, against nu = 0.3. Problem with a closed form for every nu,
// non-polynomial and divergence-free in the limit: the Lame thick cylinder
// (a = 1, b = 2, plane strain, internal pressure p = 100 kPa, E = 1e5 kPa,
// n = 0), u = A r + B / r with A = p a^2 / (2 (lambda + G) (b^2 - a^2)) -> 0
// and B = p a^2 b^2 / (2 G (b^2 - a^2)): as nu -> 1/2 the exact field tends
// to the isochoric B / r, the classic volumetric-locking test. 4 x 4 mesh.
//  - p = 4, rectangular cells: no locking. Relative H1 error at every nu
//    within a factor 2 of nu = 0.3 (measured x0.82), L2 within a factor 10
//    (measured x4.6 at 0.4999), and absolute bounds L2 <= 1e-5, H1 <= 1e-4
//    (measured 2.4e-6, 4.3e-5);
//  - p = 2 with Volumetric strain = bbar (dilatation projected onto the
//    cell's linear polynomials, the Q2-P1disc volumetric space), on the
//    rectangular AND the distorted mesh: the same ratio bounds (measured
//    L2 x1.22, H1 x0.82 at 0.4999 on both meshes);
//  - stresses with bbar: the output uses the projected dilatation the
//    equations were solved with (lambda * dilatation is the pressure, finite
//    as lambda -> infinity only if the dilatation is the projected one).
//    sigma_r, sigma_z, sigma_theta at r = 1.25, 1.5, 1.75, z = 0.5 against
//    the closed form sigma_r,t = p a^2/(b^2 - a^2) (1 -+ b^2/r^2),
//    sigma_z = 2 nu p a^2/(b^2 - a^2): max error / p within 3x the
//    nu = 0.3 value and below 2e-2 at every nu (measured in the log);
//  - reported, not asserted (finite only): standard p = 2 locks
//    (rectangular cells: L2 error x430 from nu = 0.3 to 0.4999, H1 x8.3;
//    distorted: x169, x24), and on the distorted mesh (Distortion 0.25)
//    standard p = 4 degrades too (L2 x47, H1 x23, still 4.5e-5 / 1.9e-3
//    absolute) -- Q_p on non-affine cells is not locking-free.
#include "check.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/input/harmonic.h>
#include <utility>
#include <vector>

using namespace FourierSSI;

namespace
{
  std::string
  lame_prm(const unsigned int degree,
           const double       nu,
           const double       distortion,
           const std::string &volumetric = "standard")
  {
    const double a = 1, b = 2, p = 100, E = 1e5;
    const double G = E / (2 * (1 + nu)), lambda = 2 * G * nu / (1 - 2 * nu);
    const double B = p * a * a * b * b / (2 * G * (b * b - a * a));
    const double A = p * a * a / (2 * (lambda + G) * (b * b - a * a));
    return "subsection Discretization\n set Harmonics = 0\n"
           " set Polynomial degree = " +
           std::to_string(degree) + "\n set Volumetric strain = " + volumetric +
           "\nend\n"
           "subsection Mesh\n set R breakpoints = 1, 2\n set R cells = 4\n"
           " set Z breakpoints = 0, 1\n set Z cells = 4\n"
           " set Distortion = " +
           test_support::full_precision(distortion) +
           "\nend\n"
           "subsection Materials\n set Materials = 0: E=1e5, nu=" +
           test_support::full_precision(nu) +
           "\nend\n"
           "subsection Boundary conditions\n set Dirichlet = 2: v=0; 3: v=0\n"
           " set Traction = 0: r=100\nend\n"
           "subsection Exact solution\n set Enabled = true\n set U = " +
           test_support::full_precision(A) + "*r + " +
           test_support::full_precision(B) + "/r\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{0, Family::symmetric};
  for (const double distortion : {0., 0.25})
    for (const auto &[degree, volumetric] :
         std::vector<std::pair<unsigned int, std::string>>{{2u, "standard"},
                                                           {2u, "bbar"},
                                                           {4u, "standard"}})
      {
        double l2_ref = 0, h1_ref = 0;
        for (const double nu : {0.3, 0.49, 0.499, 0.4999})
          {
            const ResultsTable r =
              test_support::run(lame_prm(degree, nu, distortion, volumetric));
            const double l2 = r.get("relative_error_l2", h, 0);
            const double h1 = r.get("relative_error_h1", h, 0);
            if (nu == 0.3)
              l2_ref = l2, h1_ref = h1;
            std::cout << "  distortion " << distortion << ", p = " << degree
                      << " " << volumetric << ", nu = " << nu
                      << ": relative L2 error " << l2 << " (x" << l2 / l2_ref
                      << " vs nu = 0.3), H1 " << h1 << " (x" << h1 / h1_ref
                      << ")" << std::endl;
            const std::string what =
              "p=" + std::to_string(degree) + " " + volumetric +
              ", nu=" + test_support::full_precision(nu) + ", distortion " +
              test_support::full_precision(distortion);
            if ((degree == 4 && distortion == 0.) || volumetric == "bbar")
              {
                check::small(what + ": L2 error / L2 error(nu=0.3)",
                             l2 / l2_ref,
                             10.);
                check::small(what + ": H1 error / H1 error(nu=0.3)",
                             h1 / h1_ref,
                             2.);
              }
            if (degree == 4 && distortion == 0.)
              {
                check::small(what + ": relative L2 error", l2, 1e-5);
                check::small(what + ": relative H1 error", h1, 1e-4);
              }
            else
              check::that(what + ": errors finite (locking reported above)",
                          std::isfinite(l2) && std::isfinite(h1));
          }
      }

  // Stresses of p = 2 bbar (and, reported only, standard p = 2).
  for (const std::string volumetric : {"bbar", "standard"})
    {
      double error_ref = 0.;
      for (const double nu : {0.3, 0.49, 0.499, 0.4999})
        {
          const AllParameters parameters =
            test_support::parameters_from(lame_prm(2, nu, 0., volumetric));
          Simulator simulator(parameters);
          simulator.run(std::cout, false);
          const double p = 100., a = 1., b = 2.;
          const double c     = p * a * a / (b * b - a * a);
          double       error = 0.;
          for (const double r : {1.25, 1.5, 1.75})
            {
              const FieldValues v =
                simulator.get_reconstruction().evaluate(Point<2>(r, 0.5), 0.);
              const double exact_r = c * (1. - b * b / (r * r));
              const double exact_t = c * (1. + b * b / (r * r));
              const double exact_z = 2. * nu * c;
              error                = std::max({error,
                                               std::abs(v.stress[0] - exact_r) / p,
                                               std::abs(v.stress[1] - exact_z) / p,
                                               std::abs(v.stress[2] - exact_t) / p});
            }
          if (nu == 0.3)
            error_ref = error;
          std::cout << "  stresses, p = 2 " << volumetric << ", nu = " << nu
                    << ": max error / p " << error << " (x" << error / error_ref
                    << " vs nu = 0.3)" << std::endl;
          const std::string what = "stresses p=2 " + volumetric +
                                   ", nu=" + test_support::full_precision(nu);
          if (volumetric == "bbar")
            {
              check::small(what + ": max error / p", error, 2e-2);
              check::small(what + ": error / error(nu=0.3)",
                           error / error_ref,
                           3.);
            }
          else
            check::that(what + ": finite (locking reported above)",
                        std::isfinite(error));
        }
    }
  return check::summary();
}
