/**
 * The 6x6 stiffness matrix of a rigid foundation at a reference point, the
 * spring that aeroelastic codes put at the mudline (OpenFAST SubDyn's SSI
 * file, doc/foundation-stiffness.md).
 *
 * Degrees of freedom in SubDyn's order (x, y, z, rx, ry, rz): translations
 * along the global axes (z up) and right-handed rotations about them. The
 * generalised forces are (F_x, F_y, F_z, M_x, M_y, M_z), moments about the
 * reference point, and F = K q.
 *
 * For a body of revolution about z with the reference point on its axis,
 * the harmonics give five independent terms (doc/theory.md, rigid-body
 * modes):
 *   K_zz = K_V (n = 0 symmetric), K_rzrz = K_T (n = 0 antisymmetric),
 *   K_xx = K_yy = K_H, K_ryry = K_rxrx = K_M, K_x,ry = K_MH (n = 1).
 * The y terms follow from the x terms by the rotation of pi/2 about z
 * (x -> y, y -> -x): a translation along x becomes one along y and a
 * rotation about +y one about -x, so K_y,rx = -K_x,ry and K_yy = K_xx,
 * K_rxrx = K_ryry. Every other term is zero by axisymmetry (the harmonics
 * do not couple: n = 0 with n = 1, symmetric with antisymmetric).
 */
#ifndef fourier_ssi_foundation_stiffness_h
#define fourier_ssi_foundation_stiffness_h

#include <array>
#include <iosfwd>
#include <limits>
#include <string>

namespace FourierSSI
{
  /** SubDyn's order of the six rigid-body degrees of freedom. */
  enum FoundationDof : unsigned int
  {
    dof_x  = 0,
    dof_y  = 1,
    dof_z  = 2,
    dof_rx = 3,
    dof_ry = 4,
    dof_rz = 5
  };

  using Matrix6 = std::array<std::array<double, 6>, 6>;
  using Point3  = std::array<double, 3>;

  /**
   * The five independent terms of an axisymmetric foundation at a point of
   * its axis, in SI units, each with its relative error bar (NaN: not
   * estimated).
   */
  struct AxisymmetricStiffnessTerms
  {
    double                  vertical   = 0.; // K_V = F_z / u_z [N/m]
    double                  horizontal = 0.; // K_H = F_x / u_x [N/m]
    double                  rocking    = 0.; // K_M = M_y / theta_y [N.m/rad]
    double                  coupling   = 0.; // K_MH = F_x / theta_y [N/rad]
    double                  torsional  = 0.; // K_T = M_z / theta_z [N.m/rad]
    static constexpr double not_estimated =
      std::numeric_limits<double>::quiet_NaN();
    double vertical_error   = not_estimated;
    double horizontal_error = not_estimated;
    double rocking_error    = not_estimated;
    double coupling_error   = not_estimated;
    double torsional_error  = not_estimated;
  };

  struct FoundationStiffness
  {
    /** The reference point (x, y, z) [m]. */
    Point3 reference_point = {{0., 0., 0.}};
    /** K [SI: N/m, N/rad, N.m/rad]. */
    Matrix6 stiffness{};
    /**
     * Absolute error bar of each term in its unit: NaN where not estimated,
     * 0 where the term is zero by axisymmetry (exact).
     */
    Matrix6 error_bar{};
  };

  /** The 6x6 matrix of the five terms at the point (0, 0, z) of the axis. */
  FoundationStiffness
  foundation_stiffness(const AxisymmetricStiffnessTerms &terms,
                       const double                      reference_elevation);

  /**
   * The same spring seen from another reference point: K_B = T^T K_A T with
   * T = [[I, -[d]x], [0, I]], d = A - B, since a rigid body moves point A
   * by u_A = u_B + theta x (A - B) = u_B - [d]x theta; the forces follow
   * by virtual work (F_B = F_A, M_B = M_A + d x F_A). Exact algebra.
   */
  Matrix6
  moved_reference_point(const Matrix6 &K_A,
                        const Point3  &point_A,
                        const Point3  &point_B);

  /** max |K_ij - K_ji| <= tolerance * max |K_ij|. */
  bool
  is_symmetric(const Matrix6 &K, const double tolerance);

  /** A Cholesky factorization of K exists (every pivot > 0). */
  bool
  is_positive_definite(const Matrix6 &K);

  /** "x", "y", "z", "rx", "ry", "rz". */
  std::string
  dof_name(const unsigned int dof);

  /** SI unit of K_ij: N/m, N/rad or N.m/rad. */
  std::string
  stiffness_unit(const unsigned int i, const unsigned int j);

  /**
   * CSV "term,value,unit,error_bar": the 21 terms of the upper triangle,
   * row by row, named K_<row>_<column> (K_x_ry: F_x per unit theta_y).
   */
  void
  write_stiffness_csv(const FoundationStiffness &K,
                      const std::string         &filename);

  /**
   * OpenFAST SubDyn's SSI input file (docs/source/user/subdyn/
   * input_files.rst, "SSI Input File"): comment lines starting with '!',
   * then one line "value label" per stiffness term, the 21 labels of the
   * upper triangle (Kxx, Kxy, Kyy, Kxz, ..., Ktztz; 't' a rotation) in
   * SubDyn's own order (column by column), SI units. All 21 are written: a
   * missing one would be read as zero (SubDyn's reader; its documentation
   * says infinitely stiff).
   */
  void
  write_subdyn_ssi(const FoundationStiffness &K, const std::string &filename);

  /** SubDyn's label of K_ij, i <= j: "K" + row + column, rotations 't'. */
  std::string
  subdyn_label(const unsigned int i, const unsigned int j);

  /** The matrix with units and error bars, for the log. */
  void
  print_stiffness(const FoundationStiffness &K, std::ostream &out);
} // namespace FourierSSI

#endif
