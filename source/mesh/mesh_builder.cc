#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <filesystem>
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
    check_rectangle_cells(const MeshParameters &mesh)
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
    paint_material_regions(Triangulation<2>     &triangulation,
                           const MeshParameters &mesh)
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
                             const MeshParameters   &mesh)
    {
      std::set<Triangulation<2>::active_cell_iterator> removed;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &box : mesh.removed_regions)
          if (box.point_inside(cell->center()))
            removed.insert(cell);
      return removed;
    }

    void
    remove_regions(Triangulation<2> &triangulation, const MeshParameters &mesh)
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
    build_rectangle(Triangulation<2> &triangulation, const MeshParameters &mesh)
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
  build_mesh(const MeshParameters &mesh, Triangulation<2> &triangulation)
  {
    triangulation.clear();
    if (mesh.type == MeshType::gmsh)
      read_gmsh_mesh(triangulation, mesh.mesh_file);
    else
      build_rectangle(triangulation, mesh);
    // Refuse a refinement that would exceed Maximum DoFs before it
    // allocates its cells: Global refinements here, the a priori and cycle
    // refinements through the triangulation's pre-refinement signal.
    const double dofs_per_cell = 3. * mesh.degree * mesh.degree;
    check_global_refinements(triangulation,
                             mesh.global_refinements,
                             dofs_per_cell,
                             mesh.maximum_dofs);
    guard_later_refinements(triangulation, dofs_per_cell, mesh.maximum_dofs);
    triangulation.refine_global(mesh.global_refinements);
  }
} // namespace FourierSSI
