/**
 * The (r, z) half-plane meshes of a scene (Mesh/Type): the built-in graded
 * rectangle, with material regions, removed regions and interface lines
 * (double nodes, interface_lines.h), or a gmsh .msh file whose physical
 * curve tags are boundary ids and physical surface tags material ids
 * (doc/interfaces-usage.md).
 *
 * Built-in rectangle, boundary ids (deal.II colorize convention):
 *
 *      z_max  +----------3------------+
 *             |                       |
 *   (axis if  0                       1
 *    r_min=0) |                       |
 *      z_min  +----------2------------+
 *           r_min                   r_max
 *
 * plus id 4 for the top faces with r < "Surface patch radius" (a footing
 * contact patch), when that radius is positive. Faces left free by removed
 * regions get id 3 (free surface); the faces on both sides of an interface
 * line get the line's id. doc/scenes.md draws
 * the same sketch.
 */
#ifndef fourier_ssi_mesh_builder_h
#define fourier_ssi_mesh_builder_h

#include <deal.II/grid/tria.h>
#include <fourier_ssi/input/mesh_parameters.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * Cell sizes of a graded 1D line given as segments: breakpoints
   * x_0 < x_1 < ... < x_k, cells per segment, and per segment the growth
   * ratio h_{i+1}/h_i of consecutive cells (1 = uniform, < 1 shrinks toward
   * the segment end).
   */
  std::vector<double>
  graded_steps(const std::vector<double>       &breakpoints,
               const std::vector<unsigned int> &cells,
               const std::vector<double>       &growth,
               const std::string               &entry);

  /**
   * A mesh that would exceed Mesh/Maximum DoFs. For the first mesh of a run
   * it is an input error like any other; for a later member of
   * Discretization/Target accuracy it is a bound that stops the refinement,
   * so the target run catches this type and reports the target unmet.
   */
  class MeshExceedsMaximumDoFs : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Build the coarse mesh of Mesh (MeshParameters) and apply the initial
   * global refinements; every later refinement of `triangulation` (a
   * priori, cycles) is checked against Maximum DoFs before its cells are
   * made.
   */
  void
  build_mesh(const MeshParameters &mesh, Triangulation<2> &triangulation);
} // namespace FourierSSI

#endif
