#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/cyclic_output.h>
#include <fourier_ssi/driver/interface_load_path_run.h>
#include <fourier_ssi/driver/interface_state_output.h>
#include <fourier_ssi/driver/load_path_output.h>
#include <fourier_ssi/input/problem_checks.h>

namespace FourierSSI
{
  InterfaceLoadPathRun::InterfaceLoadPathRun(const CoupledRunContext &context)
    : CoupledSceneRun(context)
  {
    check_coupled_path_supported(context.parameters, "a coulomb interface");
    // In the order of the output: rows, then files.
    postprocessors.add(std::make_unique<LoadStepRows>());
    postprocessors.add(std::make_unique<LoadDisplacementCurve>());
    postprocessors.add(std::make_unique<LoadCycleOutput>());
    postprocessors.add(std::make_unique<InterfaceStateCsv>(
      "interface state (point x theta x step)"));
    postprocessors.add(std::make_unique<LastStepField>());
    postprocessors.add(std::make_unique<HeldReactionRows>());
    postprocessors.add(std::make_unique<InterfaceState3d>());
    postprocessors.add(std::make_unique<RunResultFiles>());
  }

  std::string
  InterfaceLoadPathRun::goal_prefix() const
  {
    return "end_load_";
  }

  bool
  InterfaceLoadPathRun::has_plateau() const
  {
    return false;
  }

  CoupledGoal
  InterfaceLoadPathRun::goal_of(const CoupledSolver &solver) const
  {
    const auto &steps = solver.get_steps();
    AssertThrow(!steps.empty(),
                ExcMessage("Discretization/Target accuracy: no converged "
                           "step"));
    const AllParameters &parameters = context.parameters;
    const NamedLoad      load =
      conjugate_load(solver.applied_loads(steps.back().load_factor,
                                          steps.back().held_fraction),
                     parameters.rigid_foundation,
                     parameters.load_path.motion);
    return CoupledGoal{load.name,
                       load.unit,
                       load.value,
                       0.,
                       static_cast<unsigned int>(steps.size())};
  }
} // namespace FourierSSI
