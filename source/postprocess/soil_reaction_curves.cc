#include <algorithm>
#include <cmath>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/soil_reaction_curves.h>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Output/Soil reaction depths";

    /** Coordinates closer than this (relative to the pile) are one. */
    double
    tolerance(const double length)
    {
      return 1e-9 * length;
    }

    std::pair<double, double>
    key_of(const Point<2> &x)
    {
      return {x[0], x[1]};
    }
  } // namespace

  SoilReactionCurves::SoilReactionCurves(const DoFHandler<2> &dofs,
                                         const AllParameters &parameters)
    : parameters(parameters)
    , pile_id(parameters.output.soil_reaction_pile >= 0 ?
                parameters.output.soil_reaction_pile :
                parameters.rigid_foundation.id)
    , line_fe(dofs.get_fe().degree)
  {
    // The loads reach the pile through the Rigid foundation's tied
    // material (the pile itself, or a ring on a flexible pile's head).
    AssertThrow(parameters.rigid_foundation.enabled &&
                  parameters.rigid_foundation.tie == FoundationTie::material,
                ExcMessage(entry + ": needs a Rigid foundation with Tie = "
                                   "material (the pile, or a ring on its "
                                   "head that carries the loads)"));
    rigid_pile = pile_id == parameters.rigid_foundation.id;
    find_pile(dofs.get_triangulation());
    find_touching_cells(dofs.get_triangulation());
    make_shaft_line(dofs);
    map_shaft_nodes(dofs);
    if (!rigid_pile)
      make_section_weights(dofs);
    choose_depths();
  }

  void
  SoilReactionCurves::find_pile(const Triangulation<2> &triangulation)
  {
    double r_min = std::numeric_limits<double>::max();
    top          = -std::numeric_limits<double>::max();
    toe          = std::numeric_limits<double>::max();
    bool   found = false;
    double area  = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->material_id() == pile_id)
        {
          area += cell->measure();
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<2> &x = cell->vertex(v);
              found             = true;
              r_min             = std::min(r_min, x[0]);
              pile_radius       = std::max(pile_radius, x[0]);
              top               = std::max(top, x[1]);
              toe               = std::min(toe, x[1]);
            }
        }
    AssertThrow(found,
                ExcMessage(entry + ": no cell of the pile's material " +
                           std::to_string(pile_id) +
                           " (Output/Soil reaction pile, or the Rigid "
                           "foundation's Id)"));
    hollow      = r_min > tolerance(top - toe);
    bore_radius = hollow ? r_min : 0.;
    // Its cells fill the rectangle r_i <= r <= R, toe <= z <= top (a
    // solid cylinder or a tube's wall), else the outline below is wrong.
    const double box = (pile_radius - bore_radius) * (top - toe);
    AssertThrow(std::abs(area - box) <= 1e-9 * box,
                ExcMessage(entry + ": not yet for a pile whose material " +
                           std::to_string(pile_id) +
                           " is not one rectangle in (r, z) (a solid "
                           "cylinder or a tube's wall)"));
  }

  bool
  SoilReactionCurves::on_outline(const Point<2> &x) const
  {
    // The outer face r = R, a tube's inner face r = r_i, and the base
    // z = toe (the disc r <= R, or the annulus r_i <= r <= R).
    const double tol     = tolerance(top - toe);
    const bool   on_span = x[1] >= toe - tol && x[1] <= top + tol;
    return (std::abs(x[0] - pile_radius) <= tol && on_span) ||
           (hollow && std::abs(x[0] - bore_radius) <= tol && on_span) ||
           (std::abs(x[1] - toe) <= tol && x[0] <= pile_radius + tol &&
            x[0] >= bore_radius - tol);
  }

  void
  SoilReactionCurves::find_touching_cells(const Triangulation<2> &triangulation)
  {
    // A soil cell touches the pile if one of its vertices lies on the
    // pile's outline (on_outline). The tied material of a flexible pile
    // carries the loads to it: soil touching that material elsewhere
    // would take a share the curves miss.
    const types::material_id            tied = parameters.rigid_foundation.id;
    std::set<std::pair<double, double>> tied_vertices;
    if (!rigid_pile)
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->material_id() == tied)
          for (const unsigned int v : cell->vertex_indices())
            tied_vertices.insert(key_of(cell->vertex(v)));
    const auto &laws = parameters.soil_plasticity.laws;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (cell->material_id() == pile_id || cell->material_id() == tied)
          continue;
        bool touches = false;
        for (const unsigned int v : cell->vertex_indices())
          {
            const bool on_pile = on_outline(cell->vertex(v));
            AssertThrow(on_pile ||
                          tied_vertices.count(key_of(cell->vertex(v))) == 0,
                        ExcMessage(entry +
                                   ": not yet with soil touching "
                                   "the Rigid foundation's material "
                                   "of a flexible pile (material " +
                                   std::to_string(cell->material_id()) + ")"));
            touches = touches || on_pile;
          }
        if (!touches)
          continue;
        const Point<2> c = cell->center();
        AssertThrow(laws.count(cell->material_id()) == 1,
                    ExcMessage(entry +
                               ": not yet with elastic soil next to "
                               "the pile (material " +
                               std::to_string(cell->material_id()) +
                               " has no Soil plasticity/Laws entry)"));
        AssertThrow(c[1] < top,
                    ExcMessage(entry + ": not yet with soil above the "
                                       "pile's head touching it"));
        // The base is the soil under the pile's footprint (a tube's: the
        // annulus r_i < r < R); the cell diagonal to the corner (r > R,
        // z < toe) flows around the tip with the shaft's soil, so it joins
        // the shaft (its force at the corner node is the shaft's p at the
        // toe); under a tube, the plug's base (r < r_i) is not the pile's
        // and the cell diagonal to the inner corner joins the inner face.
        if (c[1] < toe && c[0] < pile_radius && c[0] > bore_radius)
          base_cells[key_of(c)] = cell->material_id();
        else
          shaft_cells[key_of(c)] = cell->material_id();
      }
  }

  bool
  SoilReactionCurves::beside_shaft(const Point<2> &cell_centre) const
  {
    return shaft_cells.count(key_of(cell_centre)) == 1;
  }

  bool
  SoilReactionCurves::below_base(const Point<2> &cell_centre) const
  {
    return base_cells.count(key_of(cell_centre)) == 1;
  }

  void
  SoilReactionCurves::make_shaft_line(const DoFHandler<2> &dofs)
  {
    const double tol = tolerance(top - toe);
    // The shaft line's vertices: the ends of the faces of the soil cells
    // beside it that lie on r = R (and on a tube's inner face r = r_i).
    const auto on_face = [&](const Point<2> &x) {
      return std::abs(x[0] - pile_radius) <= tol ||
             (hollow && std::abs(x[0] - bore_radius) <= tol);
    };
    std::vector<double> z;
    for (const auto &cell : dofs.active_cell_iterators())
      if (beside_shaft(cell->center()))
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (on_face(face->vertex(0)) && on_face(face->vertex(1)) &&
                std::abs(face->vertex(0)[0] - face->vertex(1)[0]) <= tol &&
                face->center()[1] > toe)
              for (const unsigned int v : {0u, 1u})
                z.push_back(face->vertex(v)[1]);
          }
    std::sort(z.begin(), z.end());
    vertex_z.clear();
    for (const double x : z)
      if (vertex_z.empty() || x - vertex_z.back() > tol)
        vertex_z.push_back(x);
    AssertThrow(vertex_z.size() >= 2 &&
                  std::abs(vertex_z.front() - toe) <= tol &&
                  std::abs(vertex_z.back() - top) <= tol,
                ExcMessage(entry + ": the soil beside the pile does not "
                                   "cover its shaft"));
    // The line mesh and its mass matrix (dense: one pile, tens of nodes).
    std::vector<Point<1>>    vertices;
    std::vector<CellData<1>> line_cells;
    for (const double x : vertex_z)
      vertices.emplace_back(x);
    for (unsigned int i = 0; i + 1 < vertex_z.size(); ++i)
      {
        CellData<1> c;
        c.vertices = {i, i + 1};
        line_cells.push_back(c);
      }
    line_mesh.create_triangulation(vertices, line_cells, SubCellData());
    line_dofs.reinit(line_mesh);
    line_dofs.distribute_dofs(line_fe);
    const unsigned int                   n = line_dofs.n_dofs();
    FullMatrix<double>                   mass(n, n);
    FEValues<1>                          values(line_fe,
                       QGauss<1>(line_fe.degree + 1),
                       update_values | update_JxW_values);
    std::vector<types::global_dof_index> indices(line_fe.n_dofs_per_cell());
    for (const auto &cell : line_dofs.active_cell_iterators())
      {
        values.reinit(cell);
        cell->get_dof_indices(indices);
        for (const unsigned int q : values.quadrature_point_indices())
          for (unsigned int i = 0; i < indices.size(); ++i)
            for (unsigned int j = 0; j < indices.size(); ++j)
              mass(indices[i], indices[j]) += values.shape_value(i, q) *
                                              values.shape_value(j, q) *
                                              values.JxW(q);
      }
    inverse_mass.reinit(n, n);
    inverse_mass.invert(mass);
  }

  std::vector<Point<1>>
  SoilReactionCurves::line_support_points() const
  {
    std::vector<Point<1>> points(line_dofs.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ1<1>(), line_dofs, points);
    return points;
  }

  void
  SoilReactionCurves::map_shaft_nodes(const DoFHandler<2> &dofs)
  {
    // Each DoF of the harmonic's field: its place on the line or the base.
    const double                tol         = tolerance(top - toe);
    const unsigned int          n           = line_dofs.n_dofs();
    const std::vector<Point<1>> line_points = line_support_points();
    std::vector<Point<2>>       points(dofs.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dofs, points);
    line_dof_of.assign(dofs.n_dofs(), -1);
    on_base.assign(dofs.n_dofs(), 0);
    on_outer_face.assign(dofs.n_dofs(), 0);
    dof_radius.resize(dofs.n_dofs());
    dof_component.resize(dofs.n_dofs());
    std::vector<types::global_dof_index> cell_dofs(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(cell_dofs);
        for (unsigned int i = 0; i < cell_dofs.size(); ++i)
          dof_component[cell_dofs[i]] =
            dofs.get_fe().system_to_component_index(i).first;
      }
    for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
      {
        const Point<2> &x = points[i];
        dof_radius[i]     = x[0];
        on_base[i] = std::abs(x[1] - toe) <= tol && x[0] <= pile_radius + tol &&
                         x[0] >= bore_radius - tol ?
                       1 :
                       0;
        const bool outer = std::abs(x[0] - pile_radius) <= tol;
        const bool inner = hollow && std::abs(x[0] - bore_radius) <= tol;
        on_outer_face[i] = outer ? 1 : 0;
        if (!(outer || inner) || x[1] < toe - tol || x[1] > top + tol)
          continue;
        for (unsigned int k = 0; k < n; ++k)
          if (std::abs(line_points[k][0] - x[1]) <= tol)
            line_dof_of[i] = k;
        AssertThrow(line_dof_of[i] >= 0,
                    ExcMessage(entry + ": a node of the shaft is not a node "
                                       "of its line (curved cells?)"));
      }
  }

  void
  SoilReactionCurves::make_section_weights(const DoFHandler<2> &dofs)
  {
    // The section integrals of section_motion at the elevation of each
    // line DoF, by Gauss points in r across each cell of the wall that
    // spans that elevation (each column of cells once); the cells must be
    // axis-parallel rectangles, so that the points lie on one elevation.
    const double                tol         = tolerance(top - toe);
    const unsigned int          n           = line_dofs.n_dofs();
    const std::vector<Point<1>> line_points = line_support_points();
    const FiniteElement<2>     &fe          = dofs.get_fe();
    const QGauss<1>             gauss(fe.degree + 2);
    const double                area_moment = // int r dr over the wall
      (pile_radius * pile_radius - bore_radius * bore_radius) / 2.;
    const double inertia_moment = // int r^3 dr over the wall
      (std::pow(pile_radius, 4) - std::pow(bore_radius, 4)) / 4.;
    const MappingQ1<2>                        mapping;
    std::vector<types::global_dof_index>      cell_dofs(fe.n_dofs_per_cell());
    std::set<std::pair<unsigned int, double>> done; // (line DoF, column r)
    section_weights.assign(n, {});
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if (cell->material_id() != pile_id)
          continue;
        const BoundingBox<2> box = cell->bounding_box();
        const Point<2>       low = box.get_boundary_points().first,
                       high      = box.get_boundary_points().second;
        AssertThrow(std::abs(cell->measure() - box.volume()) <=
                      1e-9 * box.volume(),
                    ExcMessage(entry + ": not yet for a flexible pile "
                                       "whose cells are not rectangles "
                                       "parallel to r and z"));
        cell->get_dof_indices(cell_dofs);
        for (unsigned int k = 0; k < n; ++k)
          {
            const double z = line_points[k][0];
            if (z < low[1] - tol || z > high[1] + tol ||
                !done.insert({k, low[0]}).second)
              continue;
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                const double   width = high[0] - low[0];
                const double   r     = low[0] + gauss.point(q)[0] * width;
                const double   w     = gauss.weight(q) * width;
                const Point<2> unit =
                  mapping.transform_real_to_unit_cell(cell, Point<2>(r, z));
                for (unsigned int i = 0; i < cell_dofs.size(); ++i)
                  {
                    const unsigned int c =
                      fe.system_to_component_index(i).first;
                    const double phi = fe.shape_value(i, unit);
                    // v = int (U - W)/2 r dr / int r dr;
                    // psi = -int V r^2 dr / int r^3 dr (section_motion).
                    const double in_v   = c == 0 ? 0.5 : (c == 2 ? -0.5 : 0.);
                    const double in_psi = c == 1 ? -1. : 0.;
                    if (in_v != 0. || in_psi != 0.)
                      section_weights[k].emplace_back(cell_dofs[i],
                                                      in_v * phi * r * w /
                                                        area_moment,
                                                      in_psi * phi * r * r * w /
                                                        inertia_moment);
                  }
              }
          }
      }
  }

  void
  SoilReactionCurves::section_motion(const Vector<double> &u, Step &step) const
  {
    // The n = 1 symmetric amplitudes: u_r = U cos(theta), u_z = V
    // cos(theta), u_theta = W sin(theta), so u_x = U cos^2 - W sin^2.
    // v is the mean of u_x over the section (its centroid's motion, the
    // work conjugate of a lateral load spread over it):
    //   v = int int u_x r dr dtheta / A = int (U - W)/2 r dr / int r dr;
    // psi is the plane section's rotation about +y that fits u_z best,
    // u_z ~ -psi x (the rigid rotation's u_z = -Theta x), least squares
    // over the section (the work conjugate of the bending moment):
    //   psi = -int int u_z x dA / int int x^2 dA
    //       = -int V r^2 dr / int r^3 dr.
    // Both give v = U_h + Theta (z - z_ref) and psi = Theta for a rigid
    // motion, and the mid-wall values to O(t/R) for a thin tube; the
    // ovalisation (U + W) does not enter v.
    const unsigned int n = line_dofs.n_dofs();
    step.v.reinit(n);
    step.psi.reinit(n);
    for (unsigned int k = 0; k < n; ++k)
      for (const auto &[dof, in_v, in_psi] : section_weights[k])
        {
          step.v(k) += in_v * u(dof);
          step.psi(k) += in_psi * u(dof);
        }
  }

  void
  SoilReactionCurves::choose_depths()
  {
    const double length = top - toe;
    const auto  &output = parameters.output;
    if (output.soil_reaction_auto > 0)
      {
        // Evenly spaced, at the middles of n equal parts of the shaft: the
        // head and the toe, where the reaction has its corners, are not
        // sampled.
        const unsigned int n = output.soil_reaction_auto;
        for (unsigned int i = 0; i < n; ++i)
          curve_depths.push_back((i + 0.5) * length / n);
        return;
      }
    for (const double d : output.soil_reaction_depths)
      {
        std::ostringstream message;
        message << entry << ": depth " << d
                << " m lies outside the pile's shaft (0 to " << length
                << " m below its head)";
        AssertThrow(d >= 0. && d <= length * (1. + 1e-12),
                    ExcMessage(message.str()));
        curve_depths.push_back(d);
      }
  }

  void
  SoilReactionCurves::record(const Vector<double> &shaft_force,
                             const Vector<double> &base_force,
                             const Vector<double> &displacement,
                             const RigidMotion    &motion,
                             const double          applied_H,
                             const double          applied_M)
  {
    // The work of the nodal forces on the rigid modes, node by node:
    // P = f_U - f_W (u_x = 1: U = 1, W = -1 for n = 1 symmetric) and
    // Q = -f_V r (a rotation about y through the node's level: V = -r).
    // The same works hold for a flexible body: its internal forces do no
    // work on a rigid mode, so the sums balance the loads on its head.
    const unsigned int n = line_dofs.n_dofs();
    Vector<double>     P(n), Q(n), P_outer(n), Q_outer(n);
    Step               step;
    step.applied_H = applied_H;
    step.applied_M = applied_M;
    step.motion    = motion;
    for (unsigned int i = 0; i < shaft_force.size(); ++i)
      {
        const unsigned int c      = dof_component[i];
        const double       work_x = c == 0 ? 1. : (c == 2 ? -1. : 0.);
        const double       work_y = c == 1 ? -dof_radius[i] : 0.;
        if (line_dof_of[i] >= 0)
          {
            P(line_dof_of[i]) += work_x * shaft_force(i);
            Q(line_dof_of[i]) += work_y * shaft_force(i);
            if (on_outer_face[i])
              {
                P_outer(line_dof_of[i]) += work_x * shaft_force(i);
                Q_outer(line_dof_of[i]) += work_y * shaft_force(i);
              }
          }
        if (on_base[i])
          {
            step.base_shear += work_x * base_force(i);
            step.base_moment += work_y * base_force(i);
          }
      }
    // The line's fields whose consistent nodal loads are P and Q.
    step.p.reinit(n);
    step.m.reinit(n);
    inverse_mass.vmult(step.p, P);
    inverse_mass.vmult(step.m, Q);
    if (hollow)
      {
        step.p_outer.reinit(n);
        step.m_outer.reinit(n);
        inverse_mass.vmult(step.p_outer, P_outer);
        inverse_mass.vmult(step.m_outer, Q_outer);
      }
    if (!rigid_pile)
      section_motion(displacement, step);
    steps.push_back(std::move(step));
  }

  double
  SoilReactionCurves::line_value(const Vector<double> &values,
                                 const double          z) const
  {
    const double clamped = std::min(top, std::max(toe, z));
    return VectorTools::point_value(line_dofs, values, Point<1>(clamped));
  }

  std::pair<double, double>
  SoilReactionCurves::shaft_reaction(const unsigned int step,
                                     const double       z) const
  {
    return {line_value(steps[step].p, z), line_value(steps[step].m, z)};
  }

  std::pair<double, double>
  SoilReactionCurves::outer_face_reaction(const unsigned int step,
                                          const double       z) const
  {
    if (!hollow)
      return shaft_reaction(step, z);
    return {line_value(steps[step].p_outer, z),
            line_value(steps[step].m_outer, z)};
  }

  std::pair<double, double>
  SoilReactionCurves::base_reaction(const unsigned int step) const
  {
    return {steps[step].base_shear, steps[step].base_moment};
  }

  double
  SoilReactionCurves::displacement(const unsigned int step,
                                   const double       z) const
  {
    if (!rigid_pile)
      return line_value(steps[step].v, z);
    // The rigid motion: U = U_h + Theta (z - z_ref) (rigid_foundation.h).
    const RigidMotion &m = steps[step].motion;
    return m.horizontal_displacement +
           m.rotation * (z - parameters.rigid_foundation.reference_elevation);
  }

  double
  SoilReactionCurves::rotation(const unsigned int step, const double z) const
  {
    return rigid_pile ? steps[step].motion.rotation :
                        line_value(steps[step].psi, z);
  }

  std::pair<double, double>
  SoilReactionCurves::largest_imbalance() const
  {
    const double    z_ref = parameters.rigid_foundation.reference_elevation;
    const QGauss<1> gauss(line_fe.degree + 2);
    std::pair<double, double> largest = {0., 0.};
    for (unsigned int s = 0; s < steps.size(); ++s)
      {
        double force = 0., moment = 0.;
        for (unsigned int c = 0; c + 1 < vertex_z.size(); ++c)
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double h    = vertex_z[c + 1] - vertex_z[c];
              const double z    = vertex_z[c] + gauss.point(q)[0] * h;
              const auto [p, m] = shaft_reaction(s, z);
              force += p * gauss.weight(q) * h;
              moment += (m + p * (z - z_ref)) * gauss.weight(q) * h;
            }
        const Step  &step = steps[s];
        const double H    = std::abs(step.applied_H);
        if (H == 0.)
          continue;
        force += step.base_shear - step.applied_H;
        moment +=
          step.base_moment + step.base_shear * (toe - z_ref) - step.applied_M;
        largest.first = std::max(largest.first, std::abs(force) / H);
        largest.second =
          std::max(largest.second, std::abs(moment) / (H * (top - toe)));
      }
    return largest;
  }

  SoilReactionCurves::Normalisation
  SoilReactionCurves::normalisation_at(const double z, const bool base) const
  {
    // The soil cell touching the pile at that level (beside the shaft, or
    // under the base's centre for the base).
    types::material_id id       = 0;
    double             distance = std::numeric_limits<double>::max();
    for (const auto &[centre, material] : base ? base_cells : shaft_cells)
      {
        const double d = base ? centre.first : std::abs(centre.second - z);
        if (d < distance)
          {
            distance = d;
            id       = material;
          }
      }
    const double   depth = parameters.materials.depth(z);
    const SoilLaw &law   = parameters.soil_plasticity.laws.at(id);
    Normalisation  result;
    result.shear_modulus = parameters.materials.get(id).shear_modulus(depth);
    // Undrained laws (Tresca, iwan) normalise by s_u, drained ones by
    // sigma'_v (the PISA clay and sand forms).
    result.clay     = !law.frictional();
    result.strength = result.clay ?
                        law.undrained_strength(depth) :
                        parameters.initial_stress.vertical_stress(depth);
    return result;
  }

  void
  SoilReactionCurves::write_row(std::ostream      &out,
                                const Step        &step,
                                const unsigned int s,
                                const double       depth) const
  {
    const double z = top - depth, D = 2. * pile_radius;
    const auto [p, m]      = shaft_reaction(s, z);
    const double  v        = displacement(s, z);
    const double  psi      = rotation(s, z);
    const double  psi_base = rotation(s, toe);
    Normalisation n        = normalisation_at(z, false);
    Normalisation b        = normalisation_at(toe, true);
    // PISA: clay p/(s_u D), v G/(s_u D), m/(s_u D^2), psi G/s_u (Byrne et
    // al. 2020); sand p/(sigma'_v D), v G/(sigma'_v D), m/(|p| D), psi
    // G/sigma'_v (Burd et al. 2020); the base H_B/(s D^2), M_B/(s D^3).
    // A ratio by zero (sigma'_v at the mudline, p = 0) is an empty field.
    const auto ratio = [&](const double x, const double by) {
      std::ostringstream field;
      field << std::setprecision(out.precision());
      if (by > 0.)
        field << x / by;
      return field.str();
    };
    const double v_base = displacement(s, toe);
    out << s + 1 << ',' << step.applied_H << ',' << step.applied_M << ','
        << depth << ',' << z << ',' << v << ',' << p << ',' << psi << ',' << m
        << ',' << v_base << ',' << step.base_shear << ',' << step.base_moment
        << ',' << (n.clay ? "s_u" : "sigma'_v") << ',' << n.strength << ','
        << n.shear_modulus << ',' << ratio(p, n.strength * D) << ','
        << ratio(v * n.shear_modulus, n.strength * D) << ','
        << (n.clay ? ratio(m, n.strength * D * D) : ratio(m, std::abs(p) * D))
        << ',' << ratio(psi * n.shear_modulus, n.strength) << ',' << b.strength
        << ',' << ratio(step.base_shear, b.strength * D * D) << ','
        << ratio(v_base * b.shear_modulus, b.strength * D) << ','
        << ratio(step.base_moment, b.strength * D * D * D) << ','
        << ratio(psi_base * b.shear_modulus, b.strength);
    if (!rigid_pile || hollow)
      {
        const auto [p_outer, m_outer] = outer_face_reaction(s, z);
        out << ',' << psi_base << ',' << p_outer << ',' << p - p_outer << ','
            << m_outer << ',' << m - m_outer;
      }
    out << '\n';
  }

  void
  SoilReactionCurves::add_result_rows(ResultsTable &results) const
  {
    const Harmonic any{0, Family::symmetric};
    const double   D = 2. * pile_radius;
    for (const double depth : curve_depths)
      {
        const double        z = top - depth;
        const Normalisation n = normalisation_at(z, false);
        std::ostringstream  at;
        at << "_at_" << depth << "m";
        if (steps.empty())
          continue;
        // The curve's end and its initial slope: the whole curve is in
        // soil-reaction-curves.csv.
        // Neither is defined where its normaliser is zero (sigma'_v at the
        // mudline, a level that has not moved): no row then.
        const unsigned int last     = steps.size() - 1;
        const double       strength = n.strength * D;
        const double       moved    = n.shear_modulus * displacement(0, z);
        if (strength > 0.)
          results.add("soil_reaction_p_normalised" + at.str(),
                      any,
                      last + 1,
                      shaft_reaction(last, z).first / strength,
                      "-");
        if (moved != 0.)
          results.add("soil_reaction_secant" + at.str(),
                      any,
                      1,
                      shaft_reaction(0, z).first / moved,
                      "-");
      }
  }

  void
  SoilReactionCurves::write_csv(const std::string &filename) const
  {
    AtomicFile file(filename);
    auto      &out = file.stream();
    out << std::setprecision(10)
        << "step,H [kN],M [kN m],depth [m],z [m],v [m],p [kN/m],psi [rad],"
           "m [kN m/m],v_base [m],H_B [kN],M_B [kN m],normalised by,"
           "s [kPa],G [kPa],p/(s D) [-],v G/(s D) [-],m/(s D^2) or "
           "m/(|p| D) [-],psi G/s [-],s_base [kPa],H_B/(s D^2) [-],"
           "v_base G/(s D) [-],M_B/(s D^3) [-],psi G/s_base [-]";
    // A tube or a flexible pile: the base's own rotation and the faces'
    // shares (the plug's is the inner face's).
    if (!rigid_pile || hollow)
      out << ",psi_base [rad],p outer face [kN/m],p inner face [kN/m],"
             "m outer face [kN m/m],m inner face [kN m/m]";
    out << '\n';
    for (unsigned int s = 0; s < steps.size(); ++s)
      for (const double depth : curve_depths)
        write_row(out, steps[s], s, depth);
    file.commit();
  }
} // namespace FourierSSI
