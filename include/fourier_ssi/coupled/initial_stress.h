/**
 * Initial (geostatic) effective stresses on the interfaces and in plastic
 * soil (doc/nonlinear-interfaces.md, section 4; doc/soil-plasticity.md,
 * section 3d): dry/effective soil of unit weight gamma' under a uniform
 * surcharge q at the ground surface, coefficient of earth pressure at rest
 * K0, no water table:
 *   sigma'_v = q + gamma' depth,  sigma'_h = K0 sigma'_v  (compression
 * positive), depth = ground surface elevation - z (Materials/Ground surface
 * elevation); no soil stress above the ground surface.
 *
 * How the initial state is in equilibrium: it is an internal state, set and
 * balanced by construction (the geostatic field with its own weight), not a
 * load. The harmonic systems solve for the displacement CHANGE from it, and
 * the initial stress enters only the interface and soil laws (the
 * interface's normal stress sets its Coulomb strength, the soil's mean stress
 * its Mohr-Coulomb strength; the out-of-balance load of the coupled
 * iteration is D d_p or D eps_p, which vanishes in the initial state).
 */
#ifndef fourier_ssi_initial_stress_h
#define fourier_ssi_initial_stress_h

#include <deal.II/base/tensor.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <fourier_ssi/input/initial_stress_parameters.h>
#include <fourier_ssi/interfaces/interface_law.h>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * The initial stress of the soil at a depth in the order and sign of
   * soil_law.h (r, z, theta, rz, ztheta, rtheta; tension positive):
   * (-sigma'_h, -sigma'_v, -sigma'_h, 0, 0, 0) [kPa].
   */
  StrainVector
  initial_soil_stress(const InitialStressParameters &initial_stress,
                      const double                   depth);

  /**
   * The initial traction (s, n, theta) [kPa] on an interface face with unit
   * tangent s and normal n (r, z components) at the given depth, in the
   * convention of interface_law.h (tension positive): t = -S n with
   * S = diag(sigma'_h, sigma'_v) in (r, z), so t_n = -(n_r^2 sigma'_h +
   * n_z^2 sigma'_v) and t_s = -(s_r n_r sigma'_h + s_z n_z sigma'_v)
   * (zero on horizontal and vertical faces); t_theta = 0 (no initial
   * circumferential shear in an axisymmetric geostatic state).
   */
  LocalVector
  initial_interface_traction(const InitialStressParameters &initial_stress,
                             const Tensor<1, 2>            &tangent,
                             const Tensor<1, 2>            &normal,
                             const double                   depth);
} // namespace FourierSSI

#endif
