// The 6x6 foundation stiffness matrix (Rigid foundation/Stiffness matrix,
// doc/foundation-stiffness.md), read back from the files a run writes.
//
// 1. Closed forms: prm/surface-disc-stiffness.prm, a rigid disc bonded to
//    the surface of a half-space (a = 1 m, G = 1000 kPa, nu = 0.49, domain
//    1e4 a), against K_T = 16 G a^3 / 3 (Reissner & Sagoci 1944, exact for
//    any nu), K_V = 4 G a / (1 - nu), K_M = 8 G a^3 / (3 (1 - nu))
//    (smooth disc, Poulos & Davis 1974; the bonded disc differs by
//    O(1 - 2 nu), bounded below with Spence's bonded K_V) and K_H =
//    32 (1 - nu) G a / (7 - 8 nu) (Gazetas 1991, the reference the project
//    prints): each within the error bar the run computes, plus for K_V the
//    stated allowances.
// 2. The SubDyn SSI file of that run, line by line against the documented
//    layout (OpenFAST docs/source/user/subdyn/input_files.rst, "SSI Input
//    File"): comment lines first, then "value label" lines, the 21 labels
//    of the upper triangle once each, SI values equal to the CSV's.
// 3. Symmetric (I_MH from the H and the M solves agree) and positive
//    definite (Cholesky).
// 4. x and y give the same terms: the n = 1 antisymmetric family, loaded by
//    H_y and by M_x in two runs, inverted, against K_yy, K_y,rx, K_rxrx of
//    the matrix (same mesh: to round-off; this fixes the sign of K_y,rx).
// 5. The reference-point transfer: the matrix solved about z = -1 m against
//    the one about z = 0 moved by moved_reference_point() and by the hand
//    formulas K_x,ry(B) = K_x,ry(A) + h K_xx, K_ry,ry(B) = K_ry,ry(A) +
//    2 h K_x,ry(A) + h^2 K_xx (h = z_A - z_B): exact algebra on the same
//    FE fields, so to round-off.
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <filesystem>
#include <fourier_ssi/postprocess/foundation_stiffness.h>
#include <fstream>
#include <map>
#include <sstream>

using namespace FourierSSI;

namespace
{
  struct Term
  {
    double      value = 0., error_bar = 0.;
    std::string unit;
  };
  using Terms = std::map<std::string, Term>;

  /** Run the scene writing its files to `directory`; its results table. */
  ResultsTable
  run_writing(const std::string &prm_text, const std::string &directory)
  {
    std::filesystem::remove_all(directory);
    const AllParameters parameters = test_support::parameters_from(
      prm_text + "subsection Output\n set Directory = " + directory +
      "\n set Write vtu = false\nend\n");
    Simulator simulator(parameters);
    return simulator.run(std::cout, /*write_files=*/true);
  }

  /** foundation-stiffness.csv: term -> (value, unit, error bar). */
  Terms
  read_csv(const std::string &directory)
  {
    std::ifstream in(directory + "/foundation-stiffness.csv");
    std::string   line;
    std::getline(in, line);
    check::that("CSV header term,value,unit,error_bar",
                line == "term,value,unit,error_bar");
    Terms terms;
    while (std::getline(in, line))
      {
        std::stringstream fields(line);
        std::string       name, value, unit, error;
        std::getline(fields, name, ',');
        std::getline(fields, value, ',');
        std::getline(fields, unit, ',');
        std::getline(fields, error, ',');
        // An empty error bar: not estimated (one mesh).
        terms[name] = {std::stod(value),
                       error.empty() ? std::nan("") : std::stod(error),
                       unit};
      }
    check::equal("CSV terms (upper triangle)", terms.size(), 21);
    return terms;
  }

  std::string
  term_name(const unsigned int i, const unsigned int j)
  {
    return "K_" + dof_name(std::min(i, j)) + "_" + dof_name(std::max(i, j));
  }

  Matrix6
  matrix_of(const Terms &terms)
  {
    Matrix6 K{};
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        K[i][j] = terms.at(term_name(i, j)).value;
    return K;
  }

  double
  largest_entry(const Matrix6 &K)
  {
    double largest = 0.;
    for (const auto &row : K)
      for (const double k : row)
        largest = std::max(largest, std::abs(k));
    return largest;
  }

  /** The value of a row on the last cycle it has. */
  double
  last(const ResultsTable &results,
       const std::string  &quantity,
       const Harmonic     &harmonic)
  {
    double value = std::nan("");
    for (const ResultRow &row : results.rows())
      if (row.quantity == quantity && row.harmonic.n == harmonic.n &&
          row.harmonic.family == harmonic.family)
        value = row.value;
    return value;
  }

  /** |K - exact| <= error bar + allowance * exact, printed. */
  void
  within_error_bar(const std::string &what,
                   const Term        &term,
                   const double       exact,
                   const double       allowance)
  {
    std::cout << "  " << what << ": error bar " << term.error_bar / exact
              << " (rel), allowance " << allowance << std::endl;
    check::that(what + ": the run estimates its error", term.error_bar > 0.);
    check::relative(what,
                    term.value,
                    exact,
                    term.error_bar / std::abs(exact) + allowance);
  }

  void
  check_closed_forms(const Terms &t)
  {
    const double G = 1e6 /* Pa */, a = 1., nu = 0.49;
    // The bonded disc's K_V (Spence 1968) is above the smooth one by
    // ln(3 - 4 nu) (1 - nu) / (1 - 2 nu) - 1 = 1.3e-4 at nu = 0.49; the
    // fixed boundary at L = 1e4 a stiffens it by about 1.3 a / L
    // (tests/harmonic/surface_footing.cc).
    const double bonded_excess =
      std::log(3. - 4. * nu) * (1. - nu) / (1. - 2. * nu) - 1.;
    within_error_bar("K_z_z vs 4 G a / (1 - nu)",
                     t.at("K_z_z"),
                     4. * G * a / (1. - nu),
                     bonded_excess + 1.3e-4);
    within_error_bar("K_rz_rz vs 16 G a^3 / 3 (exact)",
                     t.at("K_rz_rz"),
                     16. * G * a * a * a / 3.,
                     0.);
    within_error_bar("K_ry_ry vs 8 G a^3 / (3 (1 - nu))",
                     t.at("K_ry_ry"),
                     8. * G * a * a * a / (3. * (1. - nu)),
                     0.);
    within_error_bar("K_x_x vs 32 (1 - nu) G a / (7 - 8 nu)",
                     t.at("K_x_x"),
                     32. * (1. - nu) * G * a / (7. - 8. * nu),
                     0.);
    check::that("units N/m, N/rad, N.m/rad",
                t.at("K_z_z").unit == "N/m" && t.at("K_x_ry").unit == "N/rad" &&
                  t.at("K_rz_rz").unit == "N.m/rad");
    // The coupling of a surface disc vanishes at nu = 1/2: small and of
    // the sign of an embedded foundation's (doc/scenes.md).
    const double coupling_ratio =
      t.at("K_x_ry").value /
      std::sqrt(t.at("K_x_x").value * t.at("K_ry_ry").value);
    check::in_range("K_x,ry / sqrt(K_xx K_ryry)", coupling_ratio, -0.02, 0.);
  }

  /** The SubDyn SSI file, line by line. */
  void
  check_subdyn_file(const std::string &directory, const Terms &terms)
  {
    // The documented labels, in the order SubDyn's reader lists them (the
    // upper triangle column by column; 't' is a rotation).
    const std::vector<std::string> labels = {"Kxx",  "Kxy",   "Kyy",   "Kxz",
                                             "Kyz",  "Kzz",   "Kxtx",  "Kytx",
                                             "Kztx", "Ktxtx", "Kxty",  "Kyty",
                                             "Kzty", "Ktxty", "Ktyty", "Kxtz",
                                             "Kytz", "Kztz",  "Ktxtz", "Ktytz",
                                             "Ktztz"};
    const std::map<std::string, std::string> axis = {{"x", "x"},
                                                     {"y", "y"},
                                                     {"z", "z"},
                                                     {"tx", "rx"},
                                                     {"ty", "ry"},
                                                     {"tz", "rz"}};
    std::ifstream in(directory + "/foundation-stiffness-subdyn.txt");
    std::string   line;
    unsigned int  n_comments = 0, n_values = 0;
    bool          values_started = false, ok = true;
    while (std::getline(in, line))
      {
        if (!line.empty() && line[0] == '!')
          {
            // Comments only before the values (SubDyn skips them anywhere;
            // the documented example has them on top).
            ok &= !values_started;
            ++n_comments;
            continue;
          }
        values_started = true;
        std::stringstream words(line);
        std::string       value, label, extra;
        words >> value >> label;
        const bool two_words =
          !value.empty() && !label.empty() && !(words >> extra);
        ok &=
          two_words && n_values < labels.size() && label == labels[n_values];
        if (!ok)
          {
            std::cout << "  bad line: '" << line << "'" << std::endl;
            break;
          }
        // Kxty -> rows x, columns ry of the CSV.
        const std::string rest = label.substr(1);
        const std::string row =
          rest[0] == 't' ? rest.substr(0, 2) : rest.substr(0, 1);
        const std::string column = rest.substr(row.size());
        const Term       &term =
          terms.at("K_" + axis.at(row) + "_" + axis.at(column));
        check::relative("SubDyn " + label + " = CSV value",
                        std::stod(value),
                        term.value,
                        1e-9,
                        1.);
        ++n_values;
      }
    check::that("SubDyn file: comment lines on top, then value-label lines "
                "in the documented order",
                ok);
    check::that("SubDyn file: a comment header", n_comments >= 1);
    check::equal("SubDyn file: stiffness lines", n_values, labels.size());
  }

  /** The small fixed-mesh variant of the scene (same-mesh comparisons). */
  std::string
  fixed_mesh_scene(const std::string &foundation_entries)
  {
    return test_support::bundled_prm("prm/surface-disc-stiffness.prm") +
           "subsection Discretization\n set Target accuracy =\n"
           " set Refinement cycles = 1\nend\n"
           "subsection Mesh\n set R breakpoints = 0, 1, 100\n"
           " set R cells = 4, 12\n set Z breakpoints = -100, 0\n"
           " set Z cells = 12\nend\n"
           "subsection Rigid foundation\n" +
           foundation_entries + "end\n";
  }

  /** K_yy, K_y,rx, K_rx,rx from the unit H_y and unit M_x runs. */
  std::array<double, 3>
  y_family_stiffness()
  {
    const Harmonic y_family{1, Family::antisymmetric};
    // The antisymmetric family's (U_h, Theta) are u_y and the rotation
    // about -x (rigid_foundation.h): theta_x = -Theta.
    std::array<std::array<double, 2>, 2> flexibility;
    const std::array<std::string, 2>     loads = {
          {" set Horizontal force y = 1\n", " set Moment x = 1\n"}};
    for (unsigned int load = 0; load < 2; ++load)
      {
        const ResultsTable r = test_support::run(
          fixed_mesh_scene(" set Stiffness matrix = false\n" + loads[load]));
        flexibility[0][load] =
          last(r, "foundation_horizontal_displacement", y_family);
        flexibility[1][load] = -last(r, "foundation_rotation", y_family);
      }
    const double det = flexibility[0][0] * flexibility[1][1] -
                       flexibility[0][1] * flexibility[1][0];
    // kN -> N.
    return {{1e3 * flexibility[1][1] / det,
             -1e3 * flexibility[0][1] / det,
             1e3 * flexibility[0][0] / det}};
  }

  void
  check_x_equals_y(const Terms &t)
  {
    const auto y = y_family_stiffness();
    // The y terms of the file against the y family's own solves.
    check::relative("K_y_y (H_y, M_x runs) = CSV K_y_y",
                    y[0],
                    t.at("K_y_y").value,
                    1e-8);
    check::relative("K_y_rx (H_y, M_x runs) = CSV K_y_rx",
                    y[1],
                    t.at("K_y_rx").value,
                    1e-8);
    check::relative("K_rx_rx (H_y, M_x runs) = CSV K_rx_rx",
                    y[2],
                    t.at("K_rx_rx").value,
                    1e-8);
    check::relative("K_y_y = K_x_x",
                    t.at("K_y_y").value,
                    t.at("K_x_x").value,
                    1e-12);
    check::relative("K_rx_rx = K_ry_ry",
                    t.at("K_rx_rx").value,
                    t.at("K_ry_ry").value,
                    1e-12);
    check::relative("CSV K_y_rx = -K_x_ry",
                    t.at("K_y_rx").value,
                    -t.at("K_x_ry").value,
                    1e-12);
  }

  void
  check_transfer(const Terms &at_surface)
  {
    const double h = 1.; // z_A - z_B: B one metre below the surface
    run_writing(fixed_mesh_scene(" set Reference elevation = -1\n"), "moved");
    const Matrix6 K_A = matrix_of(at_surface),
                  K_B = matrix_of(read_csv("moved"));
    const Matrix6 moved =
      moved_reference_point(K_A, {{0., 0., 0.}}, {{0., 0., -h}});
    const double scale              = largest_entry(K_A);
    double       largest_difference = 0.;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        largest_difference =
          std::max(largest_difference, std::abs(moved[i][j] - K_B[i][j]));
    check::small("max |T^T K(z = 0) T - K(z = -1)| / max |K|",
                 largest_difference / scale,
                 1e-8);
    check::relative("K_x_ry(B) = K_x_ry(A) + h K_xx",
                    K_B[dof_x][dof_ry],
                    K_A[dof_x][dof_ry] + h * K_A[dof_x][dof_x],
                    1e-8);
    check::relative("K_ry_ry(B) = K_ry_ry(A) + 2 h K_x_ry(A) + h^2 K_xx",
                    K_B[dof_ry][dof_ry],
                    K_A[dof_ry][dof_ry] + 2. * h * K_A[dof_x][dof_ry] +
                      h * h * K_A[dof_x][dof_x],
                    1e-8);
    check::relative("K_xx, K_zz, K_rzrz do not depend on the point",
                    K_B[dof_x][dof_x] + K_B[dof_z][dof_z] + K_B[dof_rz][dof_rz],
                    K_A[dof_x][dof_x] + K_A[dof_z][dof_z] + K_A[dof_rz][dof_rz],
                    1e-8);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   lateral{1, Family::symmetric};

  // 1-3: the bundled scene as shipped.
  const ResultsTable results =
    run_writing(test_support::bundled_prm("prm/surface-disc-stiffness.prm"),
                "disc");
  const Terms disc = read_csv("disc");
  check_closed_forms(disc);
  check_subdyn_file("disc", disc);
  check::relative("symmetric: I_MH from the H solve = from the M solve",
                  last(results, "I_MH_from_H", lateral),
                  last(results, "I_MH_from_M", lateral),
                  1e-8);
  check::that("positive definite (Cholesky)",
              is_positive_definite(matrix_of(disc)));

  // 4-5: same-mesh comparisons on a small fixed mesh.
  run_writing(fixed_mesh_scene(""), "fixed");
  const Terms fixed = read_csv("fixed");
  // One mesh has no error estimate: the bars are empty fields, never nan.
  {
    std::ifstream      in("fixed/foundation-stiffness.csv");
    std::ostringstream text;
    text << in.rdbuf();
    check::that("one mesh: no nan or inf in foundation-stiffness.csv",
                text.str().find("nan") == std::string::npos &&
                  text.str().find("inf") == std::string::npos);
    check::that("one mesh: K_z_z's error bar is empty (not estimated)",
                std::isnan(fixed.at("K_z_z").error_bar));
  }
  check_x_equals_y(fixed);
  check_transfer(fixed);
  return check::summary();
}
