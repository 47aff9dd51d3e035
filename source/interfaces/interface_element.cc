#include <array>
#include <cmath>
#include <cstdio>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <iomanip>
#include <sstream>
#include <string>

namespace FourierSSI
{
  namespace
  {
#include "interface_element_tables.inc"

    /** Short text of a number for error messages ("1e-08", "-0.5"). */
    std::string
    to_text(const double x)
    {
      std::ostringstream out;
      out << std::setprecision(6) << x;
      return out.str();
    }

    template <std::size_t N>
    TripleProductTable
    make_table(const unsigned int degree, const std::array<ExactRational, N> &a)
    {
      TripleProductTable table;
      table.degree = degree;
      table.entries.assign(a.begin(), a.end());
      return table;
    }

    /**
     * The checked geometry of a straight equidistant face: its length l, the
     * unit tangent (cos alpha, sin alpha) from node 0 to node p (the angle
     * alpha of eq. 3.7) and the nodal radii r_k (eq. 3.16).
     */
    struct FaceGeometry
    {
      double              length;
      double              cos_alpha;
      double              sin_alpha;
      std::vector<double> radii;
    };

    /** Relative tolerance (to the face length) on the node layout. */
    constexpr double layout_tolerance = 1e-8;

    FaceGeometry
    check_input(const unsigned int                   degree,
                const std::vector<dealii::Point<2>> &nodes,
                const InterfaceStiffness            &stiffness)
    {
      AssertThrow(degree == 2 || degree == 4,
                  dealii::ExcMessage(
                    "interface element: degree must be 2 (6-node element) or "
                    "4 (10-node element), got " +
                    std::to_string(degree)));
      AssertThrow(nodes.size() == degree + 1,
                  dealii::ExcMessage("interface element of degree " +
                                     std::to_string(degree) + " needs " +
                                     std::to_string(degree + 1) +
                                     " nodes along the face, got " +
                                     std::to_string(nodes.size())));
      AssertThrow(std::isfinite(stiffness.normal) && stiffness.normal >= 0. &&
                    std::isfinite(stiffness.shear) && stiffness.shear >= 0.,
                  dealii::ExcMessage(
                    "interface element: the stiffnesses must be finite and "
                    ">= 0, got kn = " +
                    to_text(stiffness.normal) +
                    ", ks = " + to_text(stiffness.shear)));

      const dealii::Point<2>    &first  = nodes.front();
      const dealii::Tensor<1, 2> chord  = nodes.back() - first;
      const double               length = chord.norm();
      AssertThrow(std::isfinite(length) && length > 0.,
                  dealii::ExcMessage(
                    "interface element: the face has zero length (first and "
                    "last node coincide)"));

      FaceGeometry geometry;
      geometry.length    = length;
      geometry.cos_alpha = chord[0] / length;
      geometry.sin_alpha = chord[1] / length;
      geometry.radii.resize(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          const dealii::Point<2> expected =
            first + (static_cast<double>(k) / degree) * chord;
          const double offset = nodes[k].distance(expected);
          AssertThrow(offset <= layout_tolerance * length,
                      dealii::ExcMessage(
                        "interface element: node " + std::to_string(k) +
                        " is " + to_text(offset / length) +
                        " face lengths away from its place on the straight "
                        "equidistant face (tolerance " +
                        to_text(layout_tolerance) +
                        "); curved or unevenly spaced faces are not "
                        "supported"));
          AssertThrow(nodes[k][0] >= -1e-12 * length,
                      dealii::ExcMessage(
                        "interface element: node " + std::to_string(k) +
                        " has negative radius r = " + to_text(nodes[k][0])));
          geometry.radii[k] = std::max(nodes[k][0], 0.);
        }
      return geometry;
    }

    /**
     * The weighted constitutive matrix in the local frame (s, n, theta):
     * diag(w_in ks, w_in kn, w_out ks), eq. 3.8d times the theta integrals of
     * the squared trigonometric factors (the pi of eq. 3.15 for n >= 1).
     */
    std::array<double, 3>
    weighted_stiffness(const InterfaceStiffness &stiffness,
                       const Harmonic           &harmonic)
    {
      const double in_plane = harmonic.in_plane_weight();
      const double out      = harmonic.out_of_plane_weight();
      return {{in_plane * stiffness.shear,
               in_plane * stiffness.normal,
               out * stiffness.shear}};
    }

    /**
     * Rows of the rotation T of eq. 3.8c: the local unit vectors s, n, theta
     * in global (r, z, theta) components.
     */
    dealii::FullMatrix<double>
    rotation(const FaceGeometry &geometry)
    {
      dealii::FullMatrix<double> t(3, 3);
      t(0, 0) = geometry.cos_alpha;
      t(0, 1) = geometry.sin_alpha;
      t(1, 0) = -geometry.sin_alpha;
      t(1, 1) = geometry.cos_alpha;
      t(2, 2) = 1.;
      return t;
    }
  } // namespace



  const ExactRational &
  TripleProductTable::operator()(const unsigned int i,
                                 const unsigned int j,
                                 const unsigned int k) const
  {
    const unsigned int m = n_nodes();
    AssertIndexRange(i, m);
    AssertIndexRange(j, m);
    AssertIndexRange(k, m);
    return entries[(i * m + j) * m + k];
  }



  const TripleProductTable &
  lagrange_triple_product_table(const unsigned int degree)
  {
    AssertThrow(degree == 2 || degree == 4,
                dealii::ExcMessage("triple-product tables exist for degree 2 "
                                   "and 4 only, got " +
                                   std::to_string(degree)));
    static const TripleProductTable quadratic =
      make_table(2, triple_products_degree_2);
    static const TripleProductTable quartic =
      make_table(4, triple_products_degree_4);
    return degree == 2 ? quadratic : quartic;
  }



  dealii::FullMatrix<double>
  interface_matrix(const unsigned int                   degree,
                   const std::vector<dealii::Point<2>> &nodes,
                   const InterfaceStiffness            &stiffness,
                   const Harmonic                      &harmonic)
  {
    const FaceGeometry        geometry = check_input(degree, nodes, stiffness);
    const TripleProductTable &table    = lagrange_triple_product_table(degree);
    const unsigned int        m        = degree + 1;
    const std::array<double, 3> d = weighted_stiffness(stiffness, harmonic);

    // Scalar face integrals int_0^l N_i N_j r ds = l sum_k T_ijk r_k; for
    // degree 2 these are l times the thesis's a..f (eqs 3.17-3.22, 3.24-3.29
    // corrected), for degree 4 l times its a..r (eqs 7.13-7.41 corrected).
    dealii::FullMatrix<double> face_integral(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        {
          double sum = 0.;
          for (unsigned int k = 0; k < m; ++k)
            sum += table(i, j, k).value() * geometry.radii[k];
          face_integral(i, j) = geometry.length * sum;
        }

    // Local matrix K' (eq. 3.23 / 7.10): relative displacement = B - A, so
    // the node blocks are +M_ij D on AA and BB, -M_ij D on AB and BA.
    const unsigned int         n_dofs = 6 * m;
    dealii::FullMatrix<double> local(n_dofs, n_dofs);
    for (unsigned int side_a = 0; side_a < 2; ++side_a)
      for (unsigned int side_b = 0; side_b < 2; ++side_b)
        {
          const double sign = (side_a == side_b) ? 1. : -1.;
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              for (unsigned int c = 0; c < 3; ++c)
                local(3 * (side_a * m + i) + c, 3 * (side_b * m + j) + c) =
                  sign * face_integral(i, j) * d[c];
        }

    // T* = block diag(T, ..., T) (eq. 3.8c) and K = T*^T K' T* (eq. 3.13c).
    const dealii::FullMatrix<double> t = rotation(geometry);
    dealii::FullMatrix<double>       t_star(n_dofs, n_dofs);
    for (unsigned int node = 0; node < 2 * m; ++node)
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          t_star(3 * node + a, 3 * node + b) = t(a, b);

    dealii::FullMatrix<double> global(n_dofs, n_dofs);
    global.triple_product(local, t_star, t_star, true, false);

    // The triple product is symmetric in exact arithmetic; remove the
    // round-off asymmetry so that callers get an exactly symmetric matrix.
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int j = i + 1; j < n_dofs; ++j)
        {
          const double mean = 0.5 * (global(i, j) + global(j, i));
          global(i, j) = global(j, i) = mean;
        }
    return global;
  }



  dealii::Quadrature<1>
  nonlinear_interface_rule(const unsigned int degree, const bool nodal)
  {
    if (nodal)
      return dealii::QGaussLobatto<1>(degree + 1);
    return dealii::QGauss<1>(degree + 1);
  }

  dealii::FullMatrix<double>
  interface_matrix_by_quadrature(const unsigned int                   degree,
                                 const std::vector<dealii::Point<2>> &nodes,
                                 const InterfaceStiffness            &stiffness,
                                 const Harmonic                      &harmonic,
                                 const dealii::Quadrature<1> &quadrature)
  {
    const FaceGeometry geometry = check_input(degree, nodes, stiffness);
    AssertThrow(quadrature.size() > 0,
                dealii::ExcMessage("interface element: empty quadrature rule"));
    const unsigned int          m = degree + 1;
    const std::array<double, 3> d = weighted_stiffness(stiffness, harmonic);

    // Lagrange polynomials of the equidistant nodes, from deal.II.
    std::vector<dealii::Point<1>> support(m);
    for (unsigned int k = 0; k < m; ++k)
      support[k][0] = static_cast<double>(k) / degree;
    const std::vector<dealii::Polynomials::Polynomial<double>> basis =
      dealii::Polynomials::generate_complete_Lagrange_basis(support);

    // Local unit vectors in global components: s, n (s rotated by +90
    // degrees) and theta.
    const double frame[3][3] = {{geometry.cos_alpha, geometry.sin_alpha, 0.},
                                {-geometry.sin_alpha, geometry.cos_alpha, 0.},
                                {0., 0., 1.}};

    const unsigned int         n_dofs = 6 * m;
    dealii::FullMatrix<double> matrix(n_dofs, n_dofs);
    dealii::FullMatrix<double> b(3, n_dofs);
    const double               r_first = geometry.radii.front();
    const double               r_last  = geometry.radii.back();
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const double xi = quadrature.point(q)[0];
        // r on the straight segment, and ds = l dxi.
        const double r  = (1. - xi) * r_first + xi * r_last;
        const double jw = quadrature.weight(q) * geometry.length * r;

        // B maps the global nodal amplitudes to the local relative
        // displacement amplitudes (s, n, theta): -N_i on face A, +N_i on B.
        for (unsigned int side = 0; side < 2; ++side)
          for (unsigned int i = 0; i < m; ++i)
            {
              const double n_i = (side == 0 ? -1. : 1.) * basis[i].value(xi);
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int g = 0; g < 3; ++g)
                  b(c, 3 * (side * m + i) + g) = n_i * frame[c][g];
            }

        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = 0; j < n_dofs; ++j)
            {
              double sum = 0.;
              for (unsigned int c = 0; c < 3; ++c)
                sum += b(c, i) * d[c] * b(c, j);
              matrix(i, j) += jw * sum;
            }
      }
    return matrix;
  }



  void
  print_interface_matrix(std::ostream                     &out,
                         const dealii::FullMatrix<double> &matrix)
  {
    AssertThrow(matrix.m() == matrix.n() && matrix.m() % 6 == 0 &&
                  matrix.m() > 0,
                dealii::ExcMessage("print_interface_matrix: expected a square "
                                   "6 (p+1) x 6 (p+1) interface matrix"));
    const unsigned int n_nodes_per_side = matrix.m() / 6;
    const char         component[3]     = {'r', 'z', 't'};
    out << "# interface element matrix " << matrix.m() << " x " << matrix.n()
        << " (" << n_nodes_per_side << " node pairs; DoFs A0.r A0.z A0.t ... "
        << "B" << n_nodes_per_side - 1 << ".t, relative displacement = B - A)"
        << '\n';
    char buffer[32];
    for (unsigned int i = 0; i < matrix.m(); ++i)
      {
        const unsigned int node = i / 3;
        const std::string  label =
          std::string(1, node < n_nodes_per_side ? 'A' : 'B') +
          std::to_string(node % n_nodes_per_side) + "." + component[i % 3];
        std::snprintf(buffer, sizeof(buffer), "%-6s", label.c_str());
        out << buffer;
        for (unsigned int j = 0; j < matrix.n(); ++j)
          {
            std::snprintf(buffer, sizeof(buffer), " % .10e", matrix(i, j));
            out << buffer;
          }
        out << '\n';
      }
  }
} // namespace FourierSSI
