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
#include <set>
#include <sstream>
#include <unistd.h>

namespace FourierSSI
{
  double
  largest_poisson_ratio(const MaterialLibrary &materials)
  {
    double nu = -1.;
    for (const auto &[id, material] : materials.all())
      nu = std::max(nu, material.poisson_ratio);
    return nu;
  }

  namespace
  {
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
        if (law.kind == SoilLaw::Kind::mohr_coulomb && law.cohesion == 0.)
          notes.push_back(
            "warning: Soil plasticity/Laws: material " + std::to_string(id) +
            ": mohr-coulomb with c = 0 and no Initial stress has no strength "
            "at the start of the path; unless the loads compress it all "
            "round the first step will not converge (give c > 0 or Initial "
            "stress)");
    }
  } // namespace

  std::vector<std::string>
  check_scene_before_solve(const AllParameters    &parameters,
                           const Triangulation<2> &triangulation,
                           const ScenePlan        &plan)
  {
    std::vector<std::string>         notes;
    const DiscretizationParameters  &discretization = parameters.discretization;
    const RigidFoundationParameters &foundation = parameters.rigid_foundation;
    const BoundaryConditions        &bc = parameters.boundary_conditions;

    // A foundation resultant acts on one harmonic only: a list without it
    // solves a scene without that load.
    if (foundation.enabled && !discretization.automatic)
      {
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
        require(foundation.vertical_force,
                "Vertical force",
                0,
                Family::symmetric);
        require(foundation.torque, "Torque", 0, Family::antisymmetric);
        require(foundation.horizontal_force,
                "Horizontal force",
                1,
                Family::symmetric);
        require(foundation.moment, "Moment", 1, Family::symmetric);
        require(foundation.horizontal_force_y,
                "Horizontal force y",
                1,
                Family::antisymmetric);
        require(foundation.moment_x, "Moment x", 1, Family::antisymmetric);
        require(foundation.stiffness_coefficients ? 1. : 0.,
                "Stiffness coefficients (unit H and M)",
                1,
                Family::symmetric);
        require(foundation.stiffness_matrix ? 1. : 0.,
                "Stiffness matrix (unit V)",
                0,
                Family::symmetric);
        require(foundation.stiffness_matrix ? 1. : 0.,
                "Stiffness matrix (unit T)",
                0,
                Family::antisymmetric);
        require(foundation.held_vertical_force,
                "Held vertical force",
                0,
                Family::symmetric);
        require(foundation.held_torque,
                "Held torque",
                0,
                Family::antisymmetric);
        require(foundation.held_horizontal_force,
                "Held horizontal force",
                1,
                Family::symmetric);
        require(foundation.held_moment, "Held moment", 1, Family::symmetric);
      }

    // Held loads are a stage of a nonlinear load path; a linear solve has
    // no path (add them to the loads).
    AssertThrow(!foundation.any_held() || parameters.soil_plasticity.any(),
                ExcMessage("Rigid foundation/Held ...: not yet: held loads "
                           "without plastic soil (in a linear or interface "
                           "run add them to the loads)"));

    // A rigid foundation tied to DoFs of a boundary fixed in u, v and w is
    // clamped by the supports (typically the soil's material id given as
    // the foundation's). Rollers (some components fixed, e.g. the
    // plane-strain disc's v = 0) are legal.
    if (foundation.enabled)
      {
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
                          ExcMessage(
                            "Rigid foundation/Id: " + tied +
                            " touches "
                            "boundary " +
                            std::to_string(face->boundary_id()) +
                            ", which Boundary conditions/Dirichlet fixes in "
                            "u, v, w: the supports would clamp the rigid "
                            "body (is " +
                            tied + " the soil?)"));
            }
      }

    // Mesh extent.
    double r_max = 0., z_min = 0., z_max = 0.;
    bool   first = true;
    for (const auto &v : triangulation.get_vertices())
      {
        r_max = first ? v[0] : std::max(r_max, v[0]);
        z_min = first ? v[1] : std::min(z_min, v[1]);
        z_max = first ? v[1] : std::max(z_max, v[1]);
        first = false;
      }
    const double tolerance = 1e-10 * std::max(r_max, z_max - z_min);

    const MeshBuilder &mesh = parameters.mesh;
    if (mesh.type == MeshType::rectangle)
      AssertThrow(mesh.surface_patch_radius <= r_max + tolerance,
                  ExcMessage("Mesh/Surface patch radius: " +
                             format(mesh.surface_patch_radius) +
                             " is wider than the mesh (outer radius " +
                             format(r_max) + ", Mesh/R breakpoints)"));

    // G(depth) with alpha > 0 vanishes above the ground surface.
    const MaterialLibrary       &materials = parameters.materials;
    const double                 surface   = materials.surface_elevation;
    std::set<types::material_id> graded;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (materials.get(cell->material_id()).alpha > 0.)
        {
          graded.insert(cell->material_id());
          AssertThrow(cell->center()[1] < surface + tolerance,
                      ExcMessage(
                        "Materials/Ground surface elevation: " +
                        format(surface) + " is below cells of material " +
                        std::to_string(cell->material_id()) +
                        " (alpha > 0, G = 0 above the ground surface), "
                        "e.g. the cell at " +
                        at(cell->center()) + "; the mesh spans z = " +
                        format(z_min) + " .. " + format(z_max)));
        }
    if (!graded.empty() && surface > z_max + tolerance)
      notes.push_back("warning: Materials/Ground surface elevation " +
                      format(surface) + " is " + format(surface - z_max) +
                      " m above the top of the mesh (z = " + format(z_max) +
                      "): the mesh's top is at that depth in G(depth)");

    // Tractions on fixed DoFs.
    check_traction_on_fixed(bc.traction,
                            "Boundary conditions/Traction",
                            bc.dirichlet,
                            "Boundary conditions/Dirichlet",
                            notes);
    check_traction_on_fixed(parameters.loads.traction,
                            "Loads/Traction",
                            bc.dirichlet,
                            "Boundary conditions/Dirichlet",
                            notes);
    check_traction_on_fixed(bc.traction,
                            "Boundary conditions/Traction",
                            parameters.loads.displacement,
                            "Loads/Prescribed displacement",
                            notes);
    check_traction_on_fixed(parameters.loads.traction,
                            "Loads/Traction",
                            parameters.loads.displacement,
                            "Loads/Prescribed displacement",
                            notes);

    // NaN and infinity in the loads and prescribed values.
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
    // (The loads given as functions of theta are checked by
    // ThetaLoad::choose_samples when the scene is planned.)

    // Lines 3D: every point must lie in the mesh (the 3D sum is evaluated
    // after the solve).
    const OutputParameters &output = parameters.output;
    if (!output.lines.empty())
      {
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

    warn_cohesionless_soil(parameters, notes);

    // Volumetric locking of FE_Q(2) near incompressibility.
    const double nu = largest_poisson_ratio(materials);
    if (discretization.degree == 2 && nu >= locking_poisson_ratio)
      {
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
    return notes;
  }

  namespace
  {
    /**
     * Displacement control drives the controlled motion from where the
     * held stage left it to Target: a Target of 0 is a path of zero length
     * (every step the unloaded state, reported as converged).
     */
    void
    check_displacement_target(const AllParameters &parameters)
    {
      const NonlinearInterfaceParameters &path =
        parameters.nonlinear_interfaces;
      AssertThrow(!parameters.coupled() ||
                    path.control !=
                      NonlinearInterfaceParameters::Control::displacement ||
                    path.target != 0.,
                  ExcMessage("Nonlinear interfaces/Target: 0 with Control = "
                             "displacement, the controlled motion would not "
                             "move; give its final value [m or rad]"));
    }

    /**
     * Displacement control drives the Controlled motion; holding it at
     * zero as well is a contradiction.
     */
    void
    check_controlled_motion_not_held(const AllParameters &parameters)
    {
      const NonlinearInterfaceParameters &path =
        parameters.nonlinear_interfaces;
      if (!parameters.coupled() ||
          path.control != NonlinearInterfaceParameters::Control::displacement)
        return;
      using M = NonlinearInterfaceParameters::Motion;
      const FoundationMotion driven =
        path.motion == M::vertical   ? FoundationMotion::w :
        path.motion == M::twist      ? FoundationMotion::twist :
        path.motion == M::horizontal ? FoundationMotion::u :
                                       FoundationMotion::rotation;
      AssertThrow(!parameters.rigid_foundation.holds(driven),
                  ExcMessage("Rigid foundation/Held motions: '" +
                             name_of(driven) +
                             "' is also the Nonlinear interfaces/Controlled "
                             "motion; hold another motion or drive another"));
    }

    /** True if some load of the scene is not zero. */
    bool
    scene_has_load(const AllParameters &parameters)
    {
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      const BoundaryConditions        &bc = parameters.boundary_conditions;
      const auto                       any_nonzero =
        [](const std::map<types::boundary_id, ComponentExpressions> &entries) {
          for (const auto &[id, e] : entries)
            if (!e.is_zero())
              return true;
          return false;
        };
      const bool foundation_load =
        foundation.enabled &&
        (foundation.horizontal_force != 0. || foundation.moment != 0. ||
         foundation.horizontal_force_y != 0. || foundation.moment_x != 0. ||
         foundation.vertical_force != 0. || foundation.torque != 0. ||
         foundation.any_held());
      return foundation_load || !bc.body_force.is_zero() ||
             any_nonzero(bc.traction) || any_nonzero(bc.dirichlet) ||
             any_nonzero(parameters.loads.traction) ||
             any_nonzero(parameters.loads.displacement);
    }

    /**
     * Load control scales the scene's loads along the path: with every
     * load zero each step solves the unloaded state (displacement control
     * refuses the same scene when the pattern solve finds no motion).
     */
    void
    check_load_control_has_load(const AllParameters &parameters)
    {
      AssertThrow(!parameters.coupled() ||
                    parameters.nonlinear_interfaces.control !=
                      NonlinearInterfaceParameters::Control::load ||
                    scene_has_load(parameters),
                  ExcMessage("Nonlinear interfaces/Control = load: every "
                             "load is zero (Rigid foundation, Loads, "
                             "Boundary conditions, Body force), the path "
                             "has nothing to scale"));
    }

    /**
     * The error norms compare one harmonic's amplitudes with a closed form
     * (a linear solve); the coupled paths (plastic soil, coulomb
     * interfaces) do not compute them.
     */
    void
    check_exact_solution_linear(const AllParameters &parameters)
    {
      AssertThrow(!parameters.exact_solution.enabled || !parameters.coupled(),
                  ExcMessage("Exact solution/Enabled: error norms are "
                             "computed for linear runs only, not with "
                             "plastic soil or a coulomb interface; set it "
                             "false"));
    }
  } // namespace

  void
  check_problem_is_meaningful(const AllParameters &parameters)
  {
    check_controlled_motion_not_held(parameters);
    check_displacement_target(parameters);
    check_load_control_has_load(parameters);
    check_exact_solution_linear(parameters);
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
    return "";
  }
} // namespace FourierSSI
