#include <algorithm>
#include <fourier_ssi/input/problem_checks.h>
#include <string>

namespace FourierSSI
{
  namespace
  {
    /**
     * A capacity needs a nonlinear source: without plastic soil or a
     * coulomb or contact interface the load path is one linear solve, and a
     * displacement-controlled path to a capacity (or its normalisation)
     * would print an elastic answer as if it were one (exit 0).
     */
    void
    check_capacity_needs_nonlinear_source(const AllParameters &parameters)
    {
      if (parameters.coupled())
        return;
      const std::string why =
        ": the scene has no nonlinear source (Soil plasticity/Laws is empty "
        "and no interface is coulomb or contact), so it is one linear solve "
        "with no capacity; add a law";
      AssertThrow(parameters.load_path.control !=
                    LoadPathParameters::Control::displacement,
                  ExcMessage("Load path/Control = displacement" + why +
                             ", or leave Control at load"));
      AssertThrow(parameters.rigid_foundation.capacity_name.empty(),
                  ExcMessage("Rigid foundation/Capacity normalisation" + why +
                             ", or leave the entry empty"));
    }

    /**
     * Displacement control drives the controlled motion from where the
     * held stage left it to Target: a Target of 0 is a path of zero length
     * (every step the unloaded state, reported as converged).
     */
    void
    check_displacement_target(const AllParameters &parameters)
    {
      const LoadPathParameters &path = parameters.load_path;
      AssertThrow(!parameters.coupled() ||
                    path.control != LoadPathParameters::Control::displacement ||
                    path.target != 0. || path.is_cyclic(),
                  ExcMessage("Load path/Target: 0 with Control = "
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
      const LoadPathParameters &path = parameters.load_path;
      if (!parameters.coupled() ||
          path.control != LoadPathParameters::Control::displacement)
        return;
      using M = LoadPathParameters::Motion;
      const FoundationMotion driven =
        path.motion == M::vertical   ? FoundationMotion::w :
        path.motion == M::twist      ? FoundationMotion::twist :
        path.motion == M::horizontal ? FoundationMotion::u :
                                       FoundationMotion::rotation;
      AssertThrow(!parameters.rigid_foundation.holds(driven),
                  ExcMessage("Rigid foundation/Held motions: '" +
                             name_of(driven) +
                             "' is also the Load path/Controlled "
                             "motion; hold another motion or drive another"));
    }

    /**
     * A direction probe (Rigid foundation/Motion direction) moves u and
     * theta in a fixed ratio: displacement control must drive a motion
     * with a component along it.
     */
    void
    check_motion_direction_path(const AllParameters &parameters)
    {
      const RigidFoundationParameters &f = parameters.rigid_foundation;
      if (!f.probes_direction() || !parameters.coupled())
        return;
      const std::string         entry = "Rigid foundation/Motion direction";
      const LoadPathParameters &path  = parameters.load_path;
      if (path.control != LoadPathParameters::Control::displacement)
        return;
      using M = LoadPathParameters::Motion;
      AssertThrow(!(path.motion == M::horizontal && f.direction_u == 0.) &&
                    !(path.motion == M::rotation && f.direction_rotation == 0.),
                  ExcMessage("Load path/Controlled motion: it does not move "
                             "along " +
                             entry + " = '" + f.motion_direction +
                             "' (its component there is 0); control the "
                             "other motion"));
    }

    /**
     * A swipe (w held at the value a Held vertical force reached) is solved
     * by the coupled tangent solver's load multiplier mu on the vertical
     * load (also for nonlinear interfaces on elastic soil); what is not
     * written for it yet is refused rather than run with w free.
     */
    void
    check_swipe_path(const AllParameters &parameters)
    {
      if (!parameters.rigid_foundation.swipes())
        return;
      const std::string entry =
        "Rigid foundation/Held motions: 'w' with a Held vertical force (a "
        "swipe)";
      AssertThrow(parameters.discretization.target_accuracy == 0.,
                  ExcMessage(entry + ": not yet with Discretization/Target "
                                     "accuracy (the capacity with error bars "
                                     "is that of the applied drive alone)"));
    }

    /**
     * A cyclic path (Load path/Targets) needs a source of hysteresis, and
     * what is computed from one monotonic curve (a capacity with error
     * bars, refinement by the last step's mechanism, the swipe and the
     * probe) does not apply to it.
     */
    void
    check_cyclic_path(const AllParameters &parameters)
    {
      if (!parameters.load_path.is_cyclic())
        return;
      const std::string entry = "Load path/Targets";
      AssertThrow(parameters.coupled(),
                  ExcMessage(entry +
                             ": the scene is linear elastic (no Soil "
                             "plasticity/Laws, no coulomb or contact "
                             "interface): its cycles retrace one line and "
                             "dissipate nothing"));
      AssertThrow(parameters.rigid_foundation.enabled,
                  ExcMessage(entry + ": needs a Rigid foundation, whose load "
                                     "and motion the cycles are drawn in"));
      AssertThrow(parameters.discretization.target_accuracy == 0. &&
                    parameters.discretization.refinement_cycles == 1,
                  ExcMessage(entry +
                             ": not with Discretization/Target accuracy or "
                             "Refinement cycles > 1 (they estimate a capacity "
                             "of a monotonic path)"));
      AssertThrow(!parameters.rigid_foundation.swipes() &&
                    !parameters.rigid_foundation.probes_direction(),
                  ExcMessage(entry + ": not yet with a swipe or a Motion "
                                     "direction probe (monotonic paths)"));
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
                    parameters.load_path.control !=
                      LoadPathParameters::Control::load ||
                    scene_has_load(parameters),
                  ExcMessage("Load path/Control = load: every "
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

    /**
     * Load path/Maximum harmonic is the highest harmonic the solution may
     * add to those listed; set below them it can add none and is most
     * likely a typing error (0, the default, asks for no growth).
     */
    void
    check_maximum_harmonic_not_below_listed(const AllParameters &parameters)
    {
      const unsigned int maximum = parameters.load_path.maximum_harmonic;
      unsigned int       highest = 0;
      for (const Harmonic &h : parameters.discretization.harmonics)
        highest = std::max(highest, h.n);
      AssertThrow(maximum == 0 || maximum >= highest,
                  ExcMessage(
                    "Load path/Maximum harmonic: " + std::to_string(maximum) +
                    " is below the highest listed harmonic n = " +
                    std::to_string(highest) +
                    " (Discretization/Harmonics); set it above " +
                    std::to_string(highest) +
                    " for harmonics chosen by the solution, or 0 "
                    "for the listed ones only"));
    }

    /**
     * Mesh/Interface lines splits the mesh along each line: without a law
     * the split faces connect nothing, and the bodies on either side come
     * apart (a singular system, or a body that floats).
     */
    void
    check_interface_lines_have_laws(const AllParameters &parameters)
    {
      for (const InterfaceLine &line : parameters.mesh.interface_lines)
        AssertThrow(parameters.interfaces.laws.count(line.boundary_id) > 0,
                    ExcMessage("Mesh/Interface lines: boundary id " +
                               std::to_string(line.boundary_id) +
                               " has no law in Interfaces/Interfaces, so the "
                               "faces split along it connect nothing: give "
                               "it one, e.g. '" +
                               std::to_string(line.boundary_id) +
                               ": rough' for a bonded face"));
    }

    /**
     * The stiffness coefficients and the 6 x 6 are those of the elastic
     * scene (doc/foundation-stiffness.md); refused before anything else
     * about the harmonics they would need is checked.
     */
    void
    check_stiffness_of_linear_scene(const AllParameters &parameters)
    {
      const RigidFoundationParameters &foundation = parameters.rigid_foundation;
      AssertThrow(!foundation.stiffness_coefficients || !parameters.coupled(),
                  ExcMessage(
                    std::string("Rigid foundation/") +
                    (foundation.stiffness_matrix ? "Stiffness matrix" :
                                                   "Stiffness coefficients") +
                    ": the foundation stiffness is that of the elastic "
                    "scene, not computed with " +
                    (parameters.soil_plasticity.any() ?
                       "plastic soil (Soil plasticity/Laws)" :
                       "a coulomb or contact interface") +
                    "; set it false here and run the scene without them for "
                    "the stiffness"));
    }
  } // namespace

  void
  check_problem_is_meaningful(const AllParameters &parameters)
  {
    check_stiffness_of_linear_scene(parameters);
    check_maximum_harmonic_not_below_listed(parameters);
    check_interface_lines_have_laws(parameters);
    check_controlled_motion_not_held(parameters);
    check_motion_direction_path(parameters);
    check_swipe_path(parameters);
    check_capacity_needs_nonlinear_source(parameters);
    check_displacement_target(parameters);
    check_cyclic_path(parameters);
    check_load_control_has_load(parameters);
    check_exact_solution_linear(parameters);
  }

  void
  check_coupled_path_supported(const AllParameters &parameters,
                               const std::string   &with)
  {
    const std::string entry = "Load path";
    // The goal-oriented indicator's dual problem is the linear one.
    AssertThrow(parameters.adaptivity.strategy != RefinementStrategy::goal,
                ExcMessage("Adaptivity/Strategy = goal: not yet with " + with +
                           " (its dual problem is linear); kelly refines "
                           "where the mechanism is, global uniformly"));
    // Under mpirun the harmonics are distributed over the ranks (each
    // harmonic's system serial); what Distributed = always distributes on
    // a coupled path is the Newton tangent of all harmonics.
    AssertThrow(!parameters.solver.distributed_always ||
                  parameters.distributes_coupled_tangent(),
                ExcMessage(entry +
                           ": not yet: Linear solver/Distributed = always "
                           "with " +
                           with +
                           " and no coupled Newton tangent (it factorizes "
                           "that tangent over the ranks: plastic soil with "
                           "Soil plasticity/Stiffness = tangent); under "
                           "mpirun the harmonics are distributed over the "
                           "ranks"));
  }
} // namespace FourierSSI
