#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/foundation_stiffness.h>
#include <iomanip>
#include <ostream>

namespace FourierSSI
{
  namespace
  {
    /** K_ij = K_ji = value with its relative error bar. */
    void
    set_term(FoundationStiffness &K,
             const unsigned int   i,
             const unsigned int   j,
             const double         value,
             const double         relative_error)
    {
      K.stiffness[i][j] = K.stiffness[j][i] = value;
      K.error_bar[i][j] = K.error_bar[j][i] = std::abs(value) * relative_error;
    }

    /** [d]x: the matrix of theta -> d x theta. */
    std::array<std::array<double, 3>, 3>
    cross_product_matrix(const Point3 &d)
    {
      return {{{{0., -d[2], d[1]}}, {{d[2], 0., -d[0]}}, {{-d[1], d[0], 0.}}}};
    }
  } // namespace

  FoundationStiffness
  foundation_stiffness(const AxisymmetricStiffnessTerms &t,
                       const double                      reference_elevation)
  {
    FoundationStiffness K;
    K.reference_point = {{0., 0., reference_elevation}};
    // Every other term is zero by axisymmetry: exactly, error bar 0.
    set_term(K, dof_z, dof_z, t.vertical, t.vertical_error);
    set_term(K, dof_x, dof_x, t.horizontal, t.horizontal_error);
    set_term(K, dof_y, dof_y, t.horizontal, t.horizontal_error);
    set_term(K, dof_ry, dof_ry, t.rocking, t.rocking_error);
    set_term(K, dof_rx, dof_rx, t.rocking, t.rocking_error);
    set_term(K, dof_rz, dof_rz, t.torsional, t.torsional_error);
    // The pi/2 turn about z (header): K_y,rx = -K_x,ry.
    set_term(K, dof_x, dof_ry, t.coupling, t.coupling_error);
    set_term(K, dof_y, dof_rx, -t.coupling, t.coupling_error);
    return K;
  }

  Matrix6
  moved_reference_point(const Matrix6 &K_A,
                        const Point3  &point_A,
                        const Point3  &point_B)
  {
    const Point3 d = {{point_A[0] - point_B[0],
                       point_A[1] - point_B[1],
                       point_A[2] - point_B[2]}};
    const auto   D = cross_product_matrix(d);
    // T = [[I, -D], [0, I]]: q_A = T q_B.
    Matrix6 T{};
    for (unsigned int i = 0; i < 6; ++i)
      T[i][i] = 1.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        T[i][3 + j] = -D[i][j];
    Matrix6 KT{}, K_B{};
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int k = 0; k < 6; ++k)
          KT[i][j] += K_A[i][k] * T[k][j];
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int k = 0; k < 6; ++k)
          K_B[i][j] += T[k][i] * KT[k][j];
    return K_B;
  }

  bool
  is_symmetric(const Matrix6 &K, const double tolerance)
  {
    double largest = 0., asymmetry = 0.;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        {
          largest   = std::max(largest, std::abs(K[i][j]));
          asymmetry = std::max(asymmetry, std::abs(K[i][j] - K[j][i]));
        }
    return asymmetry <= tolerance * largest;
  }

  bool
  is_positive_definite(const Matrix6 &K)
  {
    // Cholesky K = L L^T, column by column.
    Matrix6 L{};
    for (unsigned int j = 0; j < 6; ++j)
      {
        double pivot = K[j][j];
        for (unsigned int k = 0; k < j; ++k)
          pivot -= L[j][k] * L[j][k];
        if (!(pivot > 0.))
          return false;
        L[j][j] = std::sqrt(pivot);
        for (unsigned int i = j + 1; i < 6; ++i)
          {
            double s = K[i][j];
            for (unsigned int k = 0; k < j; ++k)
              s -= L[i][k] * L[j][k];
            L[i][j] = s / L[j][j];
          }
      }
    return true;
  }

  std::string
  dof_name(const unsigned int dof)
  {
    static const std::array<std::string, 6> names = {
      {"x", "y", "z", "rx", "ry", "rz"}};
    return names.at(dof);
  }

  std::string
  stiffness_unit(const unsigned int i, const unsigned int j)
  {
    const unsigned int rotations = (i >= dof_rx) + (j >= dof_rx);
    return rotations == 0 ? "N/m" : rotations == 1 ? "N/rad" : "N.m/rad";
  }

  std::string
  subdyn_label(const unsigned int i, const unsigned int j)
  {
    static const std::array<std::string, 6> names = {
      {"x", "y", "z", "tx", "ty", "tz"}};
    return "K" + names.at(std::min(i, j)) + names.at(std::max(i, j));
  }

  void
  write_stiffness_csv(const FoundationStiffness &K, const std::string &filename)
  {
    // Complete or absent (AtomicFile), like every result file.
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    out << "term,value,unit,error_bar\n" << std::setprecision(10);
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = i; j < 6; ++j)
        {
          out << "K_" << dof_name(i) << "_" << dof_name(j) << ","
              << K.stiffness[i][j] << "," << stiffness_unit(i, j) << ",";
          // Empty where no estimate exists (one mesh): no nan in a result.
          if (std::isfinite(K.error_bar[i][j]))
            out << K.error_bar[i][j];
          out << "\n";
        }
    file.commit();
  }

  void
  write_subdyn_ssi(const FoundationStiffness &K, const std::string &filename)
  {
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    out << "! fourier-ssi: rigid foundation stiffness at (x, y, z) = ("
        << K.reference_point[0] << ", " << K.reference_point[1] << ", "
        << K.reference_point[2] << ") m\n"
        << "! SubDyn SSI file: value and label per line, SI units (N/m, "
           "N/rad, N.m/rad)\n"
        << std::scientific << std::setprecision(9);
    // SubDyn's order: the upper triangle column by column.
    for (unsigned int j = 0; j < 6; ++j)
      for (unsigned int i = 0; i <= j; ++i)
        out << std::setw(17) << K.stiffness[i][j] << "   " << subdyn_label(i, j)
            << "\n";
    file.commit();
  }

  void
  print_stiffness(const FoundationStiffness &K, std::ostream &out)
  {
    out << "foundation stiffness matrix at (x, y, z) = ("
        << K.reference_point[0] << ", " << K.reference_point[1] << ", "
        << K.reference_point[2]
        << ") m, DoFs (x, y, z, rx, ry, rz) as in OpenFAST SubDyn; "
           "units N/m (translation-translation), N/rad (translation-"
           "rotation), N.m/rad (rotation-rotation):";
    const std::ios::fmtflags flags = out.flags();
    out << std::scientific << std::setprecision(5);
    for (unsigned int i = 0; i < 6; ++i)
      {
        out << "\n    " << std::setw(2) << dof_name(i);
        for (unsigned int j = 0; j < 6; ++j)
          out << std::setw(14) << K.stiffness[i][j];
      }
    out << "\n  error bars (absolute, same units; 0: zero by axisymmetry):";
    out << std::setprecision(1);
    for (const auto &[i, j] :
         std::array<std::pair<unsigned int, unsigned int>, 5>{
           {{dof_z, dof_z},
            {dof_x, dof_x},
            {dof_ry, dof_ry},
            {dof_x, dof_ry},
            {dof_rz, dof_rz}}})
      {
        out << " K_" << dof_name(i) << "_" << dof_name(j);
        if (std::isfinite(K.error_bar[i][j]))
          out << " \u00b1 " << K.error_bar[i][j] << " " << stiffness_unit(i, j)
              << ";";
        else
          out << " not estimated (one mesh: set Refinement cycles >= 2 or "
                 "Target accuracy);";
      }
    out.flags(flags);
    out << std::endl;
  }
} // namespace FourierSSI
