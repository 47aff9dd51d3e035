#include <cmath>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q1.h>
#include <fourier_ssi/rigid_foundation.h>
#include <map>

namespace FourierSSI
{
  void
  RigidFoundationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid foundation");
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
    prm.declare_entry("Stiffness coefficients",
                      "false",
                      Patterns::Bool(),
                      "For n = 1: also solve unit H and unit M and report "
                      "I_H, I_M, I_MH and K_H, K_M, K_MH (thesis eqs 4.2-4.5), "
                      "normalised with the two entries below.");
    prm.declare_entry("Reference shear modulus",
                      "1",
                      Patterns::Double(0.),
                      "G [kPa] of the normalisation: G at depth e for an "
                      "embedded footing (thesis eq. 4.2), at depth L for a "
                      "pile (eq. 6.1).");
    prm.declare_entry("Reference length",
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
    prm.leave_subsection();
  }

  void
  RigidFoundationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid foundation");
    enabled             = prm.get_bool("Enabled");
    tie                 = prm.get("Tie");
    id                  = prm.get_integer("Id");
    normal_only         = prm.get("Tied components") == "normal";
    reference_elevation = prm.get_double("Reference elevation");
    horizontal_force    = prm.get_double("Horizontal force");
    moment              = prm.get_double("Moment");
    horizontal_force_y  = prm.get_double("Horizontal force y");
    moment_x            = prm.get_double("Moment x");
    vertical_force      = prm.get_double("Vertical force");
    torque              = prm.get_double("Torque");
    AssertThrow(!(normal_only && enabled &&
                  (horizontal_force != 0. || horizontal_force_y != 0.)),
                ExcMessage("Rigid foundation: 'Tied components = normal' is a "
                           "frictionless contact with no horizontal stiffness; "
                           "a Horizontal force makes the system singular"));
    stiffness_coefficients  = prm.get_bool("Stiffness coefficients");
    reference_shear_modulus = prm.get_double("Reference shear modulus");
    reference_length        = prm.get_double("Reference length");
    reference_poisson_ratio = prm.get_double("Reference Poisson ratio");
    AssertThrow(reference_shear_modulus > 0. && reference_length > 0.,
                ExcMessage("Rigid foundation: 'Reference shear modulus' and "
                           "'Reference length' must be positive"));
    prm.leave_subsection();
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
    const FiniteElement<2> &fe = dof_handler.get_fe();
    const MappingQ1<2>      mapping;
    const auto             &unit_points = fe.get_unit_support_points();
    const auto             &face_points = fe.get_unit_face_support_points();

    // Tied nodes: position -> DoF of each component.
    std::map<std::pair<double, double>, std::array<types::global_dof_index, 3>>
                                         nodes;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    const auto                           record = [&](const Point<2>               &x,
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
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (parameters.tie == "material")
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
              for (unsigned int i = 0; i < fe.n_dofs_per_face(); ++i)
                {
                  // Face support points mapped through the straight face.
                  const Point<2> a = cell->face(f)->vertex(0),
                                 b = cell->face(f)->vertex(1);
                  const Point<2> x = a + face_points[i][0] * (b - a);
                  record(x,
                         fe.face_system_to_component_index(i).first,
                         face_dofs[i]);
                }
            }
      }
    AssertThrow(!nodes.empty(),
                ExcMessage("Rigid foundation: no DoFs found on " +
                           parameters.tie + " id " +
                           std::to_string(parameters.id)));

    // Master node: the tied node farthest from the axis whose DoFs are free
    // (r_A > 0 is needed to read the rotation from V_A = -Theta r_A).
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

    const double s      = family_sign(harmonic.family);
    const double r_A    = master_position[0];
    const double z_A    = master_position[1];
    const bool   tie_uw = !parameters.normal_only;
    const auto   tie =
      [&](const types::global_dof_index dof,
          const std::vector<std::pair<types::global_dof_index, double>>
            &entries) {
        if (dof == numbers::invalid_dof_index ||
            constraints.is_constrained(dof))
          return;
        constraints.add_line(dof);
        for (const auto &[master, weight] : entries)
          if (weight != 0.)
            constraints.add_entry(dof, master, weight);
        ++n_tied;
      };

    for (const auto &[x, dofs] : nodes)
      {
        const double r = x.first, z = x.second;
        if (harmonic.n == 1)
          {
            // U_j = U_A + V_A (z_A - z_j) / r_A, W_j = -s U_j,
            // V_j = V_A r_j / r_A.
            if (dofs[1] != master_V)
              tie(dofs[1], {{master_V, r / r_A}});
            if (tie_uw)
              {
                if (dofs[0] != master_U)
                  tie(dofs[0], {{master_U, 1.}, {master_V, (z_A - z) / r_A}});
                tie(dofs[2],
                    {{master_U, -s}, {master_V, -s * (z_A - z) / r_A}});
              }
          }
        else if (harmonic.n == 0 && harmonic.family == Family::symmetric)
          {
            if (dofs[1] != master_V)
              tie(dofs[1], {{master_V, 1.}});
            if (tie_uw)
              tie(dofs[0], {});
          }
        else if (harmonic.n == 0)
          {
            if (tie_uw && dofs[2] != master_W)
              tie(dofs[2], {{master_W, r / r_A}});
          }
        else
          for (unsigned int c = 0; c < 3; ++c)
            if (c == 1 || tie_uw)
              tie(dofs[c], {});
      }
    // Master DoFs that a harmonic does not move are fixed too.
    if (harmonic.n >= 2)
      {
        tie(master_U, {});
        tie(master_V, {});
        tie(master_W, {});
      }
    else if (harmonic.n == 0 && harmonic.family == Family::antisymmetric)
      {
        if (tie_uw)
          {
            tie(master_U, {});
            tie(master_V, {});
          }
      }
    else if (harmonic.n == 0 && tie_uw)
      tie(master_U, {});
  }

  void
  RigidFoundation::add_loads(Vector<double> &rhs) const
  {
    const double r_A = master_position[0];
    const double z_A = master_position[1] - parameters.reference_elevation;
    if (harmonic.n == 1)
      {
        // The antisymmetric family's rigid motion is the symmetric one turned
        // by 90 degrees: translation along y and rotation about -x, so its
        // (H, M) are (H_y, -M_x).
        const bool   symmetric = harmonic.family == Family::symmetric;
        const double H         = symmetric ? parameters.horizontal_force :
                                             parameters.horizontal_force_y;
        const double M = symmetric ? parameters.moment : -parameters.moment_x;
        rhs(master_U) += H;
        rhs(master_V) += (H * z_A - M) / r_A;
      }
    else if (harmonic.n == 0 && harmonic.family == Family::symmetric)
      rhs(master_V) += parameters.vertical_force;
    else if (harmonic.n == 0)
      rhs(master_W) += parameters.torque / r_A;
  }

  RigidMotion
  RigidFoundation::motion(const Vector<double> &solution) const
  {
    RigidMotion  m;
    const double r_A = master_position[0];
    const double z_A = master_position[1] - parameters.reference_elevation;
    if (harmonic.n == 1)
      {
        m.rotation = -solution(master_V) / r_A;
        // With only the normal component tied the translation is not a
        // rigid-body unknown; it stays 0 rather than report a soil value.
        if (!parameters.normal_only)
          m.horizontal_displacement = solution(master_U) - m.rotation * z_A;
      }
    else if (harmonic.n == 0 && harmonic.family == Family::symmetric)
      m.vertical_displacement = solution(master_V);
    else if (harmonic.n == 0)
      m.twist = solution(master_W) / r_A;
    return m;
  }

  Vector<double>
  RigidFoundation::unit_load(const unsigned int load_case,
                             const unsigned int n_dofs) const
  {
    AssertThrow(harmonic.n == 1,
                ExcMessage("Rigid foundation: unit H/M loads need n = 1"));
    Vector<double> rhs(n_dofs);
    const double   r_A = master_position[0];
    const double   z_A = master_position[1] - parameters.reference_elevation;
    const double   H = load_case == 0 ? 1. : 0., M = load_case == 1 ? 1. : 0.;
    rhs(master_U) += H;
    rhs(master_V) += (H * z_A - M) / r_A;
    return rhs;
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
