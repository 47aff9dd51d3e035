/**
 * The Fourier harmonic (n, family) of the semi-analytical method (Wilson
 * 1965; thesis section 3.3, eqs 3.1-3.2).
 *
 * Amplitudes (U, V, W) = (radial, axial, circumferential) of harmonic n:
 *   symmetric family:      u = U cos(n t), v = V cos(n t), w = W sin(n t)
 *   antisymmetric family:  u = U sin(n t), v = V sin(n t), w = W cos(n t)
 * Coordinates: the 2D mesh lives in the (r, z) half plane, point(0) = r >= 0,
 * point(1) = z pointing up; theta is measured counter-clockwise seen from +z.
 */
#ifndef fourier_ssi_harmonic_h
#define fourier_ssi_harmonic_h

#include <string>

namespace FourierSSI
{
  enum class Family
  {
    symmetric,
    antisymmetric
  };

  /** "symmetric" or "antisymmetric". */
  std::string
  to_string(const Family family);

  /** Parse "symmetric"/"sym" or "antisymmetric"/"anti"; throws otherwise. */
  Family
  family_from_string(const std::string &name);

  /**
   * +1 for the symmetric family, -1 for the antisymmetric one. The strains of
   * the antisymmetric family are those of the symmetric one with n replaced by
   * -n (equivalently W by -W), see doc/theory.md.
   */
  inline double
  family_sign(const Family family)
  {
    return family == Family::symmetric ? 1. : -1.;
  }

  struct Harmonic
  {
    unsigned int n      = 0;
    Family       family = Family::symmetric;

    /**
     * Integral over theta in [0, 2 pi) of the squared trigonometric factor
     * carried by the in-plane quantities (U, V and the strains e_r, e_z,
     * e_theta, g_rz): pi for n >= 1; for n = 0 it is 2 pi in the symmetric
     * family (cos 0 = 1) and 0 in the antisymmetric one (sin 0 = 0).
     */
    double
    in_plane_weight() const;

    /**
     * The same for the circumferential quantities (W and the strains g_ztheta,
     * g_rtheta): pi for n >= 1; for n = 0 it is 0 in the symmetric family and
     * 2 pi in the antisymmetric one (pure torsion).
     */
    double
    out_of_plane_weight() const;

    /** "n=1 symmetric" */
    std::string
    name() const;
  };
} // namespace FourierSSI

#endif
