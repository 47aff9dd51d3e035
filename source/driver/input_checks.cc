#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/vector.h>
#include <filesystem>
#include <fourier_ssi/driver/input_checks.h>
#include <fourier_ssi/driver/result_files.h>
#include <set>
#include <sstream>
#include <unistd.h>

namespace FourierSSI
{
  namespace
  {
    /**
     * The results file is a plain .csv name in the output folder: a path
     * would write outside it ("../escape.csv"), and a name the run writes
     * itself, or its ".partial" stage, would be overwritten by (or
     * overwrite) that file.
     */
    std::string
    results_file_name_error(const std::string &name)
    {
      const std::string entry = "Output/Results file: '" + name + "' ";
      if (name.find('/') != std::string::npos)
        return entry + "is a path; give a file name (the file is written "
                       "in Output/Directory)";
      const std::string csv = ".csv";
      if (name.front() == '.' || name.size() <= csv.size() ||
          name.compare(name.size() - csv.size(), csv.size(), csv) != 0)
        return entry + "is not a file name ending in .csv";
      // results.csv is the catalogue's own name for this file.
      const std::vector<std::string> &own = ResultFiles::catalogue();
      if (name != "results.csv" &&
          (name == "batch.csv" ||
           std::find(own.begin(), own.end(), name) != own.end()))
        return entry + "is the name of a file the run writes itself; "
                       "choose another";
      return "";
    }

    std::string
    format(const double value)
    {
      std::ostringstream s;
      s.precision(4);
      s << value;
      return s.str();
    }

    std::string
    at(const Point<2> &p)
    {
      return "(r, z) = (" + format(p[0]) + ", " + format(p[1]) + ")";
    }

    const std::array<std::string, 3> displacement_names = {{"u", "v", "w"}};
    const std::array<std::string, 3> traction_names     = {{"r", "z", "theta"}};

    /**
     * Points of the boundary faces with an id where its values are used:
     * vertices and midpoints for a prescribed displacement (support
     * points), inner Gauss points for a traction (integrated there only: a
     * traction singular at a face end, like a rigid punch's, is legal).
     */
    std::vector<Point<2>>
    boundary_points(const Triangulation<2>  &triangulation,
                    const types::boundary_id id,
                    const bool               inner_points_only)
    {
      std::vector<Point<2>> points;
      const QGauss<1>       gauss(3);
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          {
            const Point<2> a = face->vertex(0), b = face->vertex(1);
            if (inner_points_only)
              for (const auto &q : gauss.get_points())
                points.push_back(a + q[0] * (b - a));
            else
              {
                points.push_back(a);
                points.push_back(face->center());
                points.push_back(b);
              }
          }
      return points;
    }

    /**
     * A NaN or infinity in an amplitude expression of a listed harmonic
     * gives a NaN system, reported late as "singular" or not at all: check
     * the values where they are used.
     */
    void
    check_finite_amplitudes(
      const std::map<types::boundary_id, ComponentExpressions> &entries,
      const std::string                                        &entry,
      const bool                                                is_traction,
      const Triangulation<2>                                   &triangulation,
      const std::vector<Harmonic>                              &harmonics)
    {
      std::set<unsigned int> numbers;
      for (const Harmonic &h : harmonics)
        numbers.insert(h.n);
      Vector<double> value(3);
      for (const auto &[id, expressions] : entries)
        {
          const std::vector<Point<2>> points =
            boundary_points(triangulation, id, is_traction);
          const std::array<std::string, 3> &names =
            is_traction ? traction_names : displacement_names;
          for (const unsigned int n : numbers)
            {
              const auto function =
                BoundaryConditions::make_function(expressions, n, entry);
              for (const Point<2> &p : points)
                {
                  function->vector_value(p, value);
                  for (unsigned int c = 0; c < 3; ++c)
                    AssertThrow(
                      !expressions.given[c] || std::isfinite(value(c)),
                      ExcMessage(
                        entry + ": boundary " + std::to_string(id) + ", " +
                        names[c] + " = '" + expressions.expression[c] +
                        "' is " + (std::isnan(value(c)) ? "NaN" : "infinite") +
                        " at " + at(p) + " (n = " + std::to_string(n) + ")"));
                }
            }
        }
    }

    /**
     * A traction on DoFs that are fixed does nothing (the support takes
     * it): an error if every loaded component is fixed, a warning if some.
     */
    void
    check_traction_on_fixed(
      const std::map<types::boundary_id, ComponentExpressions> &tractions,
      const std::string                                        &traction_entry,
      const std::map<types::boundary_id, ComponentExpressions> &fixed,
      const std::string                                        &fixed_entry,
      std::vector<std::string>                                 &notes)
    {
      for (const auto &[id, t] : tractions)
        {
          const auto it = fixed.find(id);
          if (it == fixed.end())
            continue;
          std::vector<std::string> loaded_fixed;
          bool                     some_loaded_free = false;
          for (unsigned int c = 0; c < 3; ++c)
            if (t.given[c] && !is_literal_zero(t.expression[c]))
              {
                if (it->second.given[c])
                  loaded_fixed.push_back(traction_names[c]);
                else
                  some_loaded_free = true;
              }
          if (loaded_fixed.empty())
            continue;
          std::string list;
          for (const std::string &c : loaded_fixed)
            list += (list.empty() ? "" : ", ") + c;
          const std::string what = traction_entry + ": boundary " +
                                   std::to_string(id) + " is also fixed by " +
                                   fixed_entry + " in " + list;
          AssertThrow(some_loaded_free,
                      ExcMessage(what + ": the supports would take the whole "
                                        "traction, nothing is loaded"));
          notes.push_back("warning: " + what +
                          ": that part of the traction goes straight into "
                          "the supports; only the free components load the "
                          "body");
        }
    }

    /**
     * A Mohr-Coulomb soil with c = 0 has no strength at zero stress: a
     * path that starts from the unstressed state (no Initial stress) can
     * only converge under all-round compression, and otherwise fails with
     * the generic "did not converge" after its step cuts. Said up front,
     * as for a coulomb interface without strength.
     */
    void
    warn_cohesionless_soil(const AllParameters      &parameters,
                           std::vector<std::string> &notes)
    {
      if (parameters.initial_stress.enabled())
        return;
      for (const auto &[id, law] : parameters.soil_plasticity.laws)
        if (law.frictional() && law.cohesion == 0.)
          notes.push_back(
            "warning: Soil plasticity/Laws: material " + std::to_string(id) +
            ": mohr-coulomb with c = 0 and no Initial stress has no strength "
            "at the start of the path; unless the loads compress it all "
            "round the first step will not converge (give c > 0 or Initial "
            "stress)");
    }

    /**
     * A foundation resultant acts on one harmonic only: a harmonic list
     * without it solves a scene without that load.
     */
    void
    check_foundation_loads_are_solved(const AllParameters &parameters,
                                      const ScenePlan     &plan)
    {
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      if (!foundation.enabled || parameters.discretization.automatic)
        return;
      const auto listed = [&](const unsigned int n, const Family family) {
        for (const Harmonic &h : plan.harmonics)
          if (h.n == n && h.family == family)
            return true;
        return false;
      };
      const auto require = [&](const double       value,
                               const std::string &entry,
                               const unsigned int n,
                               const Family       family) {
        AssertThrow(value == 0. || listed(n, family),
                    ExcMessage("Rigid foundation/" + entry +
                               " acts on harmonic " +
                               Harmonic{n, family}.name() +
                               ", which Discretization/Harmonics does not "
                               "list: add it (and Family), or set "
                               "Harmonics = auto"));
      };
      const Family symmetric     = Family::symmetric,
                   antisymmetric = Family::antisymmetric;
      require(foundation.vertical_force, "Vertical force", 0, symmetric);
      require(foundation.torque, "Torque", 0, antisymmetric);
      require(foundation.horizontal_force, "Horizontal force", 1, symmetric);
      require(foundation.moment, "Moment", 1, symmetric);
      require(foundation.horizontal_force_y,
              "Horizontal force y",
              1,
              antisymmetric);
      require(foundation.moment_x, "Moment x", 1, antisymmetric);
      require(foundation.stiffness_coefficients ? 1. : 0.,
              "Stiffness coefficients (unit H and M)",
              1,
              symmetric);
      require(foundation.stiffness_matrix ? 1. : 0.,
              "Stiffness matrix (unit V)",
              0,
              symmetric);
      require(foundation.stiffness_matrix ? 1. : 0.,
              "Stiffness matrix (unit T)",
              0,
              antisymmetric);
      require(foundation.held_vertical_force,
              "Held vertical force",
              0,
              symmetric);
      require(foundation.held_torque, "Held torque", 0, antisymmetric);
      require(foundation.held_horizontal_force,
              "Held horizontal force",
              1,
              symmetric);
      require(foundation.held_moment, "Held moment", 1, symmetric);
    }

    /**
     * Held loads are a stage of a nonlinear load path; a linear solve has
     * no path (add them to the loads).
     */
    void
    check_held_loads_have_a_path(const AllParameters &parameters)
    {
      AssertThrow(!parameters.rigid_foundation.any_held() ||
                    parameters.coupled(),
                  ExcMessage("Rigid foundation/Held ...: held loads need a "
                             "nonlinear run (plastic soil or coulomb "
                             "interfaces); in a linear run add them to the "
                             "loads"));
    }

    /**
     * Interface state 3D draws the state of the nonlinear interfaces: a
     * scene without one would silently write nothing (a linear interface
     * has no state; its tractions are Write interface tractions).
     */
    void
    check_interface_state_3d_has_interfaces(const AllParameters &parameters)
    {
      AssertThrow(!parameters.output.interface_state_3d ||
                    parameters.interfaces.any_nonlinear(),
                  ExcMessage("Output/Interface state 3D: the scene has no "
                             "nonlinear (coulomb or contact) interface; "
                             "set it false or give Interfaces/Interfaces a "
                             "coulomb or contact law"));
    }

    /**
     * A rigid foundation tied to DoFs of a boundary fixed in u, v and w is
     * clamped by the supports (typically the soil's material id given as
     * the foundation's). Rollers (some components fixed, e.g. the
     * plane-strain disc's v = 0) are legal.
     */
    void
    check_foundation_not_clamped(const AllParameters    &parameters,
                                 const Triangulation<2> &triangulation)
    {
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      const BoundaryConditions        &bc = parameters.boundary_conditions;
      if (!foundation.enabled)
        return;
      const std::string tied =
        name_of(foundation.tie) + " " + std::to_string(foundation.id);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          {
            if (!face->at_boundary())
              continue;
            const auto fixed = bc.dirichlet.find(face->boundary_id());
            if (fixed == bc.dirichlet.end() || !fixed->second.given[0] ||
                !fixed->second.given[1] || !fixed->second.given[2])
              continue;
            const bool tied_here = foundation.tie == FoundationTie::material ?
                                     cell->material_id() == foundation.id :
                                     face->boundary_id() == foundation.id;
            AssertThrow(!tied_here,
                        ExcMessage("Rigid foundation/Id: " + tied +
                                   " touches boundary " +
                                   std::to_string(face->boundary_id()) +
                                   ", which Boundary conditions/Dirichlet "
                                   "fixes in u, v, w: the supports would "
                                   "clamp the rigid body (is " +
                                   tied + " the soil?)"));
          }
    }

    /** The mesh's bounding box in (r, z) and a round-off length of it. */
    struct MeshExtent
    {
      double r_max = 0., z_min = 0., z_max = 0.;
      double tolerance = 0.;
    };

    MeshExtent
    mesh_extent(const Triangulation<2> &triangulation)
    {
      MeshExtent extent;
      bool       first = true;
      for (const auto &v : triangulation.get_vertices())
        {
          extent.r_max = first ? v[0] : std::max(extent.r_max, v[0]);
          extent.z_min = first ? v[1] : std::min(extent.z_min, v[1]);
          extent.z_max = first ? v[1] : std::max(extent.z_max, v[1]);
          first        = false;
        }
      extent.tolerance =
        1e-10 * std::max(extent.r_max, extent.z_max - extent.z_min);
      return extent;
    }

    void
    check_surface_patch(const MeshParameters &mesh, const MeshExtent &extent)
    {
      if (mesh.type == MeshType::rectangle)
        AssertThrow(mesh.surface_patch_radius <=
                      extent.r_max + extent.tolerance,
                    ExcMessage("Mesh/Surface patch radius: " +
                               format(mesh.surface_patch_radius) +
                               " is wider than the mesh (outer radius " +
                               format(extent.r_max) + ", Mesh/R breakpoints)"));
    }

    /** G(depth) with alpha > 0 vanishes above the ground surface. */
    void
    check_graded_materials_below_surface(const MaterialLibrary  &materials,
                                         const Triangulation<2> &triangulation,
                                         const MeshExtent       &extent,
                                         std::vector<std::string> &notes)
    {
      const double                 surface = materials.surface_elevation;
      std::set<types::material_id> graded;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (materials.get(cell->material_id()).graded())
          {
            graded.insert(cell->material_id());
            AssertThrow(cell->center()[1] < surface + extent.tolerance,
                        ExcMessage(
                          "Materials/Ground surface elevation: " +
                          format(surface) + " is below cells of material " +
                          std::to_string(cell->material_id()) +
                          " (alpha > 0, G = 0 above the ground surface), "
                          "e.g. the cell at " +
                          at(cell->center()) +
                          "; the mesh spans z = " + format(extent.z_min) +
                          " .. " + format(extent.z_max)));
          }
      if (!graded.empty() && surface > extent.z_max + extent.tolerance)
        notes.push_back(
          "warning: Materials/Ground surface elevation " + format(surface) +
          " is " + format(surface - extent.z_max) +
          " m above the top of the mesh (z = " + format(extent.z_max) +
          "): the mesh's top is at that depth in G(depth)");
    }

    /** Both traction entries against both prescribed-displacement entries. */
    void
    check_tractions_on_fixed(const AllParameters      &parameters,
                             std::vector<std::string> &notes)
    {
      const BoundaryConditions &bc = parameters.boundary_conditions;
      for (const auto &[fixed, fixed_entry] :
           {std::make_pair(&bc.dirichlet, "Boundary conditions/Dirichlet"),
            std::make_pair(&parameters.loads.displacement,
                           "Loads/Prescribed displacement")})
        {
          check_traction_on_fixed(bc.traction,
                                  "Boundary conditions/Traction",
                                  *fixed,
                                  fixed_entry,
                                  notes);
          check_traction_on_fixed(parameters.loads.traction,
                                  "Loads/Traction",
                                  *fixed,
                                  fixed_entry,
                                  notes);
        }
    }

    /**
     * NaN and infinity in the prescribed values and tractions (the loads
     * given as functions of theta are checked by ThetaLoad::choose_samples
     * when the scene is planned).
     */
    void
    check_finite_loads(const AllParameters    &parameters,
                       const Triangulation<2> &triangulation,
                       const ScenePlan        &plan)
    {
      const BoundaryConditions &bc = parameters.boundary_conditions;
      check_finite_amplitudes(bc.dirichlet,
                              "Boundary conditions/Dirichlet",
                              false,
                              triangulation,
                              plan.harmonics);
      check_finite_amplitudes(bc.traction,
                              "Boundary conditions/Traction",
                              true,
                              triangulation,
                              plan.harmonics);
    }

    /**
     * Output/Lines 3D: every point must lie in the mesh (the 3D sum is
     * evaluated after the solve, too late to refuse).
     */
    void
    check_lines_in_mesh(const OutputParameters &output,
                        const Triangulation<2> &triangulation)
    {
      if (output.lines.empty())
        return;
      const MappingQ1<2>     mapping;
      GridTools::Cache<2, 2> cache(triangulation, mapping);
      for (const OutputLine &line : output.lines)
        for (unsigned int i = 0; i < line.n_points; ++i)
          {
            const double t =
              line.n_points == 1 ? 0. : double(i) / (line.n_points - 1);
            const Point<2> p     = line.start + t * (line.end - line.start);
            bool           found = false;
            try
              {
                const auto cell_and_point =
                  GridTools::find_active_cell_around_point(cache, p);
                found = cell_and_point.first.state() == IteratorState::valid;
              }
            catch (...)
              {}
            AssertThrow(found,
                        ExcMessage("Output/Lines 3D: the point " + at(p) +
                                   " of the line from " + at(line.start) +
                                   " to " + at(line.end) +
                                   " is outside the mesh"));
          }
    }

    /** Volumetric locking of FE_Q(2) near incompressibility. */
    void
    note_volumetric_locking(const AllParameters      &parameters,
                            std::vector<std::string> &notes)
    {
      const DiscretizationParameters &discretization =
        parameters.discretization;
      const double nu = largest_poisson_ratio(parameters.materials);
      if (discretization.degree != 2 || nu < locking_poisson_ratio)
        return;
      if (discretization.volumetric_automatic)
        notes.push_back("volumetric strain: bbar (Volumetric strain = auto: "
                        "FE_Q(2) with nu = " +
                        format(nu) + " >= " + format(locking_poisson_ratio) +
                        ")");
      else if (discretization.volumetric == VolumetricStrain::standard)
        notes.push_back(
          "warning: Discretization/Volumetric strain = standard with "
          "FE_Q(2) and nu = " +
          format(nu) +
          ": volumetric locking makes the soil too stiff (embedded "
          "footing at nu = 0.499: K_M +5.6 %, with bbar +0.6 %); solved "
          "as asked, 'auto' or 'bbar' avoids it");
    }
  } // namespace

  std::vector<std::string>
  check_scene_before_solve(const AllParameters    &parameters,
                           const Triangulation<2> &triangulation,
                           const ScenePlan        &plan)
  {
    std::vector<std::string> notes;
    check_foundation_loads_are_solved(parameters, plan);
    check_held_loads_have_a_path(parameters);
    check_interface_state_3d_has_interfaces(parameters);
    check_foundation_not_clamped(parameters, triangulation);
    const MeshExtent extent = mesh_extent(triangulation);
    check_surface_patch(parameters.mesh, extent);
    check_graded_materials_below_surface(parameters.materials,
                                         triangulation,
                                         extent,
                                         notes);
    check_tractions_on_fixed(parameters, notes);
    check_finite_loads(parameters, triangulation, plan);
    check_lines_in_mesh(parameters.output, triangulation);
    warn_cohesionless_soil(parameters, notes);
    note_volumetric_locking(parameters, notes);
    return notes;
  }

  namespace
  {
    /**
     * Why `directory` cannot be created or written, on one line (the
     * file system's exception would name neither the entry nor the
     * cause in words); empty if it can. The folder or, if it does not
     * exist yet, its nearest existing ancestor must be a directory the
     * user may write to.
     */
    std::string
    unwritable_directory_error(const std::string &directory)
    {
      std::error_code       ignored;
      std::filesystem::path existing =
        std::filesystem::absolute(directory, ignored);
      while (!std::filesystem::exists(existing, ignored) &&
             existing.has_relative_path())
        existing = existing.parent_path();
      const std::string what = "Output/Directory: '" + directory + "' ";
      if (!std::filesystem::is_directory(existing, ignored))
        return what + "cannot be created: '" + existing.string() +
               "' is a file";
      if (access(existing.c_str(), W_OK | X_OK) != 0)
        return what + "cannot be " +
               (existing == std::filesystem::absolute(directory, ignored) ?
                  "written" :
                  "created") +
               ": '" + existing.string() + "': " + std::strerror(errno);
      return "";
    }
  } // namespace

  std::string
  output_path_error(const OutputParameters &output)
  {
    // A .prm value is taken literally: 'Directory = ""' would create a
    // folder named "" (two quote characters), an empty value has no folder
    // to create.
    const std::string directory = Utilities::trim(output.directory);
    const bool        quoted =
      directory.size() >= 2 &&
      (directory.front() == '"' || directory.front() == '\'') &&
      directory.back() == directory.front();
    if (directory.empty() || quoted)
      return "Output/Directory: '" + directory +
             "' is not a folder name (values are taken literally, without "
             "quotes); give one such as output, or . for the working folder";
    if (Utilities::trim(output.results_file).empty())
      return "Output/Results file: empty; give a file name such as "
             "results.csv";
    if (std::filesystem::exists(output.directory) &&
        !std::filesystem::is_directory(output.directory))
      return "Output/Directory: '" + output.directory +
             "' exists and is not a directory";
    const std::string unwritable = unwritable_directory_error(directory);
    if (!unwritable.empty())
      return unwritable;
    // Checked before the output folder is created: a name that can only
    // be a folder ("." , "..", "sub/") counts as one even if it does not
    // exist yet.
    const std::string results = output.directory + "/" + output.results_file;
    const std::filesystem::path name = output.results_file;
    if (std::filesystem::is_directory(results) || !name.has_filename() ||
        name.filename() == "." || name.filename() == "..")
      return "Output/Results file: '" + results + "' is a directory";
    return results_file_name_error(Utilities::trim(output.results_file));
  }
} // namespace FourierSSI
