#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/coupled_tangent_run.h>
#include <fourier_ssi/driver/cyclic_output.h>
#include <fourier_ssi/driver/interface_state_output.h>
#include <fourier_ssi/driver/load_path_capacity.h>
#include <fourier_ssi/driver/load_path_output.h>
#include <fourier_ssi/driver/plastic_soil_output.h>
#include <fourier_ssi/input/problem_checks.h>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Soil plasticity";


    /** What the plastic-soil path does not do yet: one line each. */
    void
    check_supported(const AllParameters &parameters, const bool nested_meshes)
    {
      // Growth with a swipe (its second multiplier keeping w) is not
      // checked yet.
      const LoadPathParameters &settings = parameters.load_path;
      AssertThrow(!parameters.rigid_foundation.swipes() ||
                    settings.maximum_harmonic <=
                      highest_harmonic(parameters.discretization.harmonics),
                  ExcMessage("Load path/Maximum harmonic: not "
                             "yet with a swipe (the harmonics do not grow); "
                             "list them in Discretization/Harmonics"));
      check_coupled_path_supported(parameters,
                                   parameters.soil_plasticity.any() ?
                                     "plastic soil" :
                                     "a swipe through nonlinear interfaces");
      AssertThrow(parameters.output.lines.empty() &&
                    !parameters.output.write_3d_vtu,
                  ExcMessage(entry + ": not yet: Output/Lines 3D and Write "
                                     "3d vtu with plastic soil or a swipe"));
      AssertThrow(parameters.output.plastic_field_steps.empty() ||
                    !nested_meshes,
                  ExcMessage("Output/Plastic field steps: not yet with "
                             "Discretization/Target accuracy or Refinement "
                             "cycles > 1 (the field of the last step of the "
                             "last mesh only): set Plastic field steps = "
                             "last"));
      AssertThrow(!parameters.output.soil_reaction_curves() || !nested_meshes,
                  ExcMessage("Output/Soil reaction depths: not yet with "
                             "Discretization/Target accuracy or Refinement "
                             "cycles > 1 (the curves of one mesh); set "
                             "Refinement cycles = 1 and no target"));
    }

  } // namespace

  CoupledTangentRun::CoupledTangentRun(const CoupledRunContext &context)
    : CoupledSceneRun(context)
  {
    check_supported(context.parameters,
                    context.plan.meshes != MeshSequence::one_mesh);
    // In the order of the output: rows, then files.
    postprocessors.add(std::make_unique<LoadStepRows>());
    postprocessors.add(std::make_unique<PlasticStateRows>());
    postprocessors.add(std::make_unique<LoadDisplacementCurve>());
    postprocessors.add(std::make_unique<LoadCycleOutput>());
    postprocessors.add(std::make_unique<InterfaceStateCsv>(
      "interface state around the circumference"));
    postprocessors.add(std::make_unique<InterfaceState3d>());
    postprocessors.add(std::make_unique<SoilReactionOutput>());
    postprocessors.add(std::make_unique<LastStepField>());
    postprocessors.add(std::make_unique<HeldReactionRows>());
    postprocessors.add(std::make_unique<WeightlessHeaveWarning>());
    postprocessors.add(std::make_unique<CapacityReport>());
    postprocessors.add(std::make_unique<PlasticFieldOutput>());
    postprocessors.add(std::make_unique<RunResultFiles>());
  }

  std::string
  CoupledTangentRun::goal_prefix() const
  {
    return load_control() ? "end_" : "capacity_";
  }

  bool
  CoupledTangentRun::has_plateau() const
  {
    return !load_control();
  }

  bool
  CoupledTangentRun::load_control() const
  {
    // Displacement control aims at the capacity; load control at the work
    // of the loads at the end of the path (the scene's loads are reached:
    // a load step that does not converge stops the run).
    return context.parameters.load_path.control ==
           LoadPathParameters::Control::load;
  }

  CoupledGoal
  CoupledTangentRun::goal_of(const CoupledSolver &solver) const
  {
    const auto steps = static_cast<unsigned int>(solver.get_steps().size());
    if (load_control())
      return CoupledGoal{"work", "kJ", solver.load_work(), 0., steps};
    const AllParameters &parameters = context.parameters;
    AssertThrow(has_capacity(solver, parameters),
                ExcMessage("Discretization/Target accuracy: the curve "
                           "has fewer than two steps (Load "
                           "path/Load steps)"));
    const Capacity c =
      capacity_of(solver, parameters, goal_load(solver, parameters));
    return CoupledGoal{
      c.load.name, c.load.unit, c.load.value, c.plateau_error, steps};
  }
} // namespace FourierSSI
