/**
 * Layered soil (Mesh/Soil layers): horizontal strata given as depth
 * intervals below the ground surface (Materials/Ground surface elevation),
 * each painted with its material id across the whole width of the
 * rectangle mesh. A stratum's law is its material's: modulus and G(depth)
 * from Materials/Materials, plasticity from Soil plasticity/Laws.
 *
 * The strata are painted before Mesh/Material regions, so a pile, a
 * caisson skirt or a lid given as a region stays what it is where it
 * crosses a stratum. Every stratum boundary inside the mesh must be a Z
 * breakpoint: a cell is painted by its centre, and a boundary that cut
 * cells would move silently to the nearest cell face.
 */
#ifndef fourier_ssi_mesh_soil_layers_h
#define fourier_ssi_mesh_soil_layers_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  struct MeshParameters;

  /** One stratum: material id and its depth interval [m] below the surface. */
  struct SoilLayer
  {
    types::material_id material     = 0;
    double             top_depth    = 0.;
    double             bottom_depth = 0.;
  };

  /** Declare Mesh/Soil layers (inside the Mesh subsection). */
  void
  declare_soil_layers_entry(ParameterHandler &prm);

  /**
   * Parse "id: top, bottom; id: top, bottom; ..." (depths [m], 0 <= top <
   * bottom, strata that do not overlap). Throws with one line naming
   * Mesh/Soil layers and the offending text.
   */
  std::vector<SoilLayer>
  parse_soil_layers(const std::string &text);

  /**
   * The strata as (material id, box) regions spanning the mesh's r range,
   * at elevations z = surface_elevation - depth, clipped to the mesh's z
   * range. Refuses a stratum boundary inside the mesh that is not a Z
   * breakpoint, and any stratum with Mesh/Type = gmsh.
   */
  std::vector<std::pair<types::material_id, BoundingBox<2>>>
  soil_layer_regions(const MeshParameters &mesh,
                     const double          surface_elevation);

  /**
   * Put the strata in front of mesh.material_regions (later boxes win, so
   * the regions given by the user override the strata).
   */
  void
  paint_soil_layers(MeshParameters &mesh, const double surface_elevation);
} // namespace FourierSSI

#endif
