/**
 * Subsection "Mesh" of the .prm file: the (r, z) half-plane mesh of a scene
 * as given, the built-in graded rectangle or a gmsh file; the boundary ids
 * of the rectangle are sketched in mesh/mesh_builder.h, which builds it.
 */
#ifndef fourier_ssi_mesh_parameters_h
#define fourier_ssi_mesh_parameters_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <fourier_ssi/input/soil_layers.h>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** Parse "r0, r1, z0, z1" into a box; `entry` names the .prm entry. */
  BoundingBox<2>
  parse_box(const std::string &text, const std::string &entry);

  /**
   * A straight interface line of the built-in rectangle, "id: r=1, z=-2..0"
   * (vertical) or "id: z=-2, r=0..1" (horizontal): the mesh is split there
   * with double nodes (see split_along_interface_lines()).
   */
  struct InterfaceLine
  {
    types::boundary_id boundary_id;
    unsigned int       fixed_coordinate; // 0: r = value, 1: z = value
    double             value, from, to;
  };

  /**
   * Parse Mesh/Interface lines, "id: r=1, z=-2..0; id: z=-2, r=0..1" (empty:
   * none). Throws a one-line message naming the entry.
   */
  std::vector<InterfaceLine>
  parse_interface_lines(const std::string &text);

  /**
   * Mesh/Type: the built-in graded (r, z) rectangle, or a gmsh file.
   */
  enum class MeshType
  {
    rectangle,
    gmsh
  };

  /**
   * Subsection "Mesh": the built-in rectangle (its grading, regions and
   * interface lines) or the gmsh file, and the DoF limit every mesh obeys
   * (build_mesh(), mesh/mesh_builder.h, makes the mesh).
   */
  struct MeshParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

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
