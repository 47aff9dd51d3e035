/**
 * One coupled load step to its target, read top to bottom in solve()
 * (doc/driver.md, "one load step"; doc/nonlinear-interfaces.md section 5b,
 * doc/soil-plasticity.md 3b):
 *   1. the load control sets the step's multipliers at every iterate;
 *   2. at fixed contact multipliers, from the evaluated iterate until the
 *      force test passes, or the step must be cut (a non-finite |R|, Load
 *      path/Maximum iterations reached, or no descent where the
 *      linearisation cuts):
 *      - a Newton update (SafeguardedNewton) where the linearisation
 *        linearises (Stiffness = tangent); where it finds no descent the
 *        linearisation's rule decides between a cut and one
 *        initial-stiffness update (after which Newton may start again from
 *        the iterate that update reached);
 *      - otherwise the accelerated initial-stiffness update;
 *   3. with augmented interfaces the contact multipliers move
 *      (augmented Lagrangian) and 2 runs again, until their change no
 *      longer acts on the displacements;
 *   4. the converged iterate is accepted: the sources' state and the
 *      step's record.
 */
#ifndef fourier_ssi_step_iteration_h
#define fourier_ssi_step_iteration_h

#include <fourier_ssi/coupled/coupled_step_state.h>
#include <fourier_ssi/coupled/linearisation.h>
#include <fourier_ssi/coupled/load_control.h>
#include <fourier_ssi/coupled/load_path_states.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/coupled/nonlinear_sources.h>

namespace FourierSSI
{
  class StepIteration
  {
  public:
    StepIteration(const LoadPathParameters &settings,
                  const NonlinearSources   &sources,
                  Linearisation            &linearisation,
                  LoadControl              &control,
                  const LoadPathStates     &states);

    /**
     * Solve one step to `target`: the held fraction (holding), else the
     * load factor (load control) or the controlled motion. `persistent`:
     * the retry after the last cut (Linearisation::no_descent). False if
     * the step must be cut.
     */
    bool
    solve(const double      target,
          const bool        holding,
          const bool        persistent,
          CoupledStepState &state,
          LoadStepResult   &result) const;

  private:
    /** What SafeguardedNewton updates: the iterates of one step. */
    struct Steps
    {
      using State      = CoupledStepState;
      using Evaluation = CoupledEvaluation;
      using Direction  = CoupledCorrection;

      const StepIteration &iteration;
      const double         target;
      LoadStepResult      &result;

      /** Steps 1-4 at an iterate after its multipliers are set. */
      Evaluation
      evaluate(State &state) const;

      Direction
      direction(const Evaluation &e, const State &state) const;

      void
      move(const double alpha, const Direction &d, State &state) const;
    };

    /**
     * The force test of an iterate; where K^-1 c is partial under Newton,
     * the iterate from the full solve K^-1 c is checked again (iterative
     * refinement of the flexibility blocks' round-off), `e` its
     * evaluation.
     */
    bool
    passes_force_test(const Steps       &steps,
                      CoupledStepState  &state,
                      CoupledEvaluation &e) const;

    /** A converged iterate: the sources' state and the step's record. */
    void
    accept(CoupledEvaluation &e,
           const unsigned int iterations,
           CoupledStepState  &state,
           LoadStepResult    &result) const;

    const LoadPathParameters &settings;
    const NonlinearSources   &sources;
    Linearisation            &linearisation;
    LoadControl              &control;
    const LoadPathStates     &states;
  };
} // namespace FourierSSI

#endif
