// Point refinement on a large domain: the vertex a user names by its exact
// coordinates carries the round-off of a mesh whose extent is 3e4 m. A
// foundation edge at (1, 0) on a domain of 3e4 m lies one ulp of 3e4
// (3.6e-12 m) away from where a mesh builder or a mesh file puts it. After
// 19 halvings of a 1 m cell its diagonal is 2.7e-6 m, and a tolerance of
// 1e-6 of it is below that round-off: the 20th pass found "no mesh
// vertex". The tolerance now never falls below the coordinates' own
// round-off (coordinate_tolerance.h).
// Checks: (1) the perturbed vertex is graded 24 levels: the cells at the
// point halve each pass, down to h_0 2^-24; (2) a point genuinely off the
// mesh (0.5 m from any vertex) is still refused.
#include "check.h"

#include <array>
#include <cmath>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/mesh/adaptivity.h>
#include <limits>

using namespace dealii;
using namespace FourierSSI;

namespace
{
  /**
   * Four cells: x in [0, x_edge, L], z in [-L, -1, 0], with L = 3e4 m and
   * x_edge one ulp of L above 1 m; the cell at the edge is 1 m square.
   */
  void
  make_large_domain(Triangulation<2> &triangulation, const double x_edge)
  {
    const double                L  = 3e4;
    const std::array<double, 3> xs = {{0., x_edge, L}};
    const std::array<double, 3> zs = {{-L, -1., 0.}};
    std::vector<Point<2>>       vertices;
    for (const double z : zs)
      for (const double x : xs)
        vertices.emplace_back(x, z);
    std::vector<CellData<2>> cells(4);
    for (unsigned int j = 0; j < 2; ++j)
      for (unsigned int i = 0; i < 2; ++i)
        cells[2 * j + i].vertices = {3 * j + i,
                                     3 * j + i + 1,
                                     3 * (j + 1) + i,
                                     3 * (j + 1) + i + 1};
    triangulation.create_triangulation(vertices, cells, SubCellData());
  }

  double
  smallest_cell_at(const Triangulation<2> &triangulation, const Point<2> &p)
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).distance(p) < 1e-9)
          h = std::min(h, cell->minimum_vertex_distance());
    return h;
  }
} // namespace

int
main()
{
  const double       ulp_of_extent = std::nextafter(3e4, 4e4) - 3e4;
  const Point<2>     edge(1., 0.);
  const unsigned int levels = 24;

  // (1) The edge vertex one ulp of the extent off the named point.
  {
    Triangulation<2> triangulation;
    make_large_domain(triangulation, 1. + ulp_of_extent);
    const double h0      = smallest_cell_at(triangulation, edge);
    bool         refused = false;
    try
      {
        refine_toward_points(triangulation, {{edge, levels}}, {});
      }
    catch (const std::exception &)
      {
        refused = true;
      }
    check::that("vertex one ulp of 3e4 m off (1, 0): graded, not refused",
                !refused);
    check::relative("smallest cell at the edge after 24 levels / (h_0 2^-24)",
                    smallest_cell_at(triangulation, edge) /
                      (h0 * std::pow(0.5, levels)),
                    1.,
                    1e-9);
  }

  // (2) A point 0.5 m from every vertex is an input error.
  {
    Triangulation<2> triangulation;
    make_large_domain(triangulation, 1.);
    bool refused = false;
    try
      {
        refine_toward_points(triangulation, {{Point<2>(1.5, 0.), 3}}, {});
      }
    catch (const std::exception &)
      {
        refused = true;
      }
    check::that("point 0.5 m off every vertex: refused", refused);
  }
  return check::summary();
}
