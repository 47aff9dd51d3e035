#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q1.h>
#include <fourier_ssi/harmonic/rigid_foundation.h>
#include <map>
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
  } // namespace

  std::string
  name_of(const FoundationTie tie)
  {
    return tie == FoundationTie::material ? "material" : "boundary";
  }

  std::string
  name_of(const FoundationMotion motion)
  {
    switch (motion)
      {
        case FoundationMotion::u:
          return "u";
        case FoundationMotion::w:
          return "w";
        case FoundationMotion::twist:
          return "twist";
        case FoundationMotion::rotation:
          return "rotation";
      }
    return "";
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
    switch (motion)
      {
        case FoundationMotion::u:
          return "H";
        case FoundationMotion::w:
          return "V";
        case FoundationMotion::twist:
          return "T";
        case FoundationMotion::rotation:
          return "M";
      }
    return "";
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
        for (const FoundationMotion m : {FoundationMotion::u,
                                         FoundationMotion::w,
                                         FoundationMotion::twist,
                                         FoundationMotion::rotation})
          if (name == name_of(m))
            {
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
                        Patterns::Selection("material|boundary"),
                        "material: all DoFs of cells with material id 'Id' (a "
                        "rigid footing or pile body); boundary: the DoFs on "
                        "boundary id 'Id' (a rigid plate in contact).");
      prm.declare_entry("Id", "1", Patterns::Integer(0, 254), "See 'Tie'.");
      prm.declare_entry("Tied components",
                        "all",
                        Patterns::Selection("all|normal"),
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
        Patterns::List(Patterns::Selection("u|w|twist|rotation"), 0, 4),
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
    enabled     = prm.get_bool("Enabled");
    tie         = prm.get("Tie") == "material" ? FoundationTie::material :
                                                 FoundationTie::boundary;
    id          = prm.get_integer("Id");
    normal_only = prm.get("Tied components") == "normal";
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

  RigidFoundation::RigidFoundation(const RigidFoundationParameters &parameters,
                                   const Harmonic                  &harmonic)
    : parameters(parameters)
    , harmonic(harmonic)
  {}

  void
  RigidFoundation::add_constraints(const DoFHandler<2>       &dof_handler,
                                   AffineConstraints<double> &constraints)
  {
    const TiedNodes nodes = tied_nodes(dof_handler);
    AssertThrow(!nodes.empty(),
                ExcMessage("Rigid foundation: no DoFs found on " +
                           name_of(parameters.tie) + " id " +
                           std::to_string(parameters.id)));
    choose_master(nodes, constraints);
    tie_to_master(nodes, constraints);
    fix_unmoved_masters(constraints);
  }

  RigidFoundation::TiedNodes
  RigidFoundation::tied_nodes(const DoFHandler<2> &dof_handler) const
  {
    const FiniteElement<2> &fe = dof_handler.get_fe();
    const MappingQ1<2>      mapping;
    const auto             &unit_points = fe.get_unit_support_points();
    const auto             &face_points = fe.get_unit_face_support_points();
    TiedNodes               nodes;
    const auto              record = [&](const Point<2>               &x,
                            const unsigned int            component,
                            const types::global_dof_index dof) {
      auto &entry = nodes
                      .emplace(std::make_pair(x[0], x[1]),
                               std::array<types::global_dof_index, 3>{
                                 {numbers::invalid_dof_index,
                                  numbers::invalid_dof_index,
                                  numbers::invalid_dof_index}})
                      .first->second;
      entry[component] = dof;
    };
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (parameters.tie == FoundationTie::material)
          {
            if (cell->material_id() != parameters.id)
              continue;
            cell->get_dof_indices(cell_dofs);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              record(mapping.transform_unit_to_real_cell(cell, unit_points[i]),
                     fe.system_to_component_index(i).first,
                     cell_dofs[i]);
          }
        else
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->face(f)->at_boundary() ||
                  cell->face(f)->boundary_id() != parameters.id)
                continue;
              cell->face(f)->get_dof_indices(face_dofs);
              // Face support points mapped through the straight face.
              const Point<2> a = cell->face(f)->vertex(0),
                             b = cell->face(f)->vertex(1);
              for (unsigned int i = 0; i < fe.n_dofs_per_face(); ++i)
                record(a + face_points[i][0] * (b - a),
                       fe.face_system_to_component_index(i).first,
                       face_dofs[i]);
            }
      }
    return nodes;
  }

  void
  RigidFoundation::choose_master(const TiedNodes                 &nodes,
                                 const AffineConstraints<double> &constraints)
  {
    // The tied node farthest from the axis whose DoFs are free (r_A > 0 is
    // needed to read the rotation from V_A = -Theta r_A).
    double best_r = 0.;
    for (const auto &[x, dofs] : nodes)
      if (x.first > best_r && !constraints.is_constrained(dofs[0]) &&
          !constraints.is_constrained(dofs[1]) &&
          !constraints.is_constrained(dofs[2]))
        {
          best_r          = x.first;
          master_position = Point<2>(x.first, x.second);
          master_U        = dofs[0];
          master_V        = dofs[1];
          master_W        = dofs[2];
        }
    AssertThrow(best_r > 0.,
                ExcMessage("Rigid foundation: no free tied node off the axis"));
  }

  void
  RigidFoundation::tie_to_master(const TiedNodes           &nodes,
                                 AffineConstraints<double> &constraints)
  {
    // The components that follow the rigid motion: V always, U and W unless
    // only the normal component is tied; for n = 0 not the component that
    // carries no stiffness (W symmetric, U and V antisymmetric), which
    // axis_constraints.h sets to zero.
    const bool tie_uw = !parameters.normal_only;
    const bool n0_symmetric =
      harmonic.n == 0 && harmonic.family == Family::symmetric;
    const bool n0_antisymmetric =
      harmonic.n == 0 && harmonic.family == Family::antisymmetric;
    const std::array<bool, 3> follows = {{tie_uw && !n0_antisymmetric,
                                          !n0_antisymmetric,
                                          tie_uw && !n0_symmetric}};
    const std::array<types::global_dof_index, 3> masters = {
      {master_U, master_V, master_W}};
    // Column k: the rigid motion of a unit amplitude of master DoF k. The
    // weights of a tied DoF are its displacement under these motions; a
    // master DoF that moves the body is an unknown, not tied.
    const std::array<MasterValues, 3> unit_master = {
      {{{1., 0., 0.}}, {{0., 1., 0.}}, {{0., 0., 1.}}}};
    std::array<bool, 3> moves_body;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const auto d  = displacement_at(master_position, unit_master[k]);
        moves_body[k] = d[0] != 0. || d[1] != 0. || d[2] != 0.;
      }
    for (const auto &[x, dofs] : nodes)
      {
        const Point<2> position(x.first, x.second);
        for (unsigned int c = 0; c < 3; ++c)
          {
            if (!follows[c] || dofs[c] == numbers::invalid_dof_index ||
                constraints.is_constrained(dofs[c]))
              continue;
            bool is_unknown = false;
            for (unsigned int k = 0; k < 3; ++k)
              is_unknown |= moves_body[k] && dofs[c] == masters[k];
            if (is_unknown)
              continue;
            constraints.add_line(dofs[c]);
            for (unsigned int k = 0; k < 3; ++k)
              {
                const double weight =
                  displacement_at(position, unit_master[k])[c];
                if (weight != 0.)
                  constraints.add_entry(dofs[c], masters[k], weight);
              }
          }
      }
  }

  void
  RigidFoundation::fix_unmoved_masters(AffineConstraints<double> &constraints)
  {
    // Master DoFs that a harmonic does not move are fixed (n >= 2: all;
    // n = 0 antisymmetric: U_A, V_A; n = 0 symmetric: U_A), unless only
    // the normal component is tied (then U and W are soil DoFs).
    const bool                           tie_uw = !parameters.normal_only;
    std::vector<types::global_dof_index> unmoved;
    if (harmonic.n >= 2)
      unmoved = {master_U, master_V, master_W};
    else if (harmonic.n == 0 && harmonic.family == Family::antisymmetric &&
             tie_uw)
      unmoved = {master_U, master_V};
    else if (harmonic.n == 0 && tie_uw)
      unmoved = {master_U};
    for (const types::global_dof_index dof : unmoved)
      if (dof != numbers::invalid_dof_index && !constraints.is_constrained(dof))
        constraints.add_line(dof);
  }

  bool
  RigidFoundation::carries_direction() const
  {
    return parameters.probes_direction() && harmonic.n == 1 &&
           harmonic.family == Family::symmetric;
  }

  void
  RigidFoundation::add_held_motion_constraints(
    AffineConstraints<double> &constraints)
  {
    held_here.clear();
    held_lines.clear();
    for (const FoundationMotion m : parameters.held_motions)
      if (harmonic_of(m).n == harmonic.n &&
          harmonic_of(m).family == harmonic.family)
        held_here.push_back(m);
    direction_here = carries_direction();
    if (held_here.empty() && !direction_here)
      return;
    constraints_without_hold.clear();
    constraints_without_hold.copy_from(constraints);
    constraints_without_hold.close();
    // Each motion is linear in the masters: g_k = its value under a unit
    // amplitude of master k, and sum_k g_k m_k = 0 holds it.
    const auto gradient = [this](const auto &value_of) {
      MasterValues g;
      for (unsigned int k = 0; k < 3; ++k)
        {
          MasterValues unit = {{0., 0., 0.}};
          unit[k]           = 1.;
          g[k]              = value_of(motion_of(unit));
        }
      return g;
    };
    // The w of a swipe is not constrained: the soil solver holds its
    // increment through the vertical load (one set of constraints for the
    // whole path, the preload stage included).
    for (const FoundationMotion m : held_here)
      if (!(m == FoundationMotion::w && parameters.swipes()))
        hold_combination(gradient([m](const RigidMotion &r) {
                           return component(r, m);
                         }),
                         "Rigid foundation/Held motions: '" + name_of(m) + "'",
                         constraints);
    if (direction_here)
      {
        // u : L theta = d_u : d_theta holds d_theta u - d_u L theta = 0.
        const double d_u     = parameters.direction_u,
                     d_theta = parameters.direction_rotation;
        const double L =
          parameters.direction_length > 0. ? parameters.direction_length : 1.;
        hold_combination(gradient([&](const RigidMotion &r) {
                           return d_theta * r.horizontal_displacement -
                                  d_u * L * r.rotation;
                         }),
                         "Rigid foundation/Motion direction",
                         constraints);
      }
  }

  void
  RigidFoundation::hold_combination(const MasterValues        &g,
                                    const std::string         &what,
                                    AffineConstraints<double> &constraints)
  {
    const std::array<types::global_dof_index, 3> masters = {
      {master_U, master_V, master_W}};
    // Solve for a free master with weight (a master held by an earlier
    // motion is constrained already): U_A unless V_A weighs twice as
    // much (|z_A - z_ref| > 2 r_A for U_h), a well-scaled line.
    unsigned int held = 3;
    for (unsigned int k = 0; k < 3; ++k)
      if (g[k] != 0. && !constraints.is_constrained(masters[k]) &&
          (held == 3 || std::abs(g[k]) > 2. * std::abs(g[held])))
        held = k;
    AssertThrow(held < 3,
                ExcMessage(what + " has no free master DoF in harmonic " +
                           harmonic.name()));
    std::vector<std::pair<types::global_dof_index, double>> line;
    for (unsigned int k = 0; k < 3; ++k)
      if (k != held && g[k] != 0.)
        line.emplace_back(masters[k], -g[k] / g[held]);
    constraints.add_line(masters[held]);
    constraints.add_entries(masters[held], line);
    held_lines.emplace(masters[held], line);
  }

  double
  RigidFoundation::component(const RigidMotion     &m,
                             const FoundationMotion motion)
  {
    switch (motion)
      {
        case FoundationMotion::u:
          return m.horizontal_displacement;
        case FoundationMotion::w:
          return m.vertical_displacement;
        case FoundationMotion::twist:
          return m.twist;
        case FoundationMotion::rotation:
          return m.rotation;
      }
    return 0.;
  }

  RigidFoundation::MasterValues
  RigidFoundation::unit_motion(const FoundationMotion motion) const
  {
    // n = 1: (U_h, Theta) = A (U_A, V_A); n = 0: one motion, one master.
    const MasterValues unit_U = {{1., 0., 0.}}, unit_V = {{0., 1., 0.}},
                       unit_W = {{0., 0., 1.}};
    if (harmonic.n == 0)
      {
        const MasterValues &unit =
          harmonic.family == Family::symmetric ? unit_V : unit_W;
        const double per_unit = component(motion_of(unit), motion);
        MasterValues result   = unit;
        for (double &v : result)
          v /= per_unit;
        return result;
      }
    const RigidMotion by_U = motion_of(unit_U), by_V = motion_of(unit_V);
    const double      a = by_U.horizontal_displacement,
                 b = by_V.horizontal_displacement, c = by_U.rotation,
                 d   = by_V.rotation;
    const double det = a * d - b * c;
    // (U_A, V_A) = A^-1 e, e the unit vector of the motion.
    return motion == FoundationMotion::u ?
             MasterValues{{d / det, -c / det, 0.}} :
             MasterValues{{-b / det, a / det, 0.}};
  }

  std::vector<std::pair<FoundationMotion, double>>
  RigidFoundation::held_reactions(const Vector<double> &nodal_forces) const
  {
    // C^T r: every constrained DoF's force moved onto the DoFs it follows
    // (the closed lines name unconstrained DoFs only), so the masters'
    // entries are the work of r on their unit rigid motions.
    Vector<double> condensed = nodal_forces;
    for (const auto &line : constraints_without_hold.get_lines())
      {
        for (const auto &[dof, weight] : line.entries)
          condensed(dof) += weight * condensed(line.index);
        condensed(line.index) = 0.;
      }
    const std::array<types::global_dof_index, 3> masters = {
      {master_U, master_V, master_W}};
    std::vector<FoundationMotion> reported = held_here;
    // The probe's H and M: the work on the unit u (theta = 0) and the unit
    // rotation (u = 0), which the applied loads share with the load that
    // keeps the direction.
    if (direction_here)
      reported.insert(reported.end(),
                      {FoundationMotion::u, FoundationMotion::rotation});
    std::vector<std::pair<FoundationMotion, double>> reactions;
    for (const FoundationMotion m : reported)
      {
        const MasterValues e    = unit_motion(m);
        double             work = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          if (e[k] != 0.)
            work += e[k] * condensed(masters[k]);
        reactions.emplace_back(m, work);
      }
    return reactions;
  }

  std::array<double, 3>
  RigidFoundation::displacement_at(const Point<2>     &x,
                                   const MasterValues &master) const
  {
    // The rigid motions of the header, written with the master node's
    // amplitudes as unknowns: U_h = U_A + V_A (z_A - z_ref) / r_A and
    // Theta = -V_A / r_A (n = 1), W_v = V_A (n = 0 symmetric),
    // Phi = W_A / r_A (n = 0 antisymmetric).
    const double r = x[0], z = x[1];
    const double r_A = master_position[0], z_A = master_position[1];
    const auto &[U_A, V_A, W_A] = master;
    std::array<double, 3> d     = {{0., 0., 0.}};
    if (harmonic.n == 1)
      {
        d[0] = U_A + V_A * (z_A - z) / r_A;
        d[1] = V_A * r / r_A;
        d[2] = -family_sign(harmonic.family) * d[0];
      }
    else if (harmonic.n == 0 && harmonic.family == Family::symmetric)
      d[1] = V_A;
    else if (harmonic.n == 0)
      d[2] = W_A * r / r_A;
    return d;
  }

  RigidMotion
  RigidFoundation::motion_of(const MasterValues &master) const
  {
    // Read at r = 1 on the reference elevation, where U = U_h, V = -Theta
    // (n = 1), V = W_v and W = Phi (n = 0).
    const auto d =
      displacement_at(Point<2>(1., parameters.reference_elevation), master);
    RigidMotion m;
    if (harmonic.n == 1)
      {
        m.horizontal_displacement = d[0];
        m.rotation                = -d[1];
      }
    else if (harmonic.n == 0 && harmonic.family == Family::symmetric)
      m.vertical_displacement = d[1];
    else if (harmonic.n == 0)
      m.twist = d[2];
    return m;
  }

  RigidFoundation::MasterValues
  RigidFoundation::master_forces(const double horizontal_force,
                                 const double moment,
                                 const double vertical_force,
                                 const double torque) const
  {
    // Virtual work: the force on master DoF k is the work of the resultants
    // on the rigid motion of a unit amplitude of that DoF.
    MasterValues forces = {{0., 0., 0.}};
    for (unsigned int k = 0; k < 3; ++k)
      {
        MasterValues unit   = {{0., 0., 0.}};
        unit[k]             = 1.;
        const RigidMotion m = motion_of(unit);
        forces[k]           = horizontal_force * m.horizontal_displacement +
                    moment * m.rotation +
                    vertical_force * m.vertical_displacement + torque * m.twist;
      }
    return forces;
  }

  void
  RigidFoundation::add_held_loads(Vector<double> &rhs) const
  {
    // Held H and M are along x and about y: the symmetric family of n = 1.
    const bool symmetric = harmonic.family == Family::symmetric;
    add_master_forces(rhs,
                      master_forces(symmetric ?
                                      parameters.held_horizontal_force :
                                      0.,
                                    symmetric ? parameters.held_moment : 0.,
                                    parameters.held_vertical_force,
                                    parameters.held_torque));
  }

  void
  RigidFoundation::add_master_forces(Vector<double>     &rhs,
                                     const MasterValues &forces) const
  {
    const std::array<types::global_dof_index, 3> masters = {
      {master_U, master_V, master_W}};
    for (unsigned int k = 0; k < 3; ++k)
      if (forces[k] != 0.)
        add_force(rhs, masters[k], forces[k]);
  }

  void
  RigidFoundation::add_force(Vector<double>               &rhs,
                             const types::global_dof_index dof,
                             const double                  force) const
  {
    // A held master is constrained to the others: its force acts on them
    // (C^T f, as assembly condenses every other load); a fully held body
    // ends at a line without entries and keeps nothing.
    const auto line = held_lines.find(dof);
    if (line == held_lines.end())
      {
        rhs(dof) += force;
        return;
      }
    for (const auto &[master, weight] : line->second)
      add_force(rhs, master, weight * force);
  }

  void
  RigidFoundation::add_loads(Vector<double> &rhs) const
  {
    // The antisymmetric family's rigid motion is the symmetric one turned by
    // 90 degrees: translation along y and rotation about -x, so its (H, M)
    // are (H_y, -M_x). n = 0 has one family per load, n >= 2 none.
    const bool   symmetric = harmonic.family == Family::symmetric;
    const double H =
      symmetric ? parameters.horizontal_force : parameters.horizontal_force_y;
    const double M = symmetric ? parameters.moment : -parameters.moment_x;
    add_master_forces(
      rhs, master_forces(H, M, parameters.vertical_force, parameters.torque));
  }

  RigidMotion
  RigidFoundation::motion(const Vector<double> &solution) const
  {
    RigidMotion m =
      motion_of({{solution(master_U), solution(master_V), solution(master_W)}});
    // With only the normal component tied the translation is not a
    // rigid-body unknown; it stays 0 rather than report a soil value.
    if (parameters.normal_only)
      m.horizontal_displacement = 0.;
    return m;
  }

  Vector<double>
  RigidFoundation::unit_load(const unsigned int load_case,
                             const unsigned int n_dofs) const
  {
    AssertThrow(harmonic.n == 1,
                ExcMessage("Rigid foundation: unit H/M loads need n = 1"));
    Vector<double>     rhs(n_dofs);
    const MasterValues f =
      master_forces(load_case == 0 ? 1. : 0., load_case == 1 ? 1. : 0., 0., 0.);
    add_master_forces(rhs, f);
    return rhs;
  }

  Vector<double>
  RigidFoundation::unit_axial_load(const unsigned int n_dofs) const
  {
    AssertThrow(harmonic.n == 0,
                ExcMessage("Rigid foundation: unit V/T loads need n = 0"));
    const bool     symmetric = harmonic.family == Family::symmetric;
    Vector<double> rhs(n_dofs);
    add_master_forces(
      rhs, master_forces(0., 0., symmetric ? 1. : 0., symmetric ? 0. : 1.));
    return rhs;
  }

  double
  RigidFoundation::axial_motion(const RigidMotion &m) const
  {
    return harmonic.family == Family::symmetric ? m.vertical_displacement :
                                                  m.twist;
  }

  FoundationCoefficients
  RigidFoundation::coefficients(const RigidMotion &under_unit_H,
                                const RigidMotion &under_unit_M) const
  {
    const double           G = parameters.reference_shear_modulus;
    const double           a = parameters.reference_length;
    FoundationCoefficients c;
    // Thesis eq. 4.4 with H = 1 (M = 0) and M = 1 (H = 0).
    c.I_H         = under_unit_H.horizontal_displacement * G * a;
    c.I_MH_from_H = under_unit_H.rotation * G * a * a;
    c.I_MH_from_M = under_unit_M.horizontal_displacement * G * a * a;
    c.I_M         = under_unit_M.rotation * G * a * a * a;
    // K = I^-1 (eq. 4.5; the printed K_MH lacks the minus sign of the
    // inverse, see doc/scenes.md).
    const double I_MH = 0.5 * (c.I_MH_from_H + c.I_MH_from_M);
    const double det  = c.I_H * c.I_M - I_MH * I_MH;
    c.K_H             = c.I_M / det;
    c.K_M             = c.I_H / det;
    c.K_MH            = -I_MH / det;
    return c;
  }

  void
  RigidFoundation::check_supported(
    const Vector<double>            &solution,
    const AffineConstraints<double> &constraints) const
  {
    double foundation = 0., free = 0.;
    for (const auto dof : {master_U, master_V, master_W})
      if (dof != numbers::invalid_dof_index && !constraints.is_constrained(dof))
        foundation = std::max(foundation, std::abs(solution(dof)));
    for (unsigned int i = 0; i < solution.size(); ++i)
      if (!constraints.is_constrained(i) && i != master_U && i != master_V &&
          i != master_W)
        free = std::max(free, std::abs(solution(i)));
    AssertThrow(std::isfinite(foundation) && foundation <= 1e6 * free,
                ExcMessage(
                  "Rigid foundation: singular system, nothing resists "
                  "the foundation's motion in harmonic " +
                  harmonic.name() +
                  " (e.g. a smooth interface or a normal-only contact "
                  "under a horizontal load: no horizontal stiffness)"));
  }
} // namespace FourierSSI
