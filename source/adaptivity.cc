#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/error_estimator.h>
#include <fourier_ssi/adaptivity.h>
#include <map>

namespace FourierSSI
{
  void
  AdaptivityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptivity");
    prm.declare_entry("Strategy",
                      "global",
                      Patterns::Selection("global|kelly|goal"),
                      "Refinement between cycles: global (uniform), kelly "
                      "(Kelly indicators summed over the harmonics) or goal "
                      "(dual-weighted residual for the rigid-foundation "
                      "stiffness named by 'Goal': needs Rigid foundation/"
                      "Stiffness coefficients = true, harmonic n = 1 "
                      "symmetric and Polynomial degree = 2; the error is "
                      "estimated with an FE_Q(4) solve on the same mesh, "
                      "doc/accuracy-vs-time.md). Both sides of an interface "
                      "are refined alike.");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Double(0., 1.),
                      "kelly, goal: the cells holding this fraction of the "
                      "summed indicator are refined per cycle (deal.II fixed "
                      "fraction; goal indicators are squared quantities, so "
                      "a larger fraction, e.g. 0.8, suits them).");
    prm.declare_entry("Goal",
                      "all",
                      Patterns::Selection("K_H|K_M|K_MH|all"),
                      "goal: the stiffness coefficient whose error steers "
                      "the mesh and stops the cycles (all: the largest "
                      "relative error of K_H, K_M, K_MH).");
    prm.declare_entry("Goal tolerance",
                      "0",
                      Patterns::Double(0.),
                      "goal: stop refining once the estimated relative error "
                      "of the goal is below this value (0: run every "
                      "Refinement cycle).");
    prm.declare_entry("Point refinement",
                      "",
                      Patterns::Anything(),
                      "A priori grading toward singular points, before the "
                      "first cycle: 'r, z: levels; ...' refines the cells "
                      "touching each point (a vertex of the mesh, e.g. a "
                      "foundation edge) that many times, halving their size "
                      "each time. Empty: none.");
    prm.leave_subsection();
  }

  void
  AdaptivityParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptivity");
    strategy        = prm.get("Strategy");
    refine_fraction = prm.get_double("Refine fraction");
    goal            = prm.get("Goal");
    goal_tolerance  = prm.get_double("Goal tolerance");
    point_refinements.clear();
    for (const std::string &item :
         Utilities::split_string_list(prm.get("Point refinement"), ';'))
      {
        const std::vector<std::string> parts =
          Utilities::split_string_list(item, ':');
        const std::vector<std::string> coordinates =
          parts.size() == 2 ? Utilities::split_string_list(parts[0], ',') :
                              std::vector<std::string>();
        AssertThrow(coordinates.size() == 2,
                    ExcMessage("Adaptivity/Point refinement: '" + item +
                               "' is not 'r, z: levels'"));
        try
          {
            const int levels = Utilities::string_to_int(parts[1]);
            AssertThrow(levels >= 0, ExcMessage("negative"));
            point_refinements.emplace_back(
              Point<2>(Utilities::string_to_double(coordinates[0]),
                       Utilities::string_to_double(coordinates[1])),
              static_cast<unsigned int>(levels));
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcMessage("Adaptivity/Point refinement: '" + item +
                                   "' is not 'r, z: levels' with numbers "
                                   "and levels >= 0"));
          }
      }
    prm.leave_subsection();
  }

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
  RefinementIndicator::refine(
    Triangulation<2>                   &triangulation,
    const double                        fraction,
    const std::set<types::boundary_id> &interface_ids) const
  {
    GridRefinement::refine_and_coarsen_fixed_fraction(triangulation,
                                                      indicators,
                                                      fraction,
                                                      0.);
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
             std::vector<Triangulation<2>::active_cell_iterator>>
                 cells_at_face;
    const double scale = 1e-9 * GridTools::minimal_cell_diameter(triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && interface_ids.count(face->boundary_id()))
          cells_at_face[{std::llround(face->center()[0] / scale),
                         std::llround(face->center()[1] / scale)}]
            .push_back(cell);
    // Mesh smoothing (2:1 rule) may flag more cells: repeat until the two
    // sides of every interface agree.
    for (bool changed = true; changed;)
      {
        triangulation.prepare_coarsening_and_refinement();
        changed = false;
        for (auto &[key, cells] : cells_at_face)
          {
            bool any = false;
            for (const auto &cell : cells)
              any |= cell->refine_flag_set();
            if (any)
              for (const auto &cell : cells)
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
    for (unsigned int pass = 0; pass < max_levels; ++pass)
      {
        const double tolerance =
          1e-6 * GridTools::minimal_cell_diameter(triangulation);
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
} // namespace FourierSSI
