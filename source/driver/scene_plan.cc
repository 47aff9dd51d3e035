#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <set>
#include <sstream>

namespace FourierSSI
{
  std::string
  compact_list(const std::vector<unsigned int> &numbers)
  {
    std::ostringstream out;
    for (unsigned int i = 0; i < numbers.size();)
      {
        unsigned int j = i;
        while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1)
          ++j;
        out << (i > 0 ? ", " : "") << numbers[i];
        if (j > i)
          out << (j == i + 1 ? ", " : "..") << numbers[j];
        i = j + 1;
      }
    return out.str();
  }

  namespace
  {
    std::string
    format(const double value)
    {
      std::ostringstream s;
      s.precision(3);
      s << value;
      return s.str();
    }

    /** Points of the boundary faces with an id: vertices and Gauss points. */
    std::vector<Point<2>>
    boundary_points(const Triangulation<2>  &triangulation,
                    const types::boundary_id id,
                    const std::string       &entry)
    {
      std::vector<Point<2>> points;
      const QGauss<1>       gauss(4);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            {
              const Point<2> a = cell->face(f)->vertex(0);
              const Point<2> b = cell->face(f)->vertex(1);
              points.push_back(a);
              points.push_back(b);
              for (const auto &q : gauss.get_points())
                points.push_back(a + q[0] * (b - a));
            }
      AssertThrow(!points.empty(),
                  ExcMessage(entry + ": boundary id " + std::to_string(id) +
                             " does not exist on the mesh"));
      return points;
    }
  } // namespace

  namespace
  {
    /** Why each harmonic is solved: the loads and resultants it carries. */
    using HarmonicReasons =
      std::map<std::pair<unsigned int, Family>, std::vector<std::string>>;

    /**
     * Decompose the theta-dependent loads: choose their sampling, read the
     * amplitude of every harmonic at points of their boundaries, and note
     * the harmonics above Loads/Harmonic tolerance.
     */
    void
    decompose_loads(const AllParameters    &parameters,
                    const Triangulation<2> &triangulation,
                    ScenePlan              &plan,
                    HarmonicReasons        &reasons)
    {
      const LoadParameters &load_parameters = parameters.loads;
      const unsigned int    n_max           = load_parameters.max_harmonic;
      // Theta-dependent loads: choose their sampling, then read the amplitude
      // of every harmonic at points of their boundaries.
      const auto scan =
        [&](const std::map<types::boundary_id, ComponentExpressions> &entries,
            const std::string                                        &entry,
            std::map<types::boundary_id, std::shared_ptr<ThetaLoad>> &loads) {
          for (const auto &[id, expressions] : entries)
            {
              const std::string name = entry + " " + std::to_string(id);
              auto load = std::make_shared<ThetaLoad>(expressions, name, n_max);
              const std::vector<Point<2>> points =
                boundary_points(triangulation, id, entry);
              // Aliasing one decade below the selection tolerance.
              const double largest =
                load->choose_samples(points, 0.1 * load_parameters.tolerance);
              loads[id] = load;
              std::map<std::pair<unsigned int, Family>, double> amplitude;
              for (const Point<2> &p : points)
                {
                  const PointSpectrum &s = load->spectrum(p);
                  for (const Family family :
                       {Family::symmetric, Family::antisymmetric})
                    for (unsigned int n = 0; n <= n_max; ++n)
                      for (const double c : s.get({n, family}))
                        amplitude[{n, family}] =
                          std::max(amplitude[{n, family}], std::abs(c));
                }
              std::vector<std::string> selected;
              double                   largest_skipped = 0.;
              for (const auto &[key, a] : amplitude)
                {
                  const double relative = largest > 0. ? a / largest : 0.;
                  plan.load_amplitudes[key] =
                    std::max(plan.load_amplitudes[key], relative);
                  if (relative > load_parameters.tolerance)
                    {
                      reasons[key].push_back(name);
                      selected.push_back(
                        Harmonic{key.first, key.second}.name() + " (" +
                        format(relative) + ")");
                    }
                  else
                    largest_skipped = std::max(largest_skipped, relative);
                }
              std::ostringstream line;
              line << name << ": " << load->n_samples()
                   << " samples in theta; relative amplitudes above "
                   << format(load_parameters.tolerance) << ": ";
              for (unsigned int i = 0; i < selected.size(); ++i)
                line << (i > 0 ? ", " : "") << selected[i];
              if (selected.empty())
                line << "none (zero load)";
              line << "; largest amplitude skipped " << format(largest_skipped);
              plan.log_lines.push_back(line.str());
              const double at_n_max =
                std::max(amplitude[{n_max, Family::symmetric}],
                         amplitude[{n_max, Family::antisymmetric}]);
              if (largest > 0. &&
                  at_n_max > load_parameters.tolerance * largest)
                plan.log_lines.push_back(
                  "warning: " + name + " still has relative amplitude " +
                  format(at_n_max / largest) +
                  " at n = " + std::to_string(n_max) +
                  ", the series is truncated there (Loads/Maximum harmonic)");
            }
        };
      scan(load_parameters.traction, "Loads/Traction", plan.loads.traction);
      scan(load_parameters.displacement,
           "Loads/Prescribed displacement",
           plan.loads.displacement);
      for (const auto &[id, e] : load_parameters.displacement)
        plan.loads.displacement_components[id] = e.given;
    }

    /**
     * Resultants on a rigid foundation map to harmonics exactly: V -> n = 0
     * symmetric, T -> n = 0 antisymmetric, H_x, M_y -> n = 1 symmetric,
     * H_y, M_x -> n = 1 antisymmetric; the stiffness coefficients need
     * n = 1 symmetric.
     */
    void
    map_foundation_resultants(const AllParameters &parameters,
                              HarmonicReasons     &reasons)
    {
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      if (foundation.enabled)
        {
          const auto add = [&](const double       value,
                               const unsigned int n,
                               const Family       family,
                               const std::string &what) {
            if (value != 0.)
              reasons[{n, family}].push_back(what);
          };
          add(foundation.vertical_force, 0, Family::symmetric, "V");
          add(foundation.torque, 0, Family::antisymmetric, "T");
          add(foundation.horizontal_force, 1, Family::symmetric, "H_x");
          add(foundation.moment, 1, Family::symmetric, "M_y");
          add(foundation.horizontal_force_y, 1, Family::antisymmetric, "H_y");
          add(foundation.moment_x, 1, Family::antisymmetric, "M_x");
          add(foundation.held_vertical_force, 0, Family::symmetric, "held V");
          add(foundation.held_torque, 0, Family::antisymmetric, "held T");
          add(foundation.held_horizontal_force,
              1,
              Family::symmetric,
              "held H_x");
          add(foundation.held_moment, 1, Family::symmetric, "held M_y");
          if (foundation.stiffness_coefficients)
            reasons[{1, Family::symmetric}].push_back(
              "unit H and M for the stiffness coefficients");
          if (foundation.stiffness_matrix)
            {
              reasons[{0, Family::symmetric}].push_back(
                "unit V for the stiffness matrix");
              reasons[{0, Family::antisymmetric}].push_back(
                "unit T for the stiffness matrix");
            }
        }
    }

    /**
     * A boundary amplitude on a boundary id the mesh has, and finite there
     * (evaluated with n = 0): what is wrong with it is said before that it
     * is an amplitude at all (Harmonics = auto).
     */
    void
    require_usable_amplitude(const Triangulation<2>     &triangulation,
                             const types::boundary_id    id,
                             const ComponentExpressions &expressions,
                             const std::string          &entry)
    {
      const auto function =
        BoundaryConditions::make_function(expressions, 0, entry);
      Vector<double> value(3);
      for (const Point<2> &p : boundary_points(triangulation, id, entry))
        {
          function->vector_value(p, value);
          for (unsigned int c = 0; c < 3; ++c)
            AssertThrow(!expressions.given[c] || std::isfinite(value(c)),
                        ExcMessage(entry + ": boundary " + std::to_string(id) +
                                   ", '" + expressions.expression[c] + "' is " +
                                   (std::isnan(value(c)) ? "NaN" : "infinite") +
                                   " at (r, z) = (" + std::to_string(p[0]) +
                                   ", " + std::to_string(p[1]) + ") m"));
        }
    }

    /**
     * The harmonics to solve: those with a reason (Harmonics = auto) or the
     * listed ones (with a warning for a loaded harmonic left out).
     */
    void
    select_harmonics(const AllParameters    &parameters,
                     const Triangulation<2> &triangulation,
                     const HarmonicReasons  &reasons,
                     ScenePlan              &plan)
    {
      const DiscretizationParameters &discretization =
        parameters.discretization;
      const LoadParameters            &load_parameters = parameters.loads;
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      const unsigned int               n_max = load_parameters.max_harmonic;
      if (discretization.automatic)
        {
          // Amplitude expressions (Boundary conditions, Body force) are the
          // same text for every harmonic: they cannot say which harmonics a
          // load contains unless they are zero.
          const BoundaryConditions &bc = parameters.boundary_conditions;
          const auto require_zero      = [](const ComponentExpressions &e,
                                       const std::string          &entry) {
            for (unsigned int c = 0; c < 3; ++c)
              AssertThrow(!e.given[c] || is_literal_zero(e.expression[c]),
                          ExcMessage(
                            entry + ": '" + e.expression[c] +
                            "' is a harmonic amplitude; with Discretization/"
                                 "Harmonics = auto give the load as a function of "
                                 "theta in the Loads subsection, or list the "
                                 "harmonics"));
          };
          for (const auto &[id, e] : bc.dirichlet)
            {
              require_usable_amplitude(triangulation,
                                       id,
                                       e,
                                       "Boundary conditions/Dirichlet");
              require_zero(e, "Boundary conditions/Dirichlet");
            }
          for (const auto &[id, e] : bc.traction)
            {
              require_usable_amplitude(triangulation,
                                       id,
                                       e,
                                       "Boundary conditions/Traction");
              require_zero(e, "Boundary conditions/Traction");
            }
          require_zero(bc.body_force, "Body force");

          for (const auto &[key, why] : reasons)
            plan.harmonics.push_back({key.first, key.second});
          AssertThrow(!plan.harmonics.empty(),
                      ExcMessage(
                        "Discretization/Harmonics = auto: the scene has "
                        "no load (no foundation resultant, no load in "
                        "the Loads subsection), nothing to solve"));
          std::ostringstream line;
          line << "harmonics solved:";
          for (const auto &[key, why] : reasons)
            {
              line << "\n    " << Harmonic{key.first, key.second}.name()
                   << ": ";
              for (unsigned int i = 0; i < why.size(); ++i)
                line << (i > 0 ? ", " : "") << why[i];
            }
          plan.log_lines.push_back(line.str());
          for (const Family family : {Family::symmetric, Family::antisymmetric})
            {
              std::vector<unsigned int> skipped;
              for (unsigned int n = 0; n <= n_max; ++n)
                if (reasons.count({n, family}) == 0)
                  skipped.push_back(n);
              if (!skipped.empty())
                plan.log_lines.push_back(
                  "skipped " + to_string(family) + " n = " +
                  compact_list(skipped) + ": no load amplitude above " +
                  format(load_parameters.tolerance) +
                  (foundation.enabled ? " and no foundation resultant" : ""));
            }
        }
      else
        {
          plan.harmonics = discretization.harmonics;
          std::ostringstream line;
          line << "harmonics solved (as listed in Discretization/Harmonics):";
          for (const Harmonic &h : plan.harmonics)
            line << " " << h.name() << ";";
          plan.log_lines.push_back(line.str());
          for (const auto &[key, why] : reasons)
            if (std::none_of(plan.harmonics.begin(),
                             plan.harmonics.end(),
                             [&](const Harmonic &h) {
                               return h.n == key.first &&
                                      h.family == key.second;
                             }))
              plan.log_lines.push_back(
                "warning: " + Harmonic{key.first, key.second}.name() +
                " carries load (" + why.front() +
                ") but is not in the list: not solved");
        }
    }

    /**
     * What Output/Write vtu writes in this run, as the log says it: the
     * coupled runs write the last converged step; the stress of plastic
     * soil is not C eps(u), so only its displacements are written.
     */
    std::string
    vtu_per_harmonic(const AllParameters &parameters)
    {
      const OutputParameters &output = parameters.output;
      if (!output.write_vtu)
        return "skipped (Output/Write vtu = false)";
      if (parameters.soil_plasticity.any())
        return "displacement amplitudes of the last converged step (stresses "
               "not written with plastic soil: C eps(u) omits the plastic "
               "strain)";
      const std::string fields =
        output.write_stresses ? "displacement and stress amplitudes" :
                                "displacement amplitudes (stresses not asked)";
      return parameters.interfaces.any_nonlinear() ?
               fields + " of the last converged step" :
               fields;
    }

    /** What Output/Write interface tractions writes in this run. */
    std::string
    interface_tractions_output(const AllParameters &parameters)
    {
      if (parameters.interfaces.any_nonlinear())
        return std::string(
                 "interface-state.csv (nonlinear interfaces: state, "
                 "tractions and relative displacements per point, angle and "
                 "step)") +
               (parameters.output.interface_state_3d ?
                  "; as a revolved surface: interface-state-3d-step<s>.vtu "
                  "(Output/Interface state 3D)" :
                  "");
      if (parameters.soil_plasticity.any())
        return "not written with plastic soil and linear interfaces";
      return parameters.output.write_interface_tractions ?
               "written" :
               "skipped (Output/Write interface tractions = false)";
    }

    /** One log line per effect: simulated, or skipped and why. */
    void
    describe_effects(const AllParameters    &parameters,
                     const Triangulation<2> &triangulation,
                     ScenePlan              &plan)
    {
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      if (parameters.interfaces.enabled())
        {
          std::ostringstream line;
          line << "interfaces: assembled on boundary ids";
          for (const auto &[id, law] : parameters.interfaces.laws)
            line << " " << id;
          plan.log_lines.push_back(line.str());
        }
      else
        plan.log_lines.push_back(
          "interfaces: none declared, no interface assembly");
      std::set<types::material_id> used;
      for (const auto &cell : triangulation.active_cell_iterators())
        used.insert(cell->material_id());
      for (const types::material_id id : used)
        {
          const ElasticMaterial &m = parameters.materials.get(id);
          plan.log_lines.push_back(
            "material " + std::to_string(id) +
            (m.hardin() ?
               ": G0 = G_ref (p'0/" + format(m.hardin_reference_stress) +
                 " kPa)^" + format(m.hardin_exponent) +
                 " (Hardin), p'0 the geostatic mean effective stress, "
                 "evaluated at every quadrature point" :
             m.alpha == 0. ?
               ": homogeneous (alpha = 0), constant moduli" :
               ": G(depth) = G_ref (depth/" + format(m.depth_ref) + ")^" +
                 format(m.alpha) + " evaluated at every quadrature point"));
        }
      if (!foundation.enabled)
        plan.log_lines.push_back("stiffness coefficients: skipped (no rigid "
                                 "foundation)");
      else if (!foundation.stiffness_coefficients)
        plan.log_lines.push_back("stiffness coefficients: skipped (Rigid "
                                 "foundation/Stiffness coefficients = false)");
      else
        plan.log_lines.push_back("stiffness coefficients: unit-H and unit-M "
                                 "solves on n = 1 symmetric");
      if (foundation.enabled && foundation.stiffness_matrix)
        plan.log_lines.push_back(
          "stiffness matrix: unit-V and unit-T solves on n = 0 symmetric and "
          "antisymmetric; 6x6 matrix written to foundation-stiffness.csv and "
          "foundation-stiffness-subdyn.txt");
      const OutputParameters &output = parameters.output;
      plan.log_lines.push_back("VTU per harmonic: " +
                               vtu_per_harmonic(parameters));
      if (parameters.interfaces.enabled())
        plan.log_lines.push_back("interface tractions CSV: " +
                                 interface_tractions_output(parameters));
      plan.log_lines.push_back(
        std::string("3D reconstruction: ") +
        (output.lines.empty() && !output.write_3d_vtu ?
           "skipped (no Output/Lines 3D, Output/Write 3D vtu = false)" :
           (output.lines.empty() ?
              std::string() :
              std::to_string(output.lines.size()) + " line(s) at " +
                std::to_string(output.theta_degrees.size()) + " angle(s)" +
                (output.write_3d_vtu ? ", " : "")) +
             (output.write_3d_vtu ? "revolved 3D VTU" : "")));
    }
  } // namespace

  MeshSequence
  mesh_sequence_of(const AllParameters &parameters)
  {
    if (parameters.discretization.target_accuracy > 0.)
      return MeshSequence::target_accuracy;
    if (parameters.discretization.refinement_cycles > 1)
      return MeshSequence::refinement_cycles;
    return MeshSequence::one_mesh;
  }

  RunMode
  run_mode_of(const AllParameters &parameters)
  {
    if (parameters.soil_plasticity.any())
      return RunMode::plastic_soil;
    // A swipe keeps w by a second multiplier, solved on the coupled tangent
    // (AllParameters::linearises_on_coupled_tangent) with no soil points.
    if (parameters.interfaces.any_nonlinear())
      return parameters.rigid_foundation.swipes() ?
               RunMode::interface_swipe :
               RunMode::interface_load_path;
    if (mesh_sequence_of(parameters) == MeshSequence::target_accuracy)
      return RunMode::linear_target;
    return RunMode::linear_cycles;
  }

  bool
  is_coupled(const RunMode mode)
  {
    return mode == RunMode::interface_load_path ||
           mode == RunMode::interface_swipe || mode == RunMode::plastic_soil;
  }

  ScenePlan
  plan_scene(const AllParameters    &parameters,
             const Triangulation<2> &triangulation)
  {
    ScenePlan plan;
    plan.run_mode = run_mode_of(parameters);
    plan.meshes   = mesh_sequence_of(parameters);
    HarmonicReasons reasons;
    decompose_loads(parameters, triangulation, plan, reasons);
    map_foundation_resultants(parameters, reasons);
    select_harmonics(parameters, triangulation, reasons, plan);
    describe_effects(parameters, triangulation, plan);
    return plan;
  }
} // namespace FourierSSI
