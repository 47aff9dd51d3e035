/**
 * The constitutive law of a zero-thickness interface: the closed-form return
 * mapping of the nonlinear Mohr-Coulomb law with a tension cut-off
 * (doc/nonlinear-interfaces.md, section 2; thesis ch. 2.4: adhesion,
 * glissement, decollement). The laws' data and .prm syntax are
 * InterfaceLaw and InterfaceParameters (input/interface_parameters.h).
 *
 * Sign convention, used everywhere in fourier-ssi: local components
 * (s, n, theta) of the interface element (doc/interfaces-usage.md, section
 * 4); the relative displacement is face B minus face A, positive d_n is an
 * opening; the traction t = (t_s, t_n, t_theta) = sigma n is the stress
 * vector on the face of side A (outward normal n), i.e. the force per unit
 * area that side B exerts on side A, so t_n > 0 is a TENSION and compression
 * is negative (the thesis writes sigma_n = -t_n, compression positive).
 */
#ifndef fourier_ssi_interface_law_h
#define fourier_ssi_interface_law_h

#include <array>
#include <cmath>
#include <fourier_ssi/input/interface_parameters.h>
#include <limits>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * C of the compliance error of a penalty interface: against rigid
   * contact the load-displacement answer is off by about C G / (kn r0)
   * (r0 the foundation's size), measured C = 1.2 on the disc in a ring
   * (doc/nonlinear-interfaces.md section 5e).
   */
  constexpr double compliance_error_coefficient = 1.2;

  /**
   * kn=auto, ks=auto: springs of this times G / l. With the face length l
   * no larger than the foundation, the compliance error is below
   * compliance_error_coefficient / 1e3 = 1.2e-3; and K then holds the
   * law's springs under Newton too (interface_iteration_stiffness).
   */
  constexpr double automatic_interface_stiffness = 1e3;

  /** Local interface vector (s, n, theta). */
  using LocalVector = std::array<double, 3>;

  /** What the return mapping found at one point. */
  enum class ContactState
  {
    stick,
    slip,
    open
  };

  /**
   * A 3 x 3 matrix on local (s, n, theta) vectors, row-major: entry
   * (a, b) at a * 3 + b.
   */
  using LocalTangent = std::array<double, 9>;

  /**
   * Result of one return mapping: traction, plastic part, state and the
   * consistent tangent.
   */
  struct ReturnMappingResult
  {
    /** Total traction t = t0 + D (d - d_p) [kPa], tension positive. */
    LocalVector traction = {{0., 0., 0.}};
    /** Plastic relative displacement d_p [m] (slip, and the gap if open). */
    LocalVector  plastic = {{0., 0., 0.}};
    ContactState state   = ContactState::stick;
    /**
     * Consistent tangent D_t = dt/dd of this return at fixed committed
     * plastic part (row-major; doc/nonlinear-interfaces.md section 2,
     * derived in doc/derivations/interface_consistent_tangent.py): D where
     * it sticks, 0 where it is open, the closed form of the radial return
     * where it slips. On the boundary of two regimes it is the tangent of
     * the regime the state label names (one-sided).
     */
    LocalTangent tangent = {{0., 0., 0., 0., 0., 0., 0., 0., 0.}};
  };

  /**
   * Closed-form return mapping of the Mohr-Coulomb interface with a tension
   * cut-off (doc/nonlinear-interfaces.md, section 2). With the trial traction
   *   t_tr = t0 + D (d - d_p,old),   D = diag(ks, kn, ks),
   *   tau_tr = sqrt(t_s,tr^2 + t_theta,tr^2),
   *   f(t) = tau + t_n tan(phi) - c,   g(t) = tau + t_n tan(psi),
   * the three cases are
   *   open  (t_n,tr > sigma_t): t = 0, d_p = d + D^-1 t0 (decollement, thesis
   *          2.4: the gap carries neither normal nor shear force);
   *   stick (f(t_tr) <= 0):     t = t_tr;
   *   slip  (f(t_tr) > 0):      dl = f(t_tr) / (ks + kn tan(phi) tan(psi)),
   *          tau = tau_tr - ks dl (radial return in the (s, theta) plane),
   *          t_n = t_n,tr - kn tan(psi) dl (dilation: more compression),
   *          which lands exactly on f = 0.
   * The consistent tangent of each case (ReturnMappingResult::tangent), with
   * m the unit trial shear direction in (s, theta), H = ks + kn tan(phi)
   * tan(psi) and rho = tau / tau_tr:
   *   open: 0;  stick: D;
   *   slip: dt_a/dd_b = ks rho (delta_ab - m_a m_b)
   *                     + ks kn tan(phi) tan(psi) / H m_a m_b  (a, b = s,
   * theta), dt_a/dd_n = -ks kn tan(phi) / H m_a, dt_n/dd_b = -ks kn tan(psi) /
   * H m_b,   dt_n/dd_n = ks kn / H.
   */
  class MohrCoulombInterface
  {
  public:
    explicit MohrCoulombInterface(const InterfaceLaw &law);

    /** The law with the springs kn, ks given (resolved per face). */
    MohrCoulombInterface(const InterfaceLaw &law,
                         const double        kn,
                         const double        ks);

    ReturnMappingResult
    return_map(const LocalVector &relative_displacement,
               const LocalVector &initial_traction,
               const LocalVector &old_plastic) const;

    /** f(t) = tau + t_n tan(phi) - c [kPa]. */
    double
    yield_function(const LocalVector &traction) const;

  private:
    /**
     * The slip tangent at a trial traction that slips, rho = tau / tau_tr
     * the radial-return shrink factor.
     */
    LocalTangent
    slip_tangent(const LocalVector &trial, const double scale) const;

    double kn, ks, cohesion, tan_phi, tan_psi, tension_cutoff;
  };



  /** "stick", "slip" or "open". */
  std::string
  to_string(const ContactState state);
} // namespace FourierSSI

#endif
