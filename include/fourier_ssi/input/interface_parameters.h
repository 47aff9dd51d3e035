/**
 * Subsection "Interfaces" of the .prm file: the law of each interface (its
 * syntax, the presets and the nonlinear laws' data) and how the interfaces
 * are paired and sampled. The return mapping of the nonlinear laws is
 * MohrCoulombInterface (interface_law.h); the sign convention of the
 * tractions is written there.
 */
#ifndef fourier_ssi_interface_parameters_h
#define fourier_ssi_interface_parameters_h

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <map>
#include <optional>
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
    /**
     * Which law it is (the word of its list item):
     * - springs: penalty springs kn, ks, given or the presets rough and
     *   smooth;
     * - vermeer: Van Langen & Vermeer's springs from G / l and mu;
     * - tied, tied_normal: exact limits instead of penalty springs (no
     *   stiffness assembled): tied = kn = ks = infinity (the twins move
     *   together), tied_normal = kn = infinity, ks = 0 (only the normal
     *   displacement is continuous);
     * - coulomb: Mohr-Coulomb slip and tension cut-off on elastic springs
     *   kn, ks > 0 (the strength entries below apply);
     * - contact: exact non-penetration with Coulomb friction (`contact,
     *   phi=.., c=..`): the coulomb law without kn, ks, tensionless, no
     *   dilation, enforced by an augmented Lagrangian at the theta samples
     *   (doc/nonlinear-interfaces.md section 5d); its springs are the
     *   augmentation, interface_iteration_stiffness G / l.
     */
    enum class Kind
    {
      springs,
      vermeer,
      tied,
      tied_normal,
      coulomb,
      contact
    };
    Kind kind = Kind::springs;

    double normal = 0.; // kn [kPa/m] (not vermeer)
    double shear  = 0.; // ks [kPa/m] (not vermeer)
    double mu     = 0.; // Van Langen & Vermeer factor (vermeer)
    /** Material id of the soil side (vermeer); -1: the side of lower G. */
    int material = -1;

    /** The strength of coulomb and contact. */
    double cohesion       = 0.; // c [kPa]
    double friction_angle = 0.; // phi [degrees], 0 <= phi < 90
    double dilation_angle = 0.; // psi [degrees], 0 <= psi <= phi
    /** sigma_t [kPa]: largest tensile t_n; infinity = no cut-off. */
    double tension_cutoff = 0.;

    /**
     * kn=auto, ks=auto (coulomb): automatic_interface_stiffness G / l,
     * resolved per face by InterfaceIntegrator (G of the softer side at the
     * face, l the interface's mean face length). How a spring's value is
     * given, not which law: one flag per spring.
     */
    bool automatic_normal = false, automatic_shear = false;

    /** coulomb or contact: the law has a return mapping. */
    bool
    is_nonlinear() const
    {
      return kind == Kind::coulomb || kind == Kind::contact;
    }

    /** tied or tied_normal: constraints, not springs. */
    bool
    is_exact_limit() const
    {
      return kind == Kind::tied || kind == Kind::tied_normal;
    }

    /** The faces can separate: contact, or coulomb with a tension cut-off. */
    bool
    can_open() const
    {
      return kind == Kind::contact ||
             (kind == Kind::coulomb && std::isfinite(tension_cutoff));
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
   * The coulomb penalty, max(kn, ks) l / G, from which an interface is
   * stiff: Load path/Stiffness = auto takes Newton for it, and its theta
   * samples are 2 n_max + 1 (constrained_theta_samples) with either
   * solver. Measured on the disc in a ring (benchmarks/nonlinear-engine,
   * l = 2 r0): the initial-stiffness iteration is faster up to
   * kn r0 / G = 1e3 (0.13 s against 0.27 s) and Newton from 1e4 on (0.31 s
   * against 1.0 s; from 1e5 on the iteration does not converge), with the
   * crossover of the two time trends at kn r0 / G = 2.6e3.
   */
  constexpr double stiff_penalty_ratio = 5e3;

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

    /**
     * A contact interface, or a coulomb penalty at or above
     * stiff_penalty_ratio: what Load path/Stiffness = auto and the theta
     * samples of an interface-only scene follow. Needs penalty_ratio
     * (measured on the mesh; an internal error before).
     */
    bool
    is_stiff() const;

    /**
     * The stiffest coulomb penalty against the soil beside it, max(kn, ks)
     * l / G over the faces of the coulomb interfaces (l the interface's
     * mean face length, G the softer side's shear modulus at the face),
     * measured on the scene's first mesh (choose_interface_linearisation);
     * empty before.
     */
    std::optional<double> penalty_ratio;

    std::map<types::boundary_id, InterfaceLaw> laws;
    /** Twin faces and nodes must coincide within this times face length. */
    double pairing_tolerance = 1e-8;
    /**
     * Nonlinear integration = nodal: the coulomb and contact interfaces are
     * sampled and integrated at their nodes (nonlinear_interface_rule()).
     */
    bool nodal_integration = false;
  };

} // namespace FourierSSI

#endif
