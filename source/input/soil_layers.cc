#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/input/mesh_parameters.h>
#include <fourier_ssi/input/soil_layers.h>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Mesh/Soil layers";

    void
    refuse(const std::string &what)
    {
      AssertThrow(false, ExcMessage(entry + ": " + what));
    }

    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    SoilLayer
    parse_one_layer(const std::string &item)
    {
      const auto colon = item.find(':');
      if (colon == std::string::npos)
        refuse("'" + item + "' is not 'id: top depth, bottom depth'");
      SoilLayer           layer;
      int                 id = -1;
      std::vector<double> depths;
      try
        {
          id = Utilities::string_to_int(Utilities::trim(item.substr(0, colon)));
          for (const std::string &x :
               Utilities::split_string_list(item.substr(colon + 1), ','))
            depths.push_back(Utilities::string_to_double(x));
        }
      catch (...)
        {
          refuse("'" + item + "' is not 'id: top depth, bottom depth'");
        }
      if (id < 0 || id >= 255)
        refuse("bad material id in '" + item + "'");
      if (depths.size() != 2 || !std::isfinite(depths[0]) ||
          !std::isfinite(depths[1]) || !(depths[0] >= 0.) ||
          !(depths[0] < depths[1]))
        refuse("'" + item +
               "' needs two depths [m] below the surface, 0 <= top < bottom");
      layer.material     = id;
      layer.top_depth    = depths[0];
      layer.bottom_depth = depths[1];
      return layer;
    }

    void
    check_no_overlap(std::vector<SoilLayer> layers)
    {
      std::sort(layers.begin(),
                layers.end(),
                [](const SoilLayer &a, const SoilLayer &b) {
                  return a.top_depth < b.top_depth;
                });
      for (unsigned int i = 1; i < layers.size(); ++i)
        if (layers[i].top_depth < layers[i - 1].bottom_depth)
          refuse("the strata " + number(layers[i - 1].top_depth) + "-" +
                 number(layers[i - 1].bottom_depth) + " m and " +
                 number(layers[i].top_depth) + "-" +
                 number(layers[i].bottom_depth) + " m overlap");
    }

    /** A boundary inside the mesh must be a Z breakpoint (cells painted by
     * their centre would otherwise move it to the nearest face). */
    void
    check_on_breakpoint(const double               z,
                        const double               depth,
                        const std::vector<double> &z_breakpoints)
    {
      const double z_min = z_breakpoints.front(), z_max = z_breakpoints.back();
      const double tolerance = 1e-9 * (z_max - z_min);
      if (z <= z_min + tolerance || z >= z_max - tolerance)
        return;
      for (const double b : z_breakpoints)
        if (std::abs(b - z) <= tolerance)
          return;
      refuse("the stratum boundary at depth " + number(depth) +
             " m (z = " + number(z) +
             " m) is not a Z breakpoint; add it to Mesh/Z breakpoints so that "
             "no cell straddles it");
    }
  } // namespace

  void
  declare_soil_layers_entry(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Soil layers",
      "",
      Patterns::Anything(),
      "Rectangle only: horizontal strata 'id: top, bottom; ...', depths [m] "
      "below Materials/Ground surface elevation, each given material id "
      "across the mesh width (its modulus, G(depth) and plastic law are the "
      "material's). Painted before Material regions, which win where they "
      "overlap a stratum (a pile, a skirt). Each boundary inside the mesh "
      "must be a Z breakpoint.");
  }

  std::vector<SoilLayer>
  parse_soil_layers(const std::string &text)
  {
    std::vector<SoilLayer> layers;
    for (const std::string &item : split_top_level(text, ';'))
      layers.push_back(parse_one_layer(item));
    check_no_overlap(layers);
    return layers;
  }

  std::vector<std::pair<types::material_id, BoundingBox<2>>>
  soil_layer_regions(const MeshParameters &mesh, const double surface_elevation)
  {
    std::vector<std::pair<types::material_id, BoundingBox<2>>> regions;
    if (mesh.soil_layers.empty())
      return regions;
    if (mesh.type != MeshType::rectangle)
      refuse("only for Mesh/Type = rectangle (give the strata as physical "
             "surfaces in gmsh)");
    const std::vector<double> &z = mesh.z_breakpoints;
    for (const SoilLayer &layer : mesh.soil_layers)
      {
        const double z_top    = surface_elevation - layer.top_depth;
        const double z_bottom = surface_elevation - layer.bottom_depth;
        check_on_breakpoint(z_top, layer.top_depth, z);
        check_on_breakpoint(z_bottom, layer.bottom_depth, z);
        const double low  = std::max(z_bottom, z.front());
        const double high = std::min(z_top, z.back());
        if (!(low < high))
          refuse("the stratum " + number(layer.top_depth) + "-" +
                 number(layer.bottom_depth) + " m lies outside the mesh");
        regions.emplace_back(layer.material,
                             BoundingBox<2>(std::make_pair(
                               Point<2>(mesh.r_breakpoints.front(), low),
                               Point<2>(mesh.r_breakpoints.back(), high))));
      }
    return regions;
  }

  void
  paint_soil_layers(MeshParameters &mesh, const double surface_elevation)
  {
    auto strata = soil_layer_regions(mesh, surface_elevation);
    mesh.material_regions.insert(mesh.material_regions.begin(),
                                 strata.begin(),
                                 strata.end());
  }
} // namespace FourierSSI
