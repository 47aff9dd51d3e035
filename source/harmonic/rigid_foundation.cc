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
