#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/grid/grid_tools.h>
#include <fourier_ssi/mesh/adaptivity.h>
#include <fourier_ssi/mesh/discretization_design.h>
#include <fourier_ssi/mesh/mesh_builder.h>

namespace FourierSSI
{
  namespace DiscretizationDesign
  {
    namespace
    {
      /** The two ends of an interface line. */
      std::array<Point<2>, 2>
      ends_of(const InterfaceLine &line)
      {
        const auto point = [&](const double t) {
          return line.fixed_coordinate == 0 ? Point<2>(line.value, t) :
                                              Point<2>(t, line.value);
        };
        return {{point(line.from), point(line.to)}};
      }

      /** p is one of `points` (to round-off). */
      bool
      is_among(const Point<2> &p, const std::vector<Point<2>> &points)
      {
        return std::any_of(points.begin(),
                           points.end(),
                           [&](const Point<2> &q) {
                             return q.distance(p) < 1e-9 * (1. + p.norm());
                           });
      }

      /** Every candidate point: line ends, box corners, the patch edge. */
      std::vector<Point<2>>
      candidate_points(const MeshParameters &mesh)
      {
        std::vector<Point<2>> points;
        for (const InterfaceLine &line : mesh.interface_lines)
          for (const Point<2> &end : ends_of(line))
            points.push_back(end);
        std::vector<BoundingBox<2>> boxes = mesh.removed_regions;
        for (const auto &[id, box] : mesh.material_regions)
          boxes.push_back(box);
        for (const BoundingBox<2> &box : boxes)
          for (unsigned int v = 0; v < 4; ++v)
            points.push_back(box.vertex(v));
        if (mesh.surface_patch_radius > 0.)
          points.emplace_back(mesh.surface_patch_radius,
                              mesh.z_breakpoints.back());
        return points;
      }

      /** ks = 0: nothing resists the slip along the interface. */
      bool
      slides_freely(const InterfaceLaw &law)
      {
        return law.kind == InterfaceLaw::Kind::tied_normal ||
               (law.kind == InterfaceLaw::Kind::springs && law.shear == 0.);
      }
    } // namespace

    std::vector<Point<2>>
    singular_points(const MeshParameters &mesh)
    {
      std::vector<Point<2>> points;
      if (mesh.type != MeshType::rectangle)
        return points;
      const double r0        = mesh.r_breakpoints.front(),
                   r1        = mesh.r_breakpoints.back(),
                   z0        = mesh.z_breakpoints.front(),
                   z1        = mesh.z_breakpoints.back();
      const double tolerance = 1e-9 * std::max(r1 - r0, z1 - z0);
      for (const Point<2> &p : candidate_points(mesh))
        {
          // On the axis a corner is not singular (the field is smooth by
          // symmetry); the far boundaries truncate the domain.
          const bool inside = p[0] > r0 + tolerance && p[0] < r1 - tolerance &&
                              p[1] > z0 + tolerance && p[1] < z1 + tolerance;
          const bool known =
            std::any_of(points.begin(), points.end(), [&](const Point<2> &q) {
              return q.distance(p) < tolerance;
            });
          if (inside && !known)
            points.push_back(p);
        }
      return points;
    }

    std::vector<Point<2>>
    slip_wedge_points(const AllParameters &parameters)
    {
      std::vector<Point<2>> ends;
      for (const InterfaceLine &line : parameters.mesh.interface_lines)
        {
          const auto law = parameters.interfaces.laws.find(line.boundary_id);
          if (law == parameters.interfaces.laws.end() ||
              !slides_freely(law->second))
            continue;
          for (const Point<2> &end : ends_of(line))
            ends.push_back(end);
        }
      std::vector<Point<2>> wedges;
      for (const Point<2> &p : singular_points(parameters.mesh))
        if (is_among(p, ends))
          wedges.push_back(p);
      return wedges;
    }

    AdaptivityParameters
    refinements(const AllParameters &parameters, const unsigned int member)
    {
      AdaptivityParameters        design = parameters.adaptivity;
      const std::vector<Point<2>> wedges = slip_wedge_points(parameters);
      for (const Point<2> &p : singular_points(parameters.mesh))
        {
          const unsigned int levels =
            std::min(first_grading_levels + grading_levels_per_member * member +
                       (is_among(p, wedges) ? slip_wedge_extra_levels : 0),
                     AdaptivityParameters::max_point_refinement_levels);
          auto given = std::find_if(design.point_refinements.begin(),
                                    design.point_refinements.end(),
                                    [&](const auto &entry) {
                                      return entry.first.distance(p) <
                                             1e-9 * (1. + p.norm());
                                    });
          if (given == design.point_refinements.end())
            design.point_refinements.emplace_back(p, levels);
          else
            given->second = std::max(given->second, levels);
        }
      bool graded_soil = false;
      for (const auto &[id, material] : parameters.materials.all())
        graded_soil |= material.graded();
      const double top = parameters.mesh.z_breakpoints.back();
      if (graded_soil && parameters.mesh.type == MeshType::rectangle &&
          std::abs(parameters.materials.surface_elevation - top) <
            1e-9 * (1. + std::abs(top)))
        design.layer_refinements.push_back(
          {1,
           parameters.materials.surface_elevation,
           parameters.mesh.r_breakpoints.front(),
           parameters.mesh.r_breakpoints.back(),
           first_surface_layers + member});
      return design;
    }

    void
    build_member(const AllParameters                &parameters,
                 const unsigned int                  member,
                 const std::set<types::boundary_id> &interface_ids,
                 Triangulation<2>                   &triangulation)
    {
      // The design replaces Mesh/Global refinements: member k is the
      // coarse mesh refined k times (a scene refined for a one-mesh run
      // would make every member 4x dearer).
      MeshParameters mesh     = parameters.mesh;
      mesh.global_refinements = member;
      build_mesh(mesh, triangulation);
      refine_a_priori(triangulation,
                      refinements(parameters, member),
                      interface_ids);
    }

    bool
    is_one_cell_slice(const MeshParameters &mesh)
    {
      unsigned int z_cells = 0;
      for (const unsigned int c : mesh.z_cells)
        z_cells += c;
      return mesh.type == MeshType::rectangle && z_cells == 1 &&
             mesh.global_refinements == 0;
    }

    void
    build_plastic_member(const AllParameters                &parameters,
                         const unsigned int                  member,
                         const std::set<types::boundary_id> &interface_ids,
                         Triangulation<2>                   &triangulation)
    {
      MeshParameters     mesh   = parameters.mesh;
      const unsigned int split  = 1u << member;
      const auto         refine = [&](std::vector<unsigned int> &cells,
                              std::vector<double>       &growth) {
        for (unsigned int &c : cells)
          c *= split;
        for (double &g : growth)
          g = std::pow(g, 1. / split);
      };
      if (mesh.type == MeshType::rectangle)
        {
          refine(mesh.r_cells, mesh.r_growth);
          if (!is_one_cell_slice(mesh))
            refine(mesh.z_cells, mesh.z_growth);
        }
      else
        mesh.global_refinements += member;
      triangulation.clear();
      build_mesh(mesh, triangulation);
      refine_a_priori(triangulation, parameters.adaptivity, interface_ids);
    }

    bool
    coarsen_once(Triangulation<2>                   &triangulation,
                 const std::set<types::boundary_id> &interface_ids)
    {
      bool any = false;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->level() > 0)
          {
            const auto parent     = cell->parent();
            bool       all_active = true;
            for (unsigned int c = 0; c < parent->n_children(); ++c)
              all_active &= parent->child(c)->is_active();
            if (all_active)
              {
                cell->set_coarsen_flag();
                any = true;
              }
          }
      if (any)
        // Both sides of an interface have the same refinement history, so
        // they are coarsened alike; the pairing of the solve checks it.
        execute_refinement_keeping_interface_twins(triangulation,
                                                   interface_ids);
      return any;
    }
  } // namespace DiscretizationDesign
} // namespace FourierSSI
