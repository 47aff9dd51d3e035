/**
 * The iteration of one load step at fixed contact multipliers, the same
 * for both linearisations of CoupledSolver (condensed onto the interfaces,
 * the coupled tangent; doc/nonlinear-interfaces.md section 5b,
 * doc/soil-plasticity.md 3b): from an evaluated iterate, until the force
 * test passes (true) or the step must be cut (false, a non-finite |R| or
 * Load path/Maximum iterations reached):
 *   - Newton (SafeguardedNewton) where the solver linearises (Stiffness =
 *     tangent); where it finds no descent the solver's rule decides between
 *     a cut and one initial-stiffness update (after which Newton may start
 *     again from the iterate that update reached);
 *   - otherwise the accelerated initial-stiffness update of every iteration.
 */
#ifndef fourier_ssi_balance_iteration_h
#define fourier_ssi_balance_iteration_h

#include <cmath>

namespace FourierSSI
{
  /** What a solver does where Newton finds no descent. */
  enum class NoDescent
  {
    /** give the step up (it is cut) */
    cut,
    /** one initial-stiffness update, Newton going on as it stands */
    initial_stiffness_update,
    /** one initial-stiffness update, Newton starting again from it */
    initial_stiffness_update_and_restart
  };

  /**
   * Newton: a SafeguardedNewton, or null for the initial-stiffness
   * iteration. balanced(state, e): the force test (it may refine the
   * iterate and e); fixed_point_update(state, e): the initial-stiffness
   * update; no_descent(): the solver's rule (NoDescent). `e` is the
   * evaluation of `state` on entry and on return; `iterations` counts the
   * updates taken (on across the calls of a step).
   */
  template <class Newton,
            class State,
            class Evaluation,
            class Evaluate,
            class Balanced,
            class FixedPointUpdate,
            class NoDescentRule>
  bool
  iterate_to_balance(Newton                 *newton,
                     State                  &state,
                     Evaluation             &e,
                     const Evaluate         &evaluate,
                     const Balanced         &balanced,
                     const FixedPointUpdate &fixed_point_update,
                     const NoDescentRule    &no_descent,
                     const unsigned int      maximum_iterations,
                     unsigned int           &iterations)
  {
    for (unsigned int update = 0; update <= maximum_iterations;
         ++update, ++iterations)
      {
        if (!std::isfinite(e.residual_norm))
          return false;
        if (balanced(state, e))
          return true;
        NoDescent rule = NoDescent::initial_stiffness_update;
        if (newton != nullptr)
          {
            if (newton->update(state, e))
              continue;
            rule = no_descent();
            if (rule == NoDescent::cut)
              return false;
          }
        fixed_point_update(state, e);
        e = evaluate(state);
        if (rule == NoDescent::initial_stiffness_update_and_restart)
          newton->restart();
      }
    return false;
  }
} // namespace FourierSSI

#endif
