#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/rigid_foundation_parameters.h>
#include <set>

namespace FourierSSI
{
  namespace
  {
    /** 'NAME = FORCE' -> (NAME, FORCE); empty text -> ("", 0). */
    std::pair<std::string, double>
    capacity_normalisation(const std::string &text)
    {
      std::string capacity_name;
      double      capacity_reference = 0.;
      if (Utilities::trim(text).empty())
        return {capacity_name, capacity_reference};
      const std::string entry  = "Rigid foundation/Capacity normalisation";
      const auto        equals = text.find('=');
      AssertThrow(equals != std::string::npos,
                  ExcMessage(entry + ": '" + text +
                             "' is not 'NAME = FORCE' (e.g. 'N_p = 100')"));
      capacity_name = Utilities::trim(text.substr(0, equals));
      AssertThrow(!capacity_name.empty(),
                  ExcMessage(entry + ": '" + text + "' has no NAME"));
      const std::string force = Utilities::trim(text.substr(equals + 1));
      std::size_t       used  = 0;
      try
        {
          capacity_reference = std::stod(force, &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      AssertThrow(used > 0 && used == force.size() &&
                    std::isfinite(capacity_reference) &&
                    capacity_reference > 0.,
                  ExcMessage(entry + ": FORCE '" + force +
                             "' is not a positive number"));
      return {capacity_name, capacity_reference};
    }

    const Choices<FoundationTie> &
    ties()
    {
      static const Choices<FoundationTie> choices{
        {"material", FoundationTie::material},
        {"boundary", FoundationTie::boundary}};
      return choices;
    }

    /** Rigid foundation/Tied components: normal only (true) or all. */
    const Choices<bool> &
    tied_components()
    {
      static const Choices<bool> choices{{"all", false}, {"normal", true}};
      return choices;
    }

    /** The motions as Held motions names them. */
    const Choices<FoundationMotion> &
    motion_names()
    {
      static const Choices<FoundationMotion> choices{
        {"u", FoundationMotion::u},
        {"w", FoundationMotion::w},
        {"twist", FoundationMotion::twist},
        {"rotation", FoundationMotion::rotation}};
      return choices;
    }

    /** The load that works on each motion. */
    const Choices<FoundationMotion> &
    motion_loads()
    {
      static const Choices<FoundationMotion> choices{
        {"H", FoundationMotion::u},
        {"V", FoundationMotion::w},
        {"T", FoundationMotion::twist},
        {"M", FoundationMotion::rotation}};
      return choices;
    }
  } // namespace

  std::string
  name_of(const FoundationTie tie)
  {
    return ties().name_of(tie);
  }

  std::string
  name_of(const FoundationMotion motion)
  {
    return motion_names().name_of(motion);
  }

  Harmonic
  harmonic_of(const FoundationMotion motion)
  {
    if (motion == FoundationMotion::w)
      return {0, Family::symmetric};
    if (motion == FoundationMotion::twist)
      return {0, Family::antisymmetric};
    return {1, Family::symmetric};
  }

  std::string
  load_name_of(const FoundationMotion motion)
  {
    return motion_loads().name_of(motion);
  }

  std::string
  load_unit_of(const FoundationMotion motion)
  {
    return motion == FoundationMotion::u || motion == FoundationMotion::w ?
             "kN" :
             "kN.m";
  }

  namespace
  {
    /** 'u, rotation' -> the motions; Patterns::List checked the names. */
    std::vector<FoundationMotion>
    held_motions_of(const std::string &text)
    {
      std::vector<FoundationMotion> motions;
      for (const std::string &name : Utilities::split_string_list(text))
        {
          const FoundationMotion m =
            motion_names().value_of(name, "Rigid foundation/Held motions");
          // Held twice is one constraint given twice: the second has no
          // DoF left to hold ("no free master DoF" deep in the tie).
          AssertThrow(std::find(motions.begin(), motions.end(), m) ==
                        motions.end(),
                      ExcMessage("Rigid foundation/Held motions: '" + name +
                                 "' given twice in '" + text + "'"));
          motions.push_back(m);
        }
      return motions;
    }

    /**
     * The loads that work on a motion (given or held): holding a motion
     * and loading it at once is a contradiction.
     */
    std::vector<std::pair<std::string, double>>
    loads_on(const FoundationMotion motion, const RigidFoundationParameters &f)
    {
      switch (motion)
        {
          case FoundationMotion::u:
            return {{"Horizontal force", f.horizontal_force},
                    {"Held horizontal force", f.held_horizontal_force}};
          case FoundationMotion::w:
            return {{"Vertical force", f.vertical_force},
                    {"Held vertical force", f.held_vertical_force}};
          case FoundationMotion::twist:
            return {{"Torque", f.torque}, {"Held torque", f.held_torque}};
          case FoundationMotion::rotation:
            return {{"Moment", f.moment}, {"Held moment", f.held_moment}};
        }
      return {};
    }

    /** One line for held motions that contradict the other entries. */
    void
    check_held_motions(const RigidFoundationParameters &f)
    {
      const std::string entry = "Rigid foundation/Held motions";
      if (f.held_motions.empty())
        return;
      AssertThrow(f.enabled,
                  ExcMessage(entry + ": held motions are motions of the "
                                     "rigid foundation; set Enabled = true"));
      AssertThrow(!f.stiffness_coefficients,
                  ExcMessage(entry + ": the stiffness coefficients (and "
                                     "Stiffness matrix) are those of the free "
                                     "foundation; hold no motion in that run"));
      for (const FoundationMotion m : f.held_motions)
        {
          AssertThrow(!(f.normal_only && (m == FoundationMotion::u ||
                                          m == FoundationMotion::twist)),
                      ExcMessage(entry + ": '" + name_of(m) +
                                 "' is not a rigid motion with 'Tied "
                                 "components = normal'"));
          // A swipe holds w at the value the Held vertical force reached:
          // that load is the preload, not a contradiction.
          const bool swiped = m == FoundationMotion::w && f.swipes();
          for (const auto &[load, value] : loads_on(m, f))
            AssertThrow(value == 0. ||
                          (swiped && load == "Held vertical force"),
                        ExcMessage(entry + ": '" + name_of(m) + "' is held " +
                                   (swiped ? "at the preload's value (a "
                                             "swipe)" :
                                             "at zero") +
                                   " and loaded by Rigid foundation/" + load +
                                   " at once; drop one"));
        }
    }

    /** 'u: 1, rotation: 0.25' -> the components; one line for bad text. */
    void
    parse_motion_direction(const std::string         &text,
                           RigidFoundationParameters &f)
    {
      const std::string entry = "Rigid foundation/Motion direction";
      f.motion_direction      = Utilities::trim(text);
      f.direction_u = f.direction_rotation = 0.;
      std::set<std::string> named;
      for (const std::string &item :
           Utilities::split_string_list(f.motion_direction))
        {
          const auto colon = item.find(':');
          AssertThrow(colon != std::string::npos,
                      ExcMessage(entry + ": '" + item +
                                 "' is not 'MOTION: COMPONENT' (e.g. 'u: 1, "
                                 "rotation: 0.25')"));
          const std::string name  = Utilities::trim(item.substr(0, colon));
          const std::string value = Utilities::trim(item.substr(colon + 1));
          AssertThrow(name != "w" && name != "twist",
                      ExcMessage(entry + ": '" + name +
                                 "' not yet: w and twist are carried by "
                                 "harmonic 0, u and rotation by harmonic 1, "
                                 "solved as separate systems, and a "
                                 "direction across harmonics needs a "
                                 "constraint between them"));
          AssertThrow(name == "u" || name == "rotation",
                      ExcMessage(entry + ": '" + name +
                                 "' is not a motion of the probe (u, "
                                 "rotation)"));
          AssertThrow(named.insert(name).second,
                      ExcMessage(entry + ": '" + name + "' is named twice"));
          double      component = 0.;
          std::size_t used      = 0;
          try
            {
              component = std::stod(value, &used);
            }
          catch (const std::exception &)
            {
              used = 0;
            }
          AssertThrow(used > 0 && used == value.size() &&
                        std::isfinite(component),
                      ExcMessage(entry + ": the component '" + value +
                                 "' of '" + name + "' is not a finite number"));
          (name == "u" ? f.direction_u : f.direction_rotation) = component;
        }
    }

    /** One line for a direction probe that contradicts the other entries. */
    void
    check_motion_direction(const RigidFoundationParameters &f)
    {
      const std::string entry = "Rigid foundation/Motion direction";
      if (!f.probes_direction())
        return;
      AssertThrow(f.direction_u != 0. || f.direction_rotation != 0.,
                  ExcMessage(entry + ": '" + f.motion_direction +
                             "' has zero length; give the ratio u : L "
                             "theta of the probe (e.g. 'u: 1, rotation: "
                             "0.25')"));
      AssertThrow(f.enabled,
                  ExcMessage(entry + ": the probe moves the rigid "
                                     "foundation; set Enabled = true"));
      AssertThrow(!f.normal_only,
                  ExcMessage(entry + ": 'Tied components = normal' has no "
                                     "rigid horizontal motion u"));
      AssertThrow(!f.stiffness_coefficients,
                  ExcMessage(entry + ": the stiffness coefficients (and "
                                     "Stiffness matrix) are those of the free "
                                     "foundation; probe in another run"));
      for (const FoundationMotion m :
           {FoundationMotion::u, FoundationMotion::rotation})
        AssertThrow(!f.holds(m),
                    ExcMessage(entry + ": '" + name_of(m) +
                               "' is also in Held motions; the direction "
                               "fixes u : L theta already, hold neither"));
      AssertThrow(f.direction_length > 0. ||
                    f.direction_u * f.direction_rotation == 0.,
                  ExcMessage("Rigid foundation/Direction length: give the "
                             "length L [m] of u : L theta (e.g. the "
                             "diameter D) for the direction '" +
                             f.motion_direction + "'"));
      // The loads along the direction drive it: their work on the unit
      // motion (u, theta) = (d_u, d_theta / L).
      const double L    = f.direction_length > 0. ? f.direction_length : 1.;
      const double work = f.horizontal_force * f.direction_u +
                          f.moment * f.direction_rotation / L;
      AssertThrow(work != 0.,
                  ExcMessage(entry +
                             ": Horizontal force and Moment do no "
                             "work along '" +
                             f.motion_direction +
                             "' (H d_u + M d_theta / L = 0): nothing drives "
                             "the probe"));
    }
  } // namespace

  namespace
  {
    /** Where the rigid body is and how it is tied. */
    void
    declare_tie_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Tie DoFs to an exact rigid-body motion.");
      prm.declare_entry("Tie",
                        "material",
                        Patterns::Selection(ties().selection()),
                        "material: all DoFs of cells with material id 'Id' (a "
                        "rigid footing or pile body); boundary: the DoFs on "
                        "boundary id 'Id' (a rigid plate in contact).");
      prm.declare_entry("Id", "1", Patterns::Integer(0, 254), "See 'Tie'.");
      prm.declare_entry("Tied components",
                        "all",
                        Patterns::Selection(tied_components().selection()),
                        "all: u, v, w follow the rigid motion; normal: only "
                        "the axial component v (frictionless horizontal "
                        "contact).");
      prm.declare_entry("Reference elevation",
                        "0",
                        Patterns::Double(),
                        "z [m] of the point on the axis about which M and "
                        "Theta are taken (default: ground surface z = 0).");
    }

    /** The loads on the foundation, scaled along a nonlinear path. */
    void
    declare_load_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Horizontal force",
                        "0",
                        Patterns::Double(),
                        "H_x [kN] along x (harmonic 1, symmetric).");
      prm.declare_entry("Horizontal force y",
                        "0",
                        Patterns::Double(),
                        "H_y [kN] along y (harmonic 1, antisymmetric).");
      prm.declare_entry("Moment x",
                        "0",
                        Patterns::Double(),
                        "M_x [kN.m] about +x through the reference point "
                        "(harmonic 1, antisymmetric).");
      prm.declare_entry("Moment",
                        "0",
                        Patterns::Double(),
                        "M_y [kN.m] about +y through the reference point "
                        "(harmonic 1, symmetric).");
      prm.declare_entry("Vertical force",
                        "0",
                        Patterns::Double(),
                        "V [kN] along +z (harmonic 0, symmetric).");
      prm.declare_entry("Torque",
                        "0",
                        Patterns::Double(),
                        "T [kN.m] about +z (harmonic 0, antisymmetric).");
    }

    /** Held loads, held motions and the probe direction. */
    void
    declare_held_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Held vertical force",
                        "0",
                        Patterns::Double(),
                        "Nonlinear runs: V [kN] applied first (Nonlinear "
                        "interfaces/Held load steps, with the body force and "
                        "tractions) and then held while the loads above are "
                        "scaled by the load or displacement control: a "
                        "combined loading path (a fixed V, then H or M).");
      prm.declare_entry("Held horizontal force",
                        "0",
                        Patterns::Double(),
                        "Nonlinear runs: held H_x [kN] (see Held vertical "
                        "force).");
      prm.declare_entry("Held moment",
                        "0",
                        Patterns::Double(),
                        "Nonlinear runs: held M_y [kN.m] about the reference "
                        "point (see Held vertical force).");
      prm.declare_entry("Held torque",
                        "0",
                        Patterns::Double(),
                        "Nonlinear runs: held T [kN.m] (see Held vertical "
                        "force).");
      prm.declare_entry(
        "Held motions",
        "",
        Patterns::List(Patterns::Selection(motion_names().selection()), 0, 4),
        "Rigid motions held at zero (their master DoF constrained), for "
        "the probes of the foundation literature: u (translation along x) "
        "held for pure M, rotation (about y, through the reference point) "
        "held for pure H, also w and twist. Linear and nonlinear runs; "
        "the log prints the load that holds each (kN, kN m). A held motion "
        "takes no load (Horizontal force with u, Moment with rotation, "
        "...), is not the Load path/Controlled motion, and "
        "excludes Stiffness coefficients. w with a Held vertical force is a "
        "swipe test (plastic soil): w held at the value the preload "
        "reached while the loads are scaled, V changing to keep it "
        "(doc/offshore-foundations.md 7). Empty: none held.");
      prm.declare_entry(
        "Motion direction",
        "",
        Patterns::Anything(),
        "A displacement probe: 'u: D_U, rotation: D_THETA' keeps the "
        "foundation's motion in the x-z plane along u : L theta = D_U : "
        "D_THETA (L the Direction length; theta about y through the "
        "reference point), the probe of the offshore literature that "
        "drives a fixed ratio of horizontal displacement to rotation "
        "(doc/offshore-foundations.md 7). The complementary combination "
        "D_THETA u - D_U L theta is held at zero as Held motions holds a "
        "motion, so any load that works on the direction drives it: "
        "Horizontal force (or Moment), with Load path/Controlled motion = "
        "horizontal (or rotation) under displacement control. The log "
        "prints and the rows probe_H, probe_M give the H and M on the "
        "foundation (applied plus the load that keeps the direction). "
        "u and rotation are then not Held motions. Empty: no probe.");
      prm.declare_entry("Direction length",
                        "0",
                        Patterns::Double(0.),
                        "L [m] of Motion direction's u : L theta, e.g. the "
                        "foundation diameter D; needed when both components "
                        "are non-zero.");
    }

    /** The stiffness coefficients and matrix, and their normalisation. */
    void
    declare_stiffness_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Stiffness coefficients",
        "false",
        Patterns::Bool(),
        "For n = 1: also solve unit H and unit M and report "
        "I_H, I_M, I_MH and K_H, K_M, K_MH (thesis eqs 4.2-4.5), "
        "normalised with the two entries below.");
      prm.declare_entry("Stiffness matrix",
                        "false",
                        Patterns::Bool(),
                        "Also solve a unit V (n = 0 symmetric) and a unit T "
                        "(n = 0 antisymmetric), and write the 6x6 stiffness "
                        "matrix at the reference point (axis, Reference "
                        "elevation) in SI units with its error bars: "
                        "foundation-stiffness.csv and the SubDyn SSI file "
                        "foundation-stiffness-subdyn.txt in Output/Directory "
                        "(doc/foundation-stiffness.md). Implies Stiffness "
                        "coefficients.");
      prm.declare_entry("Reference shear modulus",
                        "1",
                        Patterns::Double(0.),
                        "G [kPa] of the normalisation: G at depth e for an "
                        "embedded footing (thesis eq. 4.2), at depth L for a "
                        "pile (eq. 6.1).");
      prm.declare_entry(
        "Reference length",
        "1",
        Patterns::Double(0.),
        "Length [m] of the normalisation: footing radius a, pile "
        "radius r.");
      prm.declare_entry("Reference Poisson ratio",
                        "-1",
                        Patterns::Double(-1., 0.5),
                        "nu of the soil (< 0: not given). When given, the log "
                        "also prints the compliances with E = 2 G (1 + nu) "
                        "(e.g. theta E a^3 / M, thesis Table 4.1) and, next to "
                        "each computed stiffness, the closed form of a rigid "
                        "disc on the surface of an elastic half-space with G "
                        "and a above (vertical 4 G a / (1 - nu), rocking "
                        "8 G a^3 / (3 (1 - nu)): Poulos & Davis 1974, thesis "
                        "eq. 4.1; horizontal 32 (1 - nu) G a / (7 - 8 nu), "
                        "torsion 16 G a^3 / 3: Gazetas 1991).");
    }

    /** The pile formula and the capacity's normalisation. */
    void
    declare_reference_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Pile diameter",
                        "0",
                        Patterns::Double(0.),
                        "D [m] of a pile for the formula printed beside K_H, "
                        "K_M, K_MH (Randolph 1981, flexible pile; soil: "
                        "material 0). 0: no formula.");
      prm.declare_entry("Pile length",
                        "0",
                        Patterns::Double(0.),
                        "L [m] of that pile (the formula holds for L >= its "
                        "critical length l_c, printed).");
      prm.declare_entry("Pile Young modulus",
                        "0",
                        Patterns::Double(0.),
                        "E_p [kPa] of the solid circular pile with the same "
                        "bending stiffness as that pile: E I / (pi D^4 / 64).");
      prm.declare_entry(
        "Capacity normalisation",
        "",
        Patterns::Anything(),
        "'NAME = FORCE': a plastic run under displacement "
        "control also prints its capacity as NAME = |capacity| "
        "/ FORCE with the same relative error bar, and writes "
        "the row capacity_normalised. FORCE [kN, or kN m for a "
        "moment] is the product the literature divides by, e.g. "
        "'N_p = 100' for a pile's s_u d L = 10 kPa x 1 m x 10 m, "
        "'N_c = 31.4159' for a footing's s_u pi a^2. Empty: "
        "not printed.");
    }
  } // namespace

  void
  RigidFoundationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid foundation");
    declare_tie_entries(prm);
    declare_load_entries(prm);
    declare_held_entries(prm);
    declare_stiffness_entries(prm);
    declare_reference_entries(prm);
    prm.leave_subsection();
  }

  void
  RigidFoundationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid foundation");
    enabled = prm.get_bool("Enabled");
    tie     = ties().value_of(prm.get("Tie"), "Rigid foundation/Tie");
    id      = prm.get_integer("Id");
    normal_only =
      tied_components().value_of(prm.get("Tied components"),
                                 "Rigid foundation/Tied components");
    reference_elevation   = prm.get_double("Reference elevation");
    horizontal_force      = prm.get_double("Horizontal force");
    moment                = prm.get_double("Moment");
    horizontal_force_y    = prm.get_double("Horizontal force y");
    moment_x              = prm.get_double("Moment x");
    vertical_force        = prm.get_double("Vertical force");
    torque                = prm.get_double("Torque");
    held_horizontal_force = prm.get_double("Held horizontal force");
    held_moment           = prm.get_double("Held moment");
    held_vertical_force   = prm.get_double("Held vertical force");
    held_torque           = prm.get_double("Held torque");
    AssertThrow(!any_held() || enabled,
                ExcMessage("Rigid foundation/Held ...: held loads act on the "
                           "rigid foundation; set Enabled = true"));
    AssertThrow(!(normal_only && held_horizontal_force != 0.),
                ExcMessage("Rigid foundation/Held horizontal force: 'Tied "
                           "components = normal' has no horizontal stiffness"));
    AssertThrow(!(normal_only && enabled &&
                  (horizontal_force != 0. || horizontal_force_y != 0.)),
                ExcMessage("Rigid foundation: 'Tied components = normal' is a "
                           "frictionless contact with no horizontal stiffness; "
                           "a Horizontal force makes the system singular"));
    stiffness_matrix = prm.get_bool("Stiffness matrix");
    AssertThrow(!stiffness_matrix || enabled,
                ExcMessage("Rigid foundation/Stiffness matrix: the 6x6 is "
                           "that of the rigid foundation, which is off; set "
                           "Enabled = true"));
    // The matrix's H-M block is the unit H and unit M solves.
    stiffness_coefficients =
      prm.get_bool("Stiffness coefficients") || stiffness_matrix;
    AssertThrow(!(normal_only && stiffness_matrix),
                ExcMessage("Rigid foundation/Stiffness matrix: 'Tied "
                           "components = normal' is a frictionless contact "
                           "with no horizontal or torsional stiffness; tie "
                           "all components"));
    reference_shear_modulus = prm.get_double("Reference shear modulus");
    reference_length        = prm.get_double("Reference length");
    reference_poisson_ratio = prm.get_double("Reference Poisson ratio");
    AssertThrow(reference_shear_modulus > 0. && reference_length > 0.,
                ExcMessage("Rigid foundation: 'Reference shear modulus' and "
                           "'Reference length' must be positive"));
    pile_diameter = prm.get_double("Pile diameter");
    pile_length   = prm.get_double("Pile length");
    pile_modulus  = prm.get_double("Pile Young modulus");
    AssertThrow(pile_diameter == 0. || (pile_length > 0. && pile_modulus > 0. &&
                                        stiffness_coefficients),
                ExcMessage("Rigid foundation/Pile diameter: the pile formula "
                           "needs Pile length > 0, Pile Young modulus > 0 and "
                           "Stiffness coefficients (or Stiffness matrix)"));
    std::tie(capacity_name, capacity_reference) =
      capacity_normalisation(prm.get("Capacity normalisation"));
    held_motions = held_motions_of(prm.get("Held motions"));
    check_held_motions(*this);
    direction_length = prm.get_double("Direction length");
    parse_motion_direction(prm.get("Motion direction"), *this);
    check_motion_direction(*this);
    prm.leave_subsection();
  }


  std::vector<FoundationMotion>
  RigidFoundationParameters::reported_motions() const
  {
    std::vector<FoundationMotion> motions = held_motions;
    if (probes_direction())
      motions.insert(motions.end(),
                     {FoundationMotion::u, FoundationMotion::rotation});
    return motions;
  }

  std::string
  RigidFoundationParameters::reaction_row(const FoundationMotion motion) const
  {
    // A direction probe excludes holding u or rotation (check above).
    if (holds(motion))
      return "held_" + name_of(motion) + "_reaction";
    return "probe_" + load_name_of(motion);
  }

  std::string
  RigidFoundationParameters::reaction_label(const FoundationMotion motion) const
  {
    return (holds(motion) ? name_of(motion) + " held by " : "probe ") +
           load_name_of(motion);
  }

} // namespace FourierSSI
