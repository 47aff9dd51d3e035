/**
 * The constitutive law of a zero-thickness interface, its .prm syntax
 * (subsection "Interfaces"), and the closed-form return mapping of the
 * nonlinear Mohr-Coulomb law with a tension cut-off
 * (doc/nonlinear-interfaces.md, section 2; thesis ch. 2.4: adhesion,
 * glissement, decollement).
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
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <limits>
#include <map>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * The law of one interface. Linear laws (eq. 3.8d, D = diag(ks, kn, ks)):
   * the presets rough (kn = ks = 1e10 kPa/m), smooth (kn = 1e10, ks = 0),
   * explicit kn, ks >= 0, Van Langen & Vermeer's virtual thickness
   * (ks = mu G / l, kn = mu G / ((1 - 2 nu) l)), or the exact tied limits.
   * The nonlinear law `coulomb` keeps kn, ks > 0 as the elastic part and
   * adds the Mohr-Coulomb slip surface and the tension cut-off.
   */
  struct InterfaceLaw
  {
    bool   vermeer = false;
    double normal  = 0.; // kn [kPa/m] (not vermeer)
    double shear   = 0.; // ks [kPa/m] (not vermeer)
    double mu      = 0.; // Van Langen & Vermeer factor (vermeer)
    /** Material id of the soil side (vermeer); -1: the side of lower G. */
    int material = -1;
    /**
     * Exact limits instead of penalty springs (no stiffness assembled):
     * tied = kn = ks = infinity (the twins move together), tied_normal =
     * kn = infinity, ks = 0 (only the normal displacement is continuous).
     */
    bool tied = false, tied_normal = false;

    /** Mohr-Coulomb slip and tension cut-off (the entries below apply). */
    bool   coulomb        = false;
    double cohesion       = 0.; // c [kPa]
    double friction_angle = 0.; // phi [degrees], 0 <= phi < 90
    double dilation_angle = 0.; // psi [degrees], 0 <= psi <= phi
    /** sigma_t [kPa]: largest tensile t_n; infinity = no cut-off. */
    double tension_cutoff = 0.;

    /**
     * Exact non-penetration with Coulomb friction (`contact, phi=..,
     * c=..`): the coulomb law without kn, ks, tensionless, no dilation,
     * enforced by an augmented Lagrangian at the theta samples
     * (doc/nonlinear-interfaces.md section 5d); its springs are the
     * augmentation, interface_iteration_stiffness G / l.
     */
    bool contact = false;

    /**
     * kn=auto, ks=auto (coulomb): automatic_interface_stiffness G / l,
     * resolved per face by InterfaceIntegrator (G of the softer side at the
     * face, l the interface's mean face length).
     */
    bool automatic_normal = false, automatic_shear = false;

    bool
    is_nonlinear() const
    {
      return coulomb || contact;
    }

    /** The faces can separate: contact, or coulomb with a tension cut-off. */
    bool
    can_open() const
    {
      return contact || (coulomb && std::isfinite(tension_cutoff));
    }
  };

  /**
   * The stiffest interface spring the condensed interface iteration is
   * given, in units of G / l (G the shear modulus of the softer side at the
   * face, l the interface's mean face length): the augmentation of
   * `contact`, and under Newton (Load path/Stiffness = tangent)
   * the cap on the springs of a coulomb interface assembled into K and in
   * its return mapping; its own stiffer kn, ks then come in through the
   * augmented Lagrangian's multipliers (NonlinearInterfacePoints::
   * update_multipliers). Stiffer springs make K^-1 and
   * the correction load c = int B^T (D d - (t - t0)) carry about kappa
   * times the round-off of the applied load, which at kappa = 1e8 left the
   * Newton matrix without a correct digit (section 5b).
   */
  constexpr double interface_iteration_stiffness = 1e3;

  /**
   * The same cap for the soil solver's Newton (plastic soil; its K_t is
   * sparse and factorized whole, not the condensed dense Jacobian), in units
   * of G / l, for a coulomb law whose faces cannot open (sigma_t = none);
   * one that can keeps interface_iteration_stiffness. Measured on
   * prm/pile-adhesion.prm (G / l = 300 kPa/m): Newton on the law itself runs
   * at kn = 3.3e4 G / l and fails in step 1 from 3.3e5 G / l on (and so does
   * the augmented Lagrangian on springs of 1e5 G / l); on springs of 1e3
   * G / l it runs but takes twice the time of kn itself at 3.3e3 G / l (the
   * bundled scene), so the cap stays above the springs that run as they
   * are. At a contact edge (the free-head pile with a smooth tensionless
   * shaft) springs of 1e4 G / l fail and 1e3 G / l run.
   */
  constexpr double soil_iteration_stiffness = 1e4;

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

  /** Subsection "Interfaces" of the .prm file. */
  struct InterfaceParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Parse "id: rough; id: smooth; id: kn=1e8, ks=0; id: vermeer, mu=50;
     * id: coulomb, kn=1e6, ks=1e6, c=0, phi=25[, psi=0][, sigma_t=0|none]".
     * Throws a one-line message naming "Interfaces/Interfaces".
     */
    static std::map<types::boundary_id, InterfaceLaw>
    parse_list(const std::string &text);

    /** True if at least one interface is declared. */
    bool
    enabled() const
    {
      return !laws.empty();
    }

    /**
     * > 0: coulomb interfaces are assembled with springs of at most this
     * times G / l (Newton, interface_iteration_stiffness); 0: with their
     * own kn, ks (the initial-stiffness iteration needs K to be the law's
     * elastic stiffness).
     */
    double iteration_stiffness_cap = 0.;

    /** True if some interface has a nonlinear law. */
    bool
    any_nonlinear() const;

    /** True if some interface is `contact` (exact, augmented Lagrangian). */
    bool
    any_contact() const;

    std::map<types::boundary_id, InterfaceLaw> laws;
    /** Twin faces and nodes must coincide within this times face length. */
    double pairing_tolerance = 1e-8;
    /**
     * Nonlinear integration = nodal: the coulomb and contact interfaces are
     * sampled and integrated at their nodes (nonlinear_interface_rule()).
     */
    bool nodal_integration = false;
  };

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
