#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/mesh_parameters.h>
#include <fourier_ssi/input/prm_values.h>

namespace FourierSSI
{
  namespace
  {
    const Choices<MeshType> &
    mesh_types()
    {
      static const Choices<MeshType> choices{{"rectangle", MeshType::rectangle},
                                             {"gmsh", MeshType::gmsh}};
      return choices;
    }
  } // namespace

  namespace
  {
    /** Type, Mesh file and the DoF limit every mesh obeys. */
    void
    declare_mesh_source_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Type",
                        "rectangle",
                        Patterns::Selection(mesh_types().selection()),
                        "rectangle: built-in graded (r, z) rectangle with the "
                        "boundary ids 0 = r_min side (the axis when r_min = "
                        "0), 1 = r_max side (far side), 2 = bottom (z_min), "
                        "3 = top (z_max, ground surface), 4 = top faces with "
                        "r < Surface patch radius (footing contact); faces "
                        "left by Removed regions get 3 (sketch in "
                        "doc/scenes.md). gmsh: read 'Mesh file' (.msh), "
                        "physical curve tags are boundary ids, physical "
                        "surface tags material ids.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::FileName(),
                        "gmsh .msh file; a relative path is relative to the "
                        "folder of the .prm file.");
      prm.declare_entry("Maximum DoFs",
                        "2e6",
                        Patterns::Double(1.),
                        "Refuse a run whose mesh would exceed this many DoFs "
                        "per harmonic, estimated as 3 p^2 per cell before the "
                        "cells are made (Global refinements, a priori and "
                        "cycle refinements). 2e6 is about 8 GB with the direct "
                        "solver (doc/scaling.md: 4 kB per DoF); raise it on a "
                        "larger machine.");
    }

    /** The graded rectangle: segment ends, cells and growth in r and z. */
    void
    declare_rectangle_grading_entries(ParameterHandler &prm)
    {
      prm.declare_entry("R breakpoints",
                        "0, 1",
                        Patterns::List(Patterns::Double()),
                        "Radial segment ends [m].");
      prm.declare_entry("R cells",
                        "4",
                        Patterns::List(Patterns::Integer(1)),
                        "Cells per radial segment. All radial cells times "
                        "all Z cells times 3 p^2 must stay within Maximum "
                        "DoFs (checked before the mesh is made).");
      prm.declare_entry("R growth",
                        "1",
                        Patterns::List(Patterns::Double(0.)),
                        "Per radial segment, size ratio of consecutive cells "
                        "(1 uniform, <1 shrinking toward the segment end).");
      prm.declare_entry("Z breakpoints",
                        "0, 1",
                        Patterns::List(Patterns::Double()),
                        "Vertical segment ends [m], bottom to top.");
      prm.declare_entry("Z cells",
                        "4",
                        Patterns::List(Patterns::Integer(1)),
                        "Cells per vertical segment (bounded with R cells).");
      prm.declare_entry(
        "Z growth",
        "1",
        Patterns::List(Patterns::Double(0.)),
        "Per vertical segment, size ratio of consecutive cells.");
    }

    /** Surface patch, distortion and global refinements. */
    void
    declare_mesh_modification_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Surface patch radius",
                        "0",
                        Patterns::Double(0.),
                        "If > 0, top faces (id 3) with centre r below it get "
                        "boundary id 4; at most the outer radius.");
      prm.declare_entry("Distortion",
                        "0",
                        Patterns::Double(0., 0.4),
                        "Random interior vertex displacement as a fraction of "
                        "the local edge length (tests on distorted meshes).");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 12),
                        "Uniform refinements of the coarse mesh.");
    }

    /**
     * Material regions, soil layers, removed regions and interface lines of
     * the rectangle.
     */
    void
    declare_rectangle_region_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Material regions",
                        "",
                        Patterns::Anything(),
                        "Rectangle only: 'id: r0, r1, z0, z1; ...' gives the "
                        "cells whose centre lies in each box that material id "
                        "(later boxes win; default material 0).");
      declare_soil_layers_entry(prm);
      prm.declare_entry("Removed regions",
                        "",
                        Patterns::Anything(),
                        "Rectangle only: 'r0, r1, z0, z1; ...' removes the "
                        "cells whose centre lies in each box (e.g. the air "
                        "beside a footing standing on the surface); the new "
                        "boundary faces get id 3 (free surface).");
      prm.declare_entry(
        "Interface lines",
        "",
        Patterns::Anything(),
        "Rectangle only: straight lines where the mesh is split "
        "with double nodes, e.g. 'id: r=1, z=-2..0; id: z=-2, "
        "r=0..1'; the faces on both sides get the boundary id "
        "(declare its law in Interfaces/Interfaces). Lines and "
        "their ends must be on the breakpoints.");
    }
  } // namespace

  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    declare_mesh_source_entries(prm);
    declare_rectangle_grading_entries(prm);
    declare_mesh_modification_entries(prm);
    declare_rectangle_region_entries(prm);
    prm.leave_subsection();
  }

  namespace
  {
    template <typename T>
    std::vector<T>
    to_list(const std::string &text)
    {
      std::vector<T> values;
      for (const std::string &s : Utilities::split_string_list(text))
        values.push_back(static_cast<T>(Utilities::string_to_double(s)));
      return values;
    }
  } // namespace

  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    type                 = mesh_types().value_of(prm.get("Type"), "Mesh/Type");
    mesh_file            = prm.get("Mesh file");
    r_breakpoints        = to_list<double>(prm.get("R breakpoints"));
    r_cells              = to_list<unsigned int>(prm.get("R cells"));
    r_growth             = to_list<double>(prm.get("R growth"));
    z_breakpoints        = to_list<double>(prm.get("Z breakpoints"));
    z_cells              = to_list<unsigned int>(prm.get("Z cells"));
    z_growth             = to_list<double>(prm.get("Z growth"));
    surface_patch_radius = prm.get_double("Surface patch radius");
    distortion           = prm.get_double("Distortion");
    global_refinements   = prm.get_integer("Global refinements");
    maximum_dofs         = prm.get_double("Maximum DoFs");
    interface_lines      = parse_interface_lines(prm.get("Interface lines"));
    material_regions.clear();
    for (const std::string &item :
         split_top_level(prm.get("Material regions"), ';'))
      {
        const auto colon = item.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage("Mesh/Material regions: '" + item +
                               "' lacks 'id:'"));
        int id = -1;
        try
          {
            id =
              Utilities::string_to_int(Utilities::trim(item.substr(0, colon)));
          }
        catch (...)
          {}
        AssertThrow(id >= 0 && id < 255,
                    ExcMessage("Mesh/Material regions: bad material id in '" +
                               item + "'"));
        material_regions.emplace_back(id,
                                      parse_box(item.substr(colon + 1),
                                                "Mesh/Material regions"));
      }
    soil_layers = parse_soil_layers(prm.get("Soil layers"));
    removed_regions.clear();
    for (const std::string &item :
         split_top_level(prm.get("Removed regions"), ';'))
      removed_regions.push_back(parse_box(item, "Mesh/Removed regions"));
    prm.leave_subsection();
    AssertThrow(interface_lines.empty() || type == MeshType::rectangle,
                ExcMessage("Mesh/Interface lines: only for Type = rectangle "
                           "(duplicate the curve in gmsh instead)"));
    if (type == MeshType::rectangle)
      AssertThrow(r_breakpoints.front() >= 0.,
                  ExcMessage("Mesh/R breakpoints: r must be >= 0"));
  }

  BoundingBox<2>
  parse_box(const std::string &text, const std::string &entry)
  {
    std::vector<double> v;
    try
      {
        for (const std::string &x : Utilities::split_string_list(text, ','))
          v.push_back(Utilities::string_to_double(x));
      }
    catch (...)
      {
        v.clear();
      }
    AssertThrow(v.size() == 4 && v[0] < v[1] && v[2] < v[3],
                ExcMessage(entry + ": '" + text +
                           "' is not 'r0, r1, z0, z1' with r0 < r1, z0 < z1"));
    return BoundingBox<2>(
      std::make_pair(Point<2>(v[0], v[2]), Point<2>(v[1], v[3])));
  }

  std::vector<InterfaceLine>
  parse_interface_lines(const std::string &text)
  {
    const std::string          entry = "Mesh/Interface lines";
    std::vector<InterfaceLine> lines;
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        const auto colon = item.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage(entry + ": '" + item + "' lacks 'id:'"));
        InterfaceLine line;
        line.boundary_id = boundary_id_in_entry(item.substr(0, colon), entry);
        bool has_value = false, has_range = false;
        int  value_coordinate = -1, range_coordinate = -1;
        for (const std::string &token :
             Utilities::split_string_list(item.substr(colon + 1), ','))
          {
            const auto eq = token.find('=');
            AssertThrow(eq != std::string::npos,
                        ExcMessage(entry + ": '" + token +
                                   "' is not r=... "
                                   "or z=..."));
            const std::string key = Utilities::trim(token.substr(0, eq));
            AssertThrow(key == "r" || key == "z",
                        ExcMessage(entry + ": unknown coordinate '" + key +
                                   "' in '" + item + "'"));
            const int         c    = key == "r" ? 0 : 1;
            const std::string rhs  = token.substr(eq + 1);
            const auto        dots = rhs.find("..");
            if (dots == std::string::npos)
              {
                AssertThrow(!has_value,
                            ExcMessage(entry + ": two fixed coordinates in '" +
                                       item + "'"));
                line.value       = number_in_entry(rhs, entry);
                value_coordinate = c;
                has_value        = true;
              }
            else
              {
                AssertThrow(!has_range,
                            ExcMessage(entry + ": two ranges in '" + item +
                                       "'"));
                line.from        = number_in_entry(rhs.substr(0, dots), entry);
                line.to          = number_in_entry(rhs.substr(dots + 2), entry);
                range_coordinate = c;
                has_range        = true;
              }
          }
        AssertThrow(has_value && has_range &&
                      value_coordinate != range_coordinate,
                    ExcMessage(entry + ": '" + item +
                               "' must be 'r=a, z=b..c' or 'z=a, r=b..c'"));
        if (line.from > line.to)
          std::swap(line.from, line.to);
        AssertThrow(line.to > line.from,
                    ExcMessage(entry + ": empty range in '" + item + "'"));
        line.fixed_coordinate = value_coordinate;
        // A segment given twice (or two that overlap) would split the same
        // edges twice: the second copy has no faces of its own to pair.
        for (const InterfaceLine &other : lines)
          AssertThrow(other.fixed_coordinate != line.fixed_coordinate ||
                        other.value != line.value || other.to <= line.from ||
                        line.to <= other.from,
                      ExcMessage(entry + ": '" + Utilities::trim(item) +
                                 "' overlaps an earlier line on the same " +
                                 (line.fixed_coordinate == 0 ? "r" : "z") +
                                 " (each segment once)"));
        lines.push_back(line);
      }
    return lines;
  }
} // namespace FourierSSI
