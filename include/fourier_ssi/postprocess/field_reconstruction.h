/**
 * The 3D answer as the sum of the harmonics (thesis eq. 3.1):
 *   u_r(r, z, t) = sum U_n(r, z) c_n(t),  u_z = sum V_n c_n(t),
 *   u_t = sum W_n s_n(t),
 * with (c_n, s_n) = (cos n t, sin n t) for the symmetric family and
 * (sin n t, cos n t) for the antisymmetric one; stresses likewise (sigma_r,
 * sigma_z, sigma_t, tau_rz with c_n; tau_zt, tau_rt with s_n). Evaluated at
 * any (r, z, theta): along lines (CSV) and on the mesh revolved about the
 * axis (VTU for ParaView).
 */
#ifndef fourier_ssi_field_reconstruction_h
#define fourier_ssi_field_reconstruction_h

#include <deal.II/base/point.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <memory>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** 3D displacement and stress at one point, cylindrical components. */
  struct FieldValues
  {
    std::array<double, 3> displacement = {{0., 0., 0.}}; // u_r, u_z, u_theta
    StrainVector stress = {{0., 0., 0., 0., 0., 0.}};    // r, z, t, rz, zt, rt
  };

  class FieldReconstruction
  {
  public:
    /** Take one solved harmonic (kept alive for later evaluation). */
    void
    add(std::shared_ptr<const HarmonicProblem> problem);

    bool
    empty() const
    {
      return problems.empty();
    }

    /** The solved harmonics, in the order they were added. */
    const std::vector<std::shared_ptr<const HarmonicProblem>> &
    get_problems() const
    {
      return problems;
    }

    /** The amplitudes (no trig factor) of one harmonic at a point. */
    static FieldValues
    amplitudes(const HarmonicProblem &problem, const Point<2> &point);

    /** Sum over the harmonics at (r, z) and angle theta [rad]. */
    FieldValues
    evaluate(const Point<2> &point, const double theta) const;

    /**
     * CSV along straight lines in the (r, z) plane at the given angles:
     * line, point, r, z, theta_deg, x, y, u_r, u_z, u_theta, u_x, u_y,
     * sigma_r, sigma_z, sigma_theta, tau_rz, tau_ztheta, tau_rtheta.
     */
    void
    write_lines_csv(const std::vector<OutputLine> &lines,
                    const std::vector<double>     &theta_degrees,
                    const std::string             &filename) const;

    /**
     * The mesh revolved about the z axis in `divisions` sectors, one
     * hexahedron per cell and sector (wedges on the axis), with the
     * displacement at the vertices (Cartesian vector and cylindrical
     * components).
     */
    void
    write_revolved_vtu(const unsigned int divisions,
                       const std::string &filename) const;

  private:
    /**
     * (u_r, u_z, u_theta) at each vertex of the revolved mesh, index
     * k * n_vertices + i for vertex i at theta_k = 2 pi k / divisions.
     */
    std::vector<std::array<double, 3>>
    revolved_displacement(const unsigned int divisions) const;

    std::vector<std::shared_ptr<const HarmonicProblem>> problems;
  };
} // namespace FourierSSI

#endif
