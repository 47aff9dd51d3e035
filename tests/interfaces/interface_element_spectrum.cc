// Algebraic structure of the interface matrix: symmetry, positive
// semi-definiteness, and the exact null space. For ks, kn > 0, a face with
// r > 0 and n >= 1 the kernel is exactly "both faces move together"
// (dimension 3 (p + 1)); for n = 0 the vanishing theta weight of one group
// of components adds (p + 1) or 2 (p + 1) further zero modes. Also: for
// n >= 1 the matrix does not depend on n or on the family.

#include "interface_test_support.h"

#include <algorithm>
#include <check.h>
#include <cmath>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace FourierSSI;

namespace
{
  /** Sorted real eigenvalues; also returns the largest imaginary part. */
  std::vector<double>
  eigenvalues(const dealii::FullMatrix<double> &k, double &max_imaginary)
  {
    dealii::LAPACKFullMatrix<double> lapack(k.m(), k.n());
    lapack = k;
    lapack.compute_eigenvalues();
    std::vector<double> values(k.m());
    max_imaginary = 0.;
    for (unsigned int i = 0; i < k.m(); ++i)
      {
        values[i] = lapack.eigenvalue(i).real();
        max_imaginary =
          std::max(max_imaginary, std::abs(lapack.eigenvalue(i).imag()));
      }
    std::sort(values.begin(), values.end());
    return values;
  }

  struct Case
  {
    std::string      name;
    unsigned int     degree;
    dealii::Point<2> start;
    double           angle;
    double           length;
    double           kn;
    double           ks;
  };
} // namespace

int
main()
{
  const double pi = dealii::numbers::PI;

  const std::vector<Case> cases = {
    {"p=2 vertical pile shaft",
     2,
     dealii::Point<2>(0.5, -4.),
     0.5 * pi,
     1.,
     1e6,
     1e6},
    {"p=2 inclined, kn >> ks", 2, dealii::Point<2>(2., 1.), 2.2, 0.7, 5e7, 3e3},
    {"p=2 radial, ks >> kn", 2, dealii::Point<2>(0.1, 0.), 0., 3., 10., 4e4},
    {"p=4 vertical", 4, dealii::Point<2>(1.5, 0.), -0.5 * pi, 2., 2e5, 8e4},
    {"p=4 inclined, kn >> ks", 4, dealii::Point<2>(3., 2.), 0.6, 1.3, 1e8, 1e4},
    {"p=4 radial", 4, dealii::Point<2>(0.05, 1.), 0., 4., 1., 1.},
    {"p=4 radial touching the axis",
     4,
     dealii::Point<2>(0., 1.),
     0.,
     1.,
     3.,
     2.},
    {"p=2 ending on the axis",
     2,
     dealii::Point<2>(1., 1.),
     0.75 * pi,
     std::sqrt(2.),
     3.,
     2.},
  };

  std::mt19937                           rng(31415);
  std::uniform_real_distribution<double> uniform(-1., 1.);

  double worst_asymmetry      = 0.;
  double worst_negative       = 0.;
  double worst_kernel_residue = 0.;
  double smallest_gap         = 1e300;

  for (const Case &c : cases)
    {
      const std::vector<dealii::Point<2>> nodes =
        straight_face(c.degree, c.start, c.angle, c.length);
      const unsigned int m      = c.degree + 1;
      const unsigned int n_dofs = 6 * m;

      for (const Harmonic harmonic : {Harmonic{0, Family::symmetric},
                                      Harmonic{0, Family::antisymmetric},
                                      Harmonic{1, Family::symmetric},
                                      Harmonic{2, Family::antisymmetric}})
        {
          const dealii::FullMatrix<double> k =
            interface_matrix(c.degree, nodes, {c.kn, c.ks}, harmonic);
          const double      scale = max_norm(k);
          const std::string label = c.name + ", " + harmonic.name();

          // Symmetry: the implementation symmetrises, so exactly 0.
          dealii::FullMatrix<double> kt(n_dofs, n_dofs);
          kt.copy_transposed(k);
          kt.add(-1., k);
          worst_asymmetry = std::max(worst_asymmetry, max_norm(kt) / scale);

          double                    max_imaginary = 0.;
          const std::vector<double> lambda     = eigenvalues(k, max_imaginary);
          const double              lambda_max = lambda.back();
          // Zero eigenvalues of a matrix with O(1) entries come out of LAPACK
          // at ~1e-16 * lambda_max; call |lambda| <= 1e-11 lambda_max zero.
          // The gap check below shows the nonzero ones are far above that.
          const double zero_threshold   = 1e-11 * lambda_max;
          unsigned int n_zero           = 0;
          double       smallest_nonzero = 1e300;
          for (const double l : lambda)
            if (std::abs(l) <= zero_threshold)
              ++n_zero;
            else
              smallest_nonzero = std::min(smallest_nonzero, l);
          worst_negative =
            std::max(worst_negative, -lambda.front() / lambda_max);

          // Expected kernel: 3 m rigid "same displacement" modes, plus the
          // components whose theta weight vanishes for n = 0.
          unsigned int expected = 3 * m;
          if (harmonic.n == 0)
            expected += (harmonic.family == Family::symmetric ? 1 : 2) * m;
          check::that(label + ": " + std::to_string(n_zero) +
                        " zero eigenvalues, expected " +
                        std::to_string(expected),
                      n_zero == expected);
          // Imaginary parts: a symmetric matrix has a real spectrum; bound
          // 1e-12 lambda_max covers the round-off of the general solver.
          check::small(label + ": max |Im lambda| / lambda_max",
                       max_imaginary / lambda_max,
                       1e-12);
          if (harmonic.n >= 1 && c.start[0] > 0.)
            smallest_gap =
              std::min(smallest_gap, smallest_nonzero / lambda_max);
          else if (harmonic.n >= 1)
            std::cout << "  (info) " << label
                      << ": smallest nonzero / largest eigenvalue "
                      << smallest_nonzero / lambda_max << std::endl;

          // Kernel vectors: the rigid translations in r, z and theta of both
          // faces together, then an arbitrary displacement shared by them.
          for (unsigned int component = 0; component < 3; ++component)
            {
              dealii::Vector<double> u(n_dofs), f(n_dofs);
              for (unsigned int i = 0; i < 3 * m; ++i)
                u[i] = u[i + 3 * m] = (i % 3 == component ? 1. : 0.);
              k.vmult(f, u);
              worst_kernel_residue =
                std::max(worst_kernel_residue,
                         f.linfty_norm() / (scale * u.linfty_norm()));
            }
          dealii::Vector<double> u(n_dofs), f(n_dofs);
          for (unsigned int i = 0; i < 3 * m; ++i)
            u[i] = u[i + 3 * m] = uniform(rng);
          k.vmult(f, u);
          worst_kernel_residue =
            std::max(worst_kernel_residue,
                     f.linfty_norm() / (scale * u.linfty_norm()));
        }
    }

  // Exactly symmetric by construction.
  check::small("max |K - K^T| / max|K| over all cases", worst_asymmetry, 0.);
  // Positive semi-definite: the most negative eigenvalue is a round-off
  // zero, |lambda_min| <= 1e-12 lambda_max (LAPACK backward error
  // ~ n eps lambda_max with n <= 30).
  check::small("max (-lambda_min / lambda_max) over all cases",
               worst_negative,
               1e-12);
  // The zero/nonzero classification is unambiguous: the smallest nonzero
  // eigenvalue of the r > 0, n >= 1 cases (measured ~7e-6 lambda_max for
  // p = 4 with kn/ks = 1e4) is orders of magnitude above the 1e-11
  // threshold and the zero ones (~1e-16). With the kernel vectors below,
  // 3 (p + 1) zero eigenvalues mean the kernel is exactly the space of
  // "both faces move together".
  check::in_range("min over r > 0, n >= 1 cases of smallest nonzero / "
                  "largest eigenvalue",
                  smallest_gap,
                  1e-8,
                  1.);
  // K u = 0 for the same displacement on both faces: the A-A and A-B
  // blocks cancel up to round-off of O(1) sums (1e-14 relative).
  check::small("max |K u| / (max|K| |u|) for same-displacement vectors",
               worst_kernel_residue,
               1e-14);

  // Harmonic dependence: for n >= 1 both weights are pi, so n and the
  // family do not change the matrix (bit-identical: same operations on the
  // same numbers).
  for (const unsigned int degree : {2u, 4u})
    {
      const std::vector<dealii::Point<2>> nodes =
        straight_face(degree, dealii::Point<2>(0.8, 0.3), 1.1, 1.7);
      const InterfaceStiffness         k{4e3, 9e2};
      const dealii::FullMatrix<double> reference =
        interface_matrix(degree, nodes, k, {1, Family::symmetric});
      double difference = 0.;
      for (const Harmonic harmonic : {Harmonic{1, Family::antisymmetric},
                                      Harmonic{2, Family::symmetric},
                                      Harmonic{7, Family::antisymmetric}})
        {
          dealii::FullMatrix<double> d =
            interface_matrix(degree, nodes, k, harmonic);
          d.add(-1., reference);
          difference = std::max(difference, max_norm(d));
        }
      check::small("p=" + std::to_string(degree) +
                     ": K(n, family) - K(1, symmetric) for n = 1 anti, 2 "
                     "sym, 7 anti",
                   difference,
                   0.);

      // n = 0: the symmetric matrix is the in-plane part of the n >= 1
      // matrix times 2 (weight 2 pi instead of pi), the antisymmetric one
      // the theta part times 2; together they sum to 2 K(n >= 1).
      // Tolerance: one rounding per entry, 1e-15 relative.
      dealii::FullMatrix<double> sum =
        interface_matrix(degree, nodes, k, {0, Family::symmetric});
      sum.add(1.,
              interface_matrix(degree, nodes, k, {0, Family::antisymmetric}));
      sum.add(-2., reference);
      check::small("p=" + std::to_string(degree) +
                     ": K(0, sym) + K(0, anti) - 2 K(1) relative to max|K|",
                   max_norm(sum) / max_norm(reference),
                   1e-15);
    }

  return check::summary();
}
