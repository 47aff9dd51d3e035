#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/error_estimator.h>
#include <fourier_ssi/mesh/adaptivity.h>
#include <fourier_ssi/mesh/coordinate_tolerance.h>
#include <map>
#include <sstream>

namespace FourierSSI
{
  RefinementIndicator::RefinementIndicator(
    const Triangulation<2> &triangulation)
    : indicators(triangulation.n_active_cells())
  {}

  void
  RefinementIndicator::add_kelly(const DoFHandler<2>  &dof_handler,
                                 const Vector<double> &solution)
  {
    Vector<float> kelly(indicators.size());
    // Interface faces are boundary faces of the mesh: no jump across them
    // is counted, as it should (the interface allows a jump).
    KellyErrorEstimator<2>::estimate(dof_handler,
                                     QGauss<1>(dof_handler.get_fe().degree + 1),
                                     {},
                                     solution,
                                     kelly);
    const double norm = kelly.l2_norm();
    if (norm > 0.)
      for (unsigned int i = 0; i < kelly.size(); ++i)
        indicators(i) += kelly(i) / norm;
  }

  void
  RefinementIndicator::add(const Vector<float> &cell_indicators)
  {
    AssertDimension(cell_indicators.size(), indicators.size());
    indicators += cell_indicators;
  }

  void
  RefinementIndicator::refine(Triangulation<2>                   &triangulation,
                              const double                        fraction,
                              const std::set<types::boundary_id> &interface_ids,
                              const RefinementCase<2>             cut) const
  {
    GridRefinement::refine_and_coarsen_fixed_fraction(triangulation,
                                                      indicators,
                                                      fraction,
                                                      0.);
    if (cut != RefinementCase<2>::isotropic_refinement)
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->refine_flag_set())
          cell->set_refine_flag(cut);
    execute_refinement_keeping_interface_twins(triangulation, interface_ids);
  }

  void
  execute_refinement_keeping_interface_twins(
    Triangulation<2>                   &triangulation,
    const std::set<types::boundary_id> &interface_ids)
  {
    // Twin interface faces, matched by their centres (rounded to a grid far
    // below the smallest face length).
    std::map<std::pair<long long, long long>,
             std::vector<
               std::pair<Triangulation<2>::active_cell_iterator, unsigned int>>>
                 cells_at_face;
    const double scale = 1e-9 * GridTools::minimal_cell_diameter(triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            interface_ids.count(cell->face(f)->boundary_id()))
          cells_at_face[{std::llround(cell->face(f)->center()[0] / scale),
                         std::llround(cell->face(f)->center()[1] / scale)}]
            .emplace_back(cell, f);
    // A cell's cut splits its face f if it cuts across the face: faces 0, 1
    // (normal r) by cut_y, faces 2, 3 (normal z) by cut_x.
    const auto splits_face = [](const RefinementCase<2> cut,
                                const unsigned int      f) {
      const RefinementCase<2> across(f < 2 ? RefinementCase<2>::cut_y :
                                             RefinementCase<2>::cut_x);
      return (cut & across) !=
             RefinementCase<2>(RefinementCase<2>::no_refinement);
    };
    // Mesh smoothing (2:1 rule) may flag more cells: repeat until the two
    // sides of every interface agree.
    for (bool changed = true; changed;)
      {
        triangulation.prepare_coarsening_and_refinement();
        changed = false;
        for (auto &[key, cells] : cells_at_face)
          {
            bool split = false;
            for (const auto &[cell, f] : cells)
              split |= splits_face(cell->refine_flag_set(), f);
            if (split)
              for (const auto &[cell, f] : cells)
                if (!cell->refine_flag_set())
                  {
                    cell->set_refine_flag();
                    changed = true;
                  }
          }
      }
    triangulation.execute_coarsening_and_refinement();
  }

  void
  refine_toward_points(
    Triangulation<2>                                     &triangulation,
    const std::vector<std::pair<Point<2>, unsigned int>> &point_refinements,
    const std::set<types::boundary_id>                   &interface_ids)
  {
    unsigned int max_levels = 0;
    for (const auto &[point, levels] : point_refinements)
      max_levels = std::max(max_levels, levels);
    // The vertex coordinates carry the round-off of the mesh's extent: on
    // a domain of 3e4 m a vertex at r = 1 m is off by more than 1e-6 of
    // the smallest cell (coordinate_tolerance.h).
    const auto corners =
      GridTools::compute_bounding_box(triangulation).get_boundary_points();
    const double extent = std::max(corners.first.norm(), corners.second.norm());
    for (unsigned int pass = 0; pass < max_levels; ++pass)
      {
        const double tolerance =
          coincidence_tolerance(1e-6,
                                GridTools::minimal_cell_diameter(triangulation),
                                extent);
        for (const auto &[point, levels] : point_refinements)
          {
            if (pass >= levels)
              continue;
            bool touched = false;
            for (const auto &cell : triangulation.active_cell_iterators())
              for (const unsigned int v : cell->vertex_indices())
                if (cell->vertex(v).distance(point) < tolerance)
                  {
                    cell->set_refine_flag();
                    touched = true;
                  }
            AssertThrow(touched,
                        ExcMessage("Adaptivity/Point refinement: no mesh "
                                   "vertex at (" +
                                   std::to_string(point[0]) + ", " +
                                   std::to_string(point[1]) + ")"));
          }
        execute_refinement_keeping_interface_twins(triangulation,
                                                   interface_ids);
      }
  }

  namespace
  {
    /** "r = r0 .. r1, z = z0 .. z1 m" */
    std::string
    extent_of(const BoundingBox<2> &box)
    {
      const auto        &corners = box.get_boundary_points();
      std::ostringstream text;
      text << "r = " << corners.first[0] << " .. " << corners.second[0]
           << ", z = " << corners.first[1] << " .. " << corners.second[1]
           << " m";
      return text.str();
    }
  } // namespace

  void
  refine_a_priori(Triangulation<2>                   &triangulation,
                  const AdaptivityParameters         &parameters,
                  const std::set<types::boundary_id> &interface_ids)
  {
    for (const auto &[box, levels] : parameters.box_refinements)
      for (unsigned int pass = 0; pass < levels; ++pass)
        {
          bool touched = false;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (box.point_inside(cell->center()))
              {
                cell->set_refine_flag();
                touched = true;
              }
          // A box off the mesh, or smaller than the cells it lies in,
          // would refine nothing: say so rather than run the coarse mesh.
          AssertThrow(touched,
                      ExcMessage("Adaptivity/Box refinement: no cell centre "
                                 "lies in the box " +
                                 extent_of(box) +
                                 ", so it refines nothing; move it onto the "
                                 "mesh or enlarge it"));
          execute_refinement_keeping_interface_twins(triangulation,
                                                     interface_ids);
        }
    refine_toward_points(triangulation,
                         parameters.point_refinements,
                         interface_ids);
    for (const auto &layer : parameters.layer_refinements)
      {
        const unsigned int fixed = layer.fixed_coordinate, along = 1 - fixed;
        // A cut across a line z = c halves the cell in z (cut_y).
        const RefinementCase<2> across =
          fixed == 1 ? RefinementCase<2>::cut_y : RefinementCase<2>::cut_x;
        bool touched = false;
        for (unsigned int pass = 0; pass < layer.levels; ++pass)
          {
            for (const auto &cell : triangulation.active_cell_iterators())
              for (const auto &face : cell->face_iterators())
                {
                  // Relative to the face itself: a tolerance from the
                  // smallest cell of a mesh graded 24 levels deep (1e-6 of
                  // 2^-24 of a cell) fell below the round-off of the
                  // surface's own coordinates, and no face was found.
                  const double   tolerance = 1e-6 * face->diameter();
                  const Point<2> c         = face->center();
                  if (std::abs(face->vertex(0)[fixed] - layer.value) >
                        tolerance ||
                      std::abs(face->vertex(1)[fixed] - layer.value) >
                        tolerance ||
                      c[along] < layer.from || c[along] > layer.to)
                    continue;
                  touched = true;
                  // Only cells wider along the line than across it: the
                  // layer thins geometrically, square (graded) cells stay.
                  if (cell->extent_in_direction(along) >
                      1.01 * cell->extent_in_direction(fixed))
                    cell->set_refine_flag(across);
                }
            execute_refinement_keeping_interface_twins(triangulation,
                                                       interface_ids);
          }
        AssertThrow(touched || layer.levels == 0,
                    ExcMessage("Adaptivity/Layer refinement: no cell face on "
                               "the segment " +
                               std::string(fixed == 0 ? "r" : "z") + " = " +
                               std::to_string(layer.value)));
      }
  }
} // namespace FourierSSI
