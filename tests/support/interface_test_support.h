// Helpers shared by the interface-element test programs.
#ifndef fourier_ssi_tests_interface_test_support_h
#define fourier_ssi_tests_interface_test_support_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>
#include <vector>

namespace
{
  /** The degree + 1 equidistant nodes of a straight face. */
  inline std::vector<dealii::Point<2>>
  straight_face(const unsigned int      degree,
                const dealii::Point<2> &start,
                const double            angle,
                const double            length)
  {
    std::vector<dealii::Point<2>> nodes(degree + 1);
    for (unsigned int k = 0; k <= degree; ++k)
      {
        const double t = length * k / degree;
        nodes[k] =
          start + dealii::Point<2>(t * std::cos(angle), t * std::sin(angle));
      }
    return nodes;
  }

  /** max |a_ij|. */
  inline double
  max_norm(const dealii::FullMatrix<double> &a)
  {
    double m = 0.;
    for (unsigned int i = 0; i < a.m(); ++i)
      for (unsigned int j = 0; j < a.n(); ++j)
        m = std::max(m, std::abs(a(i, j)));
    return m;
  }
} // namespace

#endif
