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

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/mesh/interface_lines.h>
#include <fourier_ssi/mesh/soil_layers.h>
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

  /** Parse "r0, r1, z0, z1" into a box; `entry` names the .prm entry. */
  BoundingBox<2>
  parse_box(const std::string &text, const std::string &entry);

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
   * Mesh/Type: the built-in graded (r, z) rectangle, or a gmsh file.
   */
  enum class MeshType
  {
    rectangle,
    gmsh
  };

  class MeshBuilder
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Build the coarse mesh and apply the initial global refinements; every
     * later refinement of `triangulation` (a priori, cycles) is checked
     * against Maximum DoFs before its cells are made.
     */
    void
    build(Triangulation<2> &triangulation) const;

    MeshType                  type = MeshType::rectangle;
    std::vector<double>       r_breakpoints, z_breakpoints, r_growth, z_growth;
    std::vector<unsigned int> r_cells, z_cells;
    double                    surface_patch_radius = 0.;
    double                    distortion           = 0.;
    unsigned int              global_refinements   = 0;
    std::string               mesh_file;
    /**
     * Refuse a mesh whose refinement would exceed this many DoFs per
     * harmonic (estimated as 3 p^2 per cell, before the cells are made):
     * a typo such as Global refinements = 12 would otherwise end in
     * std::bad_alloc after minutes. The default, 2e6, is about 8 GB with
     * the direct solver (4 kB per DoF, doc/scaling.md).
     */
    double maximum_dofs = 2e6;
    /** Polynomial degree for that estimate (Discretization, set on parse). */
    unsigned int degree = 2;
    /** (material id, box) pairs: cells with centre in the box get the id. */
    std::vector<std::pair<types::material_id, BoundingBox<2>>> material_regions;
    /**
     * Mesh/Soil layers as parsed; AllParameters puts them in front of
     * material_regions once the ground surface is known (soil_layers.h).
     */
    std::vector<SoilLayer> soil_layers;
    /** Cells with centre in one of these boxes are removed. */
    std::vector<BoundingBox<2>> removed_regions;
    std::vector<InterfaceLine>  interface_lines;
  };
} // namespace FourierSSI

#endif
