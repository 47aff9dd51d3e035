#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <filesystem>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/mesh/interface_lines.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <fstream>
#include <memory>
#include <numeric>
#include <set>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    /** 1.2e+07 style, for DoF counts in messages. */
    std::string
    format_count(const double value)
    {
      std::ostringstream s;
      s.precision(2);
      s << value;
      return s.str();
    }
  } // namespace

  std::vector<double>
  graded_steps(const std::vector<double>       &breakpoints,
               const std::vector<unsigned int> &cells,
               const std::vector<double>       &growth,
               const std::string               &entry)
  {
    AssertThrow(breakpoints.size() >= 2 &&
                  cells.size() == breakpoints.size() - 1 &&
                  growth.size() == cells.size(),
                ExcMessage(entry + ": need k+1 breakpoints, k cell counts and "
                                   "k growth ratios"));
    std::vector<double> steps;
    for (unsigned int s = 0; s < cells.size(); ++s)
      {
        const double length = breakpoints[s + 1] - breakpoints[s];
        AssertThrow(length > 0.,
                    ExcMessage(entry + ": breakpoints must increase"));
        AssertThrow(cells[s] > 0,
                    ExcMessage(entry + ": every segment needs >= 1 cell"));
        AssertThrow(growth[s] > 0.,
                    ExcMessage(entry + ": growth ratios must be > 0"));
        const double q = growth[s];
        // h0 (1 + q + ... + q^(m-1)) = length
        const double sum =
          (q == 1.) ? cells[s] : (std::pow(q, cells[s]) - 1.) / (q - 1.);
        double h = length / sum;
        for (unsigned int i = 0; i < cells[s]; ++i, h *= q)
          steps.push_back(h);
      }
    return steps;
  }

  namespace
  {
    /** Type, Mesh file and the DoF limit every mesh obeys. */
    void
    declare_mesh_source_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Type",
                        "rectangle",
                        Patterns::Selection("rectangle|gmsh"),
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
  MeshBuilder::declare_parameters(ParameterHandler &prm)
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
  MeshBuilder::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    type = prm.get("Type") == "gmsh" ? MeshType::gmsh : MeshType::rectangle;
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

  namespace
  {
    void
    read_gmsh_mesh(Triangulation<2>  &triangulation,
                   const std::string &mesh_file)
    {
      AssertThrow(!std::filesystem::is_directory(mesh_file),
                  ExcMessage("Mesh/Mesh file: '" + mesh_file +
                             "' is a directory"));
      std::ifstream in(mesh_file);
      AssertThrow(in,
                  ExcMessage("Mesh/Mesh file: cannot open '" + mesh_file +
                             "'"));
      GridIn<2> grid_in(triangulation);
      try
        {
          grid_in.read_msh(in);
        }
      catch (...)
        {
          // GridIn's message quotes the offending text, binary bytes
          // included: name the file instead.
          AssertThrow(false,
                      ExcMessage("Mesh/Mesh file: '" + mesh_file +
                                 "' is not a readable gmsh .msh mesh"));
        }
      for (const auto &v : triangulation.get_vertices())
        AssertThrow(v[0] > -1e-12,
                    ExcMessage("Mesh/Mesh file: '" + mesh_file +
                               "' has a vertex at r < 0"));
    }

    /**
     * Refuse a typo such as R cells = 1e6 before the cell sizes (one
     * number per cell) and the cells themselves are allocated; the
     * same estimate as for Global refinements (check_global_refinements).
     */
    void
    check_rectangle_cells(const MeshBuilder &mesh)
    {
      const double n_r =
        std::accumulate(mesh.r_cells.begin(), mesh.r_cells.end(), 0.);
      const double n_z =
        std::accumulate(mesh.z_cells.begin(), mesh.z_cells.end(), 0.);
      const double cell_dofs = n_r * n_z * 3. * mesh.degree * mesh.degree;
      if (!(cell_dofs <= mesh.maximum_dofs))
        throw MeshExceedsMaximumDoFs(
          "Mesh/R cells, Z cells: " + format_count(n_r) + " x " +
          format_count(n_z) + " cells would give about " +
          format_count(cell_dofs) +
          " DoFs per harmonic, above Mesh/Maximum DoFs "
          "= " +
          format_count(mesh.maximum_dofs));
    }

    /**
     * colorize also numbers the material ids: reset, then paint the
     * material regions (cell centres inside a box).
     */
    void
    paint_material_regions(Triangulation<2>  &triangulation,
                           const MeshBuilder &mesh)
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          cell->set_material_id(0);
          for (const auto &[id, box] : mesh.material_regions)
            if (box.point_inside(cell->center()))
              cell->set_material_id(id);
        }
    }

    std::set<Triangulation<2>::active_cell_iterator>
    cells_in_removed_regions(const Triangulation<2> &triangulation,
                             const MeshBuilder      &mesh)
    {
      std::set<Triangulation<2>::active_cell_iterator> removed;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &box : mesh.removed_regions)
          if (box.point_inside(cell->center()))
            removed.insert(cell);
      return removed;
    }

    void
    remove_regions(Triangulation<2> &triangulation, const MeshBuilder &mesh)
    {
      AssertThrow(cells_in_removed_regions(triangulation, mesh).size() <
                    triangulation.n_active_cells(),
                  ExcMessage("Mesh/Removed regions: every cell removed"));
      Triangulation<2> full;
      full.copy_triangulation(triangulation);
      triangulation.clear();
      GridGenerator::create_triangulation_with_removed_cells(
        full, cells_in_removed_regions(full, mesh), triangulation);
      // Boundary ids by position (the sketch in declare_parameters); the new
      // faces left by the removal are free surface (3).
      const std::vector<double> &r_breakpoints = mesh.r_breakpoints;
      const std::vector<double> &z_breakpoints = mesh.z_breakpoints;
      const double tol = 1e-10 * (r_breakpoints.back() - r_breakpoints.front());
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<2> c = face->center();
              face->set_boundary_id(
                std::abs(c[0] - r_breakpoints.front()) < tol ? 0 :
                std::abs(c[0] - r_breakpoints.back()) < tol  ? 1 :
                std::abs(c[1] - z_breakpoints.front()) < tol ? 2 :
                                                               3);
            }
    }

    void
    mark_surface_patch(Triangulation<2> &triangulation, const double radius)
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == 3 &&
              face->center()[0] < radius)
            face->set_boundary_id(4);
    }

    void
    build_rectangle(Triangulation<2> &triangulation, const MeshBuilder &mesh)
    {
      check_rectangle_cells(mesh);
      const std::vector<std::vector<double>> steps = {
        graded_steps(mesh.r_breakpoints, mesh.r_cells, mesh.r_growth, "Mesh/R"),
        graded_steps(
          mesh.z_breakpoints, mesh.z_cells, mesh.z_growth, "Mesh/Z")};
      GridGenerator::subdivided_hyper_rectangle(
        triangulation,
        steps,
        Point<2>(mesh.r_breakpoints.front(), mesh.z_breakpoints.front()),
        Point<2>(mesh.r_breakpoints.back(), mesh.z_breakpoints.back()),
        /*colorize=*/true);
      paint_material_regions(triangulation, mesh);
      if (!mesh.removed_regions.empty())
        remove_regions(triangulation, mesh);
      if (!mesh.interface_lines.empty())
        split_along_interface_lines(triangulation,
                                    mesh.interface_lines,
                                    mesh.r_breakpoints,
                                    mesh.z_breakpoints);
      if (mesh.surface_patch_radius > 0.)
        mark_surface_patch(triangulation, mesh.surface_patch_radius);
      if (mesh.distortion > 0.)
        GridTools::distort_random(mesh.distortion,
                                  triangulation,
                                  /*keep_boundary=*/true,
                                  /*seed=*/20070101);
    }

    void
    check_global_refinements(const Triangulation<2> &triangulation,
                             const unsigned int      global_refinements,
                             const double            dofs_per_cell,
                             const double            maximum_dofs)
    {
      const double estimate = triangulation.n_active_cells() *
                              std::pow(4., global_refinements) * dofs_per_cell;
      if (!(estimate <= maximum_dofs))
        throw MeshExceedsMaximumDoFs(
          "Mesh/Global refinements: " + std::to_string(global_refinements) +
          " refinements of " + std::to_string(triangulation.n_active_cells()) +
          " cells would give about " + format_count(estimate) +
          " DoFs per harmonic, above Mesh/Maximum DoFs = " +
          format_count(maximum_dofs));
    }

    /**
     * Throw before any later refinement (a priori, cycles) allocates cells
     * beyond the limit; the guard belongs to this build: the next clear()
     * (a new build) removes it.
     */
    void
    guard_later_refinements(Triangulation<2> &triangulation,
                            const double      dofs_per_cell,
                            const double      maximum_dofs)
    {
      const auto guard = std::make_shared<boost::signals2::connection>();
      *guard           = triangulation.signals.pre_refinement.connect(
        [&triangulation, dofs_per_cell, limit = maximum_dofs]() {
          unsigned int n_new = 0;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->refine_flag_set() ==
                RefinementCase<2>::isotropic_refinement)
              n_new += 3;
            else if (cell->refine_flag_set())
              n_new += 1;
          const double dofs =
            (triangulation.n_active_cells() + n_new) * dofs_per_cell;
          if (!(dofs <= limit))
            throw MeshExceedsMaximumDoFs(
              "Mesh/Maximum DoFs: refining the mesh to " +
              std::to_string(triangulation.n_active_cells() + n_new) +
              " cells would give about " + format_count(dofs) +
              " DoFs per harmonic, above the limit " + format_count(limit) +
              " (lower Adaptivity/Box, Layer or Point refinement, "
                        "Discretization/Refinement cycles, or raise Mesh/"
                        "Maximum DoFs)");
        });
      const auto clear_slot = std::make_shared<boost::signals2::connection>();
      *clear_slot = triangulation.signals.clear.connect([guard, clear_slot]() {
        guard->disconnect();
        clear_slot->disconnect();
      });
    }
  } // namespace

  void
  MeshBuilder::build(Triangulation<2> &triangulation) const
  {
    triangulation.clear();
    if (type == MeshType::gmsh)
      read_gmsh_mesh(triangulation, mesh_file);
    else
      build_rectangle(triangulation, *this);
    // Refuse a refinement that would exceed Maximum DoFs before it
    // allocates its cells: Global refinements here, the a priori and cycle
    // refinements through the triangulation's pre-refinement signal.
    const double dofs_per_cell = 3. * degree * degree;
    check_global_refinements(triangulation,
                             global_refinements,
                             dofs_per_cell,
                             maximum_dofs);
    guard_later_refinements(triangulation, dofs_per_cell, maximum_dofs);
    triangulation.refine_global(global_refinements);
  }
} // namespace FourierSSI
