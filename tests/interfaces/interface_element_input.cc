// Interface element: the exact triple-product tables (properties and an
// independent numerical check), rejection of bad input with a clear message,
// and the matrix printer used by the --interface-matrix sub-command.

#include <check.h>
#include <cmath>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace FourierSSI;

namespace
{
  std::vector<dealii::Point<2>>
  straight_face(const unsigned int degree)
  {
    std::vector<dealii::Point<2>> nodes(degree + 1);
    for (unsigned int k = 0; k <= degree; ++k)
      nodes[k] = dealii::Point<2>(1. + 0.3 * k / degree, 2. - 0.9 * k / degree);
    return nodes;
  }

  /** Expect an exception; print its first message line. */
  void
  expect_throw(const std::string &what, const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        std::string text  = message.str();
        const auto  first = text.find_first_not_of(" \n");
        text              = text.substr(first == std::string::npos ? 0 : first);
        std::cout << "  (message) " << text.substr(0, text.find('\n'))
                  << std::endl;
        check::that(what + " is rejected", true);
        return;
      }
    check::that(what + " is rejected", false);
  }
} // namespace

int
main()
{
  // --- tables
  for (const unsigned int degree : {2u, 4u})
    {
      const TripleProductTable &table = lagrange_triple_product_table(degree);
      const unsigned int        m     = table.n_nodes();
      check::that("degree " + std::to_string(degree) + " table has " +
                    std::to_string(m * m * m) + " entries",
                  table.degree == degree && table.entries.size() == m * m * m);

      // Exact structural properties (integer comparisons): symmetry under
      // permutations of (i, j, k) and under the mirror k -> p - k.
      bool symmetric = true;
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int k = 0; k < m; ++k)
            {
              const ExactRational &a = table(i, j, k);
              for (const ExactRational &b :
                   {table(j, i, k),
                    table(k, j, i),
                    table(i, k, j),
                    table(degree - i, degree - j, degree - k)})
                symmetric = symmetric && a.numerator == b.numerator &&
                            a.denominator == b.denominator;
              symmetric = symmetric && a.denominator > 0;
            }
      check::that("degree " + std::to_string(degree) +
                    " table symmetric in (i, j, k) and under the mirror",
                  symmetric);

      // Independent numerical values: Gauss with 2 p points (exact for
      // degree 4p - 1 >= 3p) and deal.II's Lagrange polynomials. Tolerance
      // 1e-15 absolute: entries are O(0.1-0.5), sums of a few products.
      std::vector<dealii::Point<1>> support(m);
      for (unsigned int k = 0; k < m; ++k)
        support[k][0] = static_cast<double>(k) / degree;
      const auto basis =
        dealii::Polynomials::generate_complete_Lagrange_basis(support);
      const dealii::QGauss<1> gauss(2 * degree);
      double                  max_error = 0., total = 0.;
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int k = 0; k < m; ++k)
            {
              double value = 0.;
              for (unsigned int q = 0; q < gauss.size(); ++q)
                {
                  const double x = gauss.point(q)[0];
                  value += gauss.weight(q) * basis[i].value(x) *
                           basis[j].value(x) * basis[k].value(x);
                }
              max_error =
                std::max(max_error, std::abs(value - table(i, j, k).value()));
              total += table(i, j, k).value();
            }
      check::small("degree " + std::to_string(degree) +
                     ": max |T_exact - T_Gauss|",
                   max_error,
                   1e-15);
      // Partition of unity: the sum of all T_ijk is int_0^1 1 = 1 (double
      // sum of (p+1)^3 terms: tolerance 1e-14).
      check::relative("degree " + std::to_string(degree) + ": sum of T_ijk",
                      total,
                      1.,
                      1e-14);
    }
  // Two values quoted in doc/interface-elements.md.
  check::that("T_000 (p=2) = 13/140",
              lagrange_triple_product_table(2)(0, 0, 0).numerator == 13 &&
                lagrange_triple_product_table(2)(0, 0, 0).denominator == 140);
  check::that("T_222 (p=4) = 368/2145",
              lagrange_triple_product_table(4)(2, 2, 2).numerator == 368 &&
                lagrange_triple_product_table(4)(2, 2, 2).denominator == 2145);

  // --- bad input
  const InterfaceStiffness stiffness{1e5, 1e4};
  const Harmonic           harmonic{1, Family::symmetric};
  expect_throw("degree 3", [&]() {
    interface_matrix(3, straight_face(3), stiffness, harmonic);
  });
  expect_throw("table of degree 1", []() { lagrange_triple_product_table(1); });
  expect_throw("4 nodes for degree 2", [&]() {
    interface_matrix(2, straight_face(3), stiffness, harmonic);
  });
  expect_throw("3 nodes for degree 4", [&]() {
    interface_matrix(4, straight_face(2), stiffness, harmonic);
  });
  {
    std::vector<dealii::Point<2>> curved = straight_face(2);
    curved[1][0] += 1e-4; // the face is ~0.95 long: 1e-4 relative
    expect_throw("curved face (mid node off by 1e-4 l)",
                 [&]() { interface_matrix(2, curved, stiffness, harmonic); });
    std::vector<dealii::Point<2>> uneven = straight_face(4);
    uneven[1] = uneven[0] + 0.3 * (uneven[4] - uneven[0]); // on the line
    expect_throw("unevenly spaced nodes on a straight face",
                 [&]() { interface_matrix(4, uneven, stiffness, harmonic); });
    std::vector<dealii::Point<2>> almost = straight_face(4);
    almost[2][1] += 1e-11; // within the 1e-8 relative layout tolerance
    bool accepted = true;
    try
      {
        interface_matrix(4, almost, stiffness, harmonic);
      }
    catch (const dealii::ExceptionBase &)
      {
        accepted = false;
      }
    check::that("node off by 1e-11 l is accepted (tolerance 1e-8 l)", accepted);
  }
  expect_throw("zero-length face", [&]() {
    interface_matrix(2,
                     std::vector<dealii::Point<2>>(3, dealii::Point<2>(1., 1.)),
                     stiffness,
                     harmonic);
  });
  expect_throw("negative normal stiffness", [&]() {
    interface_matrix(2, straight_face(2), {-1., 1e4}, harmonic);
  });
  expect_throw("negative shear stiffness", [&]() {
    interface_matrix(4, straight_face(4), {1e5, -1e-3}, harmonic);
  });
  expect_throw("NaN stiffness", [&]() {
    interface_matrix(2,
                     straight_face(2),
                     {std::numeric_limits<double>::quiet_NaN(), 1.},
                     harmonic);
  });
  {
    std::vector<dealii::Point<2>> crossing(3);
    for (unsigned int k = 0; k < 3; ++k)
      crossing[k] = dealii::Point<2>(-0.5 + 0.5 * k, 0.);
    expect_throw("face with r < 0",
                 [&]() { interface_matrix(2, crossing, stiffness, harmonic); });
  }
  expect_throw("empty quadrature", [&]() {
    interface_matrix_by_quadrature(
      2, straight_face(2), stiffness, harmonic, dealii::Quadrature<1>());
  });

  // --- printer
  {
    std::ostringstream out;
    print_interface_matrix(
      out, interface_matrix(2, straight_face(2), stiffness, harmonic));
    std::istringstream       in(out.str());
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    std::cout << "  (printed) " << lines.front() << std::endl
              << "  (printed) " << lines[1].substr(0, 60) << " ..."
              << std::endl;
    check::that("printer: header + 18 rows",
                lines.size() == 19 && lines.front()[0] == '#');
    check::that("printer: first row labelled A0.r, last B2.t",
                lines[1].rfind("A0.r", 0) == 0 &&
                  lines[18].rfind("B2.t", 0) == 0);
    std::istringstream row(lines[1].substr(6));
    unsigned int       n_values = 0;
    for (double v; row >> v;)
      ++n_values;
    check::that("printer: 18 values per row", n_values == 18);
    expect_throw("printing a non-interface matrix", []() {
      std::ostringstream sink;
      print_interface_matrix(sink, dealii::FullMatrix<double>(5, 5));
    });
  }

  return check::summary();
}
