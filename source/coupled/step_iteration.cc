#include <cmath>
#include <fourier_ssi/coupled/step_iteration.h>

namespace FourierSSI
{
  StepIteration::StepIteration(const LoadPathParameters &settings,
                               const NonlinearSources   &sources,
                               Linearisation            &linearisation,
                               LoadControl              &control,
                               const LoadPathStates     &states)
    : settings(settings)
    , sources(sources)
    , linearisation(linearisation)
    , control(control)
    , states(states)
  {}

  bool
  StepIteration::solve(const double      target,
                       const bool        holding,
                       const bool        persistent,
                       CoupledStepState &state,
                       LoadStepResult   &result) const
  {
    control.start_step(target, holding, state);
    const Steps       steps{*this, target, result};
    CoupledEvaluation e;
    unsigned int      iterations = 0;
    for (unsigned int multiplier_update = 0;; ++multiplier_update)
      {
        // At fixed contact multipliers, until the force test passes.
        FixedPointAcceleration   acceleration(linearisation.acceleration(),
                                            settings.anderson_depth);
        SafeguardedNewton<Steps> newton(linearisation.newton_settings(), steps);
        e = steps.evaluate(state);
        for (unsigned int update = 0;; ++update, ++iterations)
          {
            if (update > settings.maximum_iterations ||
                !std::isfinite(e.residual_norm))
              return false;
            if (passes_force_test(steps, state, e))
              break;
            NoDescent rule = NoDescent::initial_stiffness_update;
            if (linearisation.uses_newton())
              {
                if (newton.update(state, e))
                  continue;
                rule = linearisation.no_descent(persistent, newton.stalled());
                if (rule == NoDescent::cut)
                  return false;
              }
            linearisation.add(1.,
                              linearisation.initial_stiffness_correction(
                                acceleration, state, e),
                              state);
            e = steps.evaluate(state);
            if (rule == NoDescent::initial_stiffness_update_and_restart)
              newton.restart();
          }
        // The augmented Lagrangian's multipliers move between balanced
        // iterates.
        if (!sources.augments())
          break;
        result.multiplier_updates = multiplier_update + 1;
        const NonlinearSources::MultiplierUpdate next =
          sources.update_multipliers(e,
                                     settings.tolerance,
                                     multiplier_update,
                                     state);
        if (next == NonlinearSources::MultiplierUpdate::converged)
          break;
        if (next != NonlinearSources::MultiplierUpdate::again)
          return false;
      }
    accept(e, iterations, state, result);
    return true;
  }

  bool
  StepIteration::passes_force_test(const Steps       &steps,
                                   CoupledStepState  &state,
                                   CoupledEvaluation &e) const
  {
    if (!e.scale.converged(e.residual_norm, settings.tolerance))
      return false;
    if (!linearisation.uses_newton() || !linearisation.keeps_partial_solution())
      return true;
    linearisation.complete(state);
    e = steps.evaluate(state);
    return e.scale.converged(e.residual_norm, settings.tolerance);
  }

  void
  StepIteration::accept(CoupledEvaluation &e,
                        const unsigned int iterations,
                        CoupledStepState  &state,
                        LoadStepResult    &result) const
  {
    // Newton's force test completed K^-1 c already (passes_force_test).
    if (linearisation.keeps_partial_solution() && !linearisation.uses_newton())
      linearisation.complete(state);
    sources.accept(e, state, result);
    result.iterations = iterations;
    result.residual   = e.scale.relative(e.residual_norm);
  }

  CoupledEvaluation
  StepIteration::Steps::evaluate(CoupledStepState &state) const
  {
    iteration.control.set_multipliers(target, state);
    return iteration.sources.evaluate(state,
                                      iteration.states.committed,
                                      result);
  }

  CoupledCorrection
  StepIteration::Steps::direction(const CoupledEvaluation &e,
                                  const CoupledStepState  &state) const
  {
    return iteration.linearisation.newton_direction(e, state);
  }

  void
  StepIteration::Steps::move(const double             alpha,
                             const CoupledCorrection &d,
                             CoupledStepState        &state) const
  {
    iteration.linearisation.add(alpha, d, state);
  }
} // namespace FourierSSI
