/**
 * Subsection "Rigid foundation" of the .prm file: what the foundation ties,
 * its loads, held loads and held motions, the probe direction and the
 * normalisations of what is reported (RigidFoundation, rigid_foundation.h,
 * is the rigid-body kinematics these drive).
 */
#ifndef fourier_ssi_rigid_foundation_parameters_h
#define fourier_ssi_rigid_foundation_parameters_h

#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <fourier_ssi/input/harmonic.h>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * What the rigid foundation holds (Rigid foundation/Tie): every DoF of
   * the cells of a material (a footing or pile body) or the DoFs on a
   * boundary (a rigid plate in contact).
   */
  enum class FoundationTie
  {
    material,
    boundary
  };

  /** "material" or "boundary", as the entry spells it. */
  std::string
  name_of(const FoundationTie tie);

  /**
   * A rigid-body motion that Rigid foundation/Held motions can hold at
   * zero: the horizontal translation U_h along x and the rotation Theta
   * about y (n = 1, symmetric family), the vertical translation W_v (n = 0
   * symmetric) and the twist Phi about z (n = 0 antisymmetric).
   */
  enum class FoundationMotion
  {
    u,
    w,
    twist,
    rotation
  };

  /** "u", "w", "twist" or "rotation", as the entry spells it. */
  std::string
  name_of(const FoundationMotion motion);

  /** The harmonic whose master DoFs carry the motion. */
  Harmonic
  harmonic_of(const FoundationMotion motion);

  /** The load that works on the motion: "H", "V", "T" or "M". */
  std::string
  load_name_of(const FoundationMotion motion);

  /** Its unit: "kN" (H, V) or "kN.m" (M, T). */
  std::string
  load_unit_of(const FoundationMotion motion);

  struct RigidFoundationParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    bool          enabled     = false;
    FoundationTie tie         = FoundationTie::material;
    unsigned int  id          = 1;
    bool          normal_only = false; // tie only V (a frictionless contact)
    double        reference_elevation = 0.;
    double        horizontal_force    = 0.; // H [kN], n = 1
    double        moment              = 0.; // M [kN.m], n = 1
    double        horizontal_force_y  = 0.; // H_y [kN], n = 1 antisymmetric
    double        moment_x            = 0.; // M_x [kN.m], n = 1 antisymmetric
    double        vertical_force      = 0.; // V [kN], n = 0 symmetric
    double        torque              = 0.; // T [kN.m], n = 0 antisymmetric
    /**
     * Held loads (plastic soil): applied first, then kept while the loads
     * above are scaled; a combined loading path (a fixed V, then H or M).
     */
    double held_horizontal_force = 0.; // H_x [kN]
    double held_moment           = 0.; // M_y [kN.m]
    double held_vertical_force   = 0.; // V [kN]
    double held_torque           = 0.; // T [kN.m]

    bool
    any_held() const
    {
      return held_horizontal_force != 0. || held_moment != 0. ||
             held_vertical_force != 0. || held_torque != 0.;
    }
    /**
     * Motions held at zero (Held motions): the master DoF constrained, so
     * the foundation is probed with that motion fixed (pure H with the
     * rotation held, pure M with the translation held); the log prints the
     * load that holds each.
     */
    std::vector<FoundationMotion> held_motions;

    bool
    holds(const FoundationMotion motion) const
    {
      return std::find(held_motions.begin(), held_motions.end(), motion) !=
             held_motions.end();
    }
    /**
     * A swipe test (Tan 1990; Gottardi, Houlsby & Butterfield 1999): w in
     * Held motions together with a Held vertical force holds w at the value
     * the preload reached, not at zero. w is then not constrained: the
     * coupled soil solver keeps its increment at zero through a multiplier
     * mu on the unit vertical load (LoadControl::swipe_multipliers),
     * and the V that does it is reported as the load that holds w.
     */
    bool
    swipes() const
    {
      return holds(FoundationMotion::w) && held_vertical_force != 0.;
    }
    /**
     * A displacement probe (Motion direction): the n = 1 rigid motion kept
     * along u : L theta = direction_u : direction_rotation (L the Direction
     * length), i.e. the combination direction_rotation u - direction_u L
     * theta held at zero; the foundation moves along the direction only.
     */
    std::string motion_direction; // the entry as given; empty: no probe
    double      direction_u        = 0.;
    double      direction_rotation = 0.;
    double      direction_length   = 0.; // L [m]; 0: not given

    bool
    probes_direction() const
    {
      return !motion_direction.empty();
    }
    /**
     * The motions whose load is reported at every step: the held motions
     * (the load that holds each) and, in a direction probe, u and rotation
     * (the H and M on the foundation along the probe).
     */
    std::vector<FoundationMotion>
    reported_motions() const;
    /** The results row of that load: held_<motion>_reaction or probe_H/M. */
    std::string
    reaction_row(const FoundationMotion motion) const;
    /** The log's words before its value: 'rotation held by M', 'probe H'. */
    std::string
    reaction_label(const FoundationMotion motion) const;
    /** Also solve the unit H and unit M cases (thesis eqs 4.2-4.5). */
    bool stiffness_coefficients = false;
    /**
     * The 6x6 stiffness matrix at the reference point: also solve a unit V
     * (n = 0 symmetric) and a unit T (n = 0 antisymmetric); implies
     * stiffness_coefficients (doc/foundation-stiffness.md).
     */
    bool   stiffness_matrix        = false;
    double reference_shear_modulus = 1.; // G_se (footing) or G_L (pile)
    double reference_length        = 1.; // a (footing radius) or r (pile)
    /**
     * nu of the soil for E = 2 G (1 + nu) in the printed compliances and
     * for the half-space closed forms of a rigid disc; < 0: not given.
     */
    double reference_poisson_ratio = -1.;
    /**
     * A pile for the published formula printed beside K_H, K_M, K_MH
     * (Randolph 1981, pile_head_formulas.h): diameter [m] (0: none),
     * length [m] and the Young's modulus [kPa] of the solid pile of the
     * same bending stiffness; the soil is material 0.
     */
    double pile_diameter = 0.;
    double pile_length   = 0.;
    double pile_modulus  = 0.;
    /**
     * The capacity's normalisation, 'NAME = FORCE': NAME = capacity / FORCE
     * [kN or kN m] is printed beside a capacity (N_p = H / (s_u d L) for a
     * pile, N_c = V / (s_u A) for a footing). Empty: not printed.
     */
    std::string capacity_name;
    double      capacity_reference = 0.;
  };
} // namespace FourierSSI

#endif
