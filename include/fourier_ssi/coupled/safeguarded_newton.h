/**
 * The Newton update of every coupled iteration under Load path/Stiffness =
 * tangent, whatever linearises it (the interfaces' condensed Jacobian,
 * interface_condensation.cc; the coupled tangent of the plastic soil,
 * coupled_tangent.cc, both in coupled_solver.cc): one globalisation for both
 * (doc/nonlinear-interfaces.md section 5b, doc/soil-plasticity.md 3b).
 *
 * The unknown is the correction load c; an iterate is a solver's state, its
 * evaluation holds |R| (R = G(c) - c). From the best iterate so far Newton
 * takes the full step. Full steps may go on without improving on the best
 * |R| for `nonmonotone_steps` updates: a gap that closes or a slip that
 * reverses beyond the tangent's foresight is corrected by the next
 * tangent, as in an active-set (semismooth) Newton. After that (the states
 * cycle) the iteration returns to the best iterate and searches along the
 * direction it took from there, halving the step from 1/2 (the full step
 * did not improve) until |R| falls by the Armijo fraction, down to
 * `shortest_step`; failing that, the step of the smallest |R| below the
 * best is taken. So the best |R| falls at least every nonmonotone_steps + 2
 * updates and stick/slip or plastic cycling cannot go on (the watchdog of
 * Chamberlain et al., 1982, with a backtracking line search). Where no
 * step along the direction lowers |R| at all, update() returns false and
 * the solver decides (a cut of the load step, or one initial-stiffness
 * update off a kink of the return mapping; after such an update restart()
 * makes its iterate the start of the next Newton steps, and stalled() says
 * when `patience` updates in a row brought no new smallest |R|).
 */
#ifndef fourier_ssi_safeguarded_newton_h
#define fourier_ssi_safeguarded_newton_h

#include <cmath>
#include <limits>
#include <utility>

namespace FourierSSI
{
  /** The globalisation's settings (each linearisation names its own). */
  struct NewtonSettings
  {
    /** Full steps without a new best |R| before the line search. */
    unsigned int nonmonotone_steps = 0;
    /** The shortest fraction of a Newton step the line search tries. */
    double shortest_step = 1. / 16.;
    /** Updates without a new smallest |R| before the step is cut. */
    unsigned int patience = 20;
  };

  /**
   * Steps: what Newton updates, with the types State (a solver's iterate,
   * copyable), Evaluation (what it evaluates at an iterate, with a member
   * residual_norm, |R|) and Direction (a Newton direction), and the
   * members
   *   Evaluation evaluate(State &) const: the evaluation at an iterate
   *     (it may set the iterate's load factor);
   *   Direction direction(const Evaluation &, const State &) const: the
   *     Newton direction at an iterate and its evaluation;
   *   void move(double alpha, const Direction &, State &) const:
   *     state += alpha direction.
   */
  template <class Steps>
  class SafeguardedNewton
  {
  public:
    using Settings   = NewtonSettings;
    using State      = typename Steps::State;
    using Evaluation = typename Steps::Evaluation;
    using Direction  = typename Steps::Direction;

    SafeguardedNewton(const Settings &settings, const Steps &steps)
      : settings(settings)
      , steps(steps)
    {}

    /**
     * One Newton update of `state`; `e` is its evaluation on entry and the
     * new iterate's on return. False if no step along the best iterate's
     * direction lowers its |R| (the state is then the best iterate).
     */
    bool
    update(State &state, Evaluation &e)
    {
      note_progress(e.residual_norm);
      const bool from_best = e.residual_norm <= best_norm;
      if (!from_best && ++since_best > settings.nonmonotone_steps)
        return search_from_best(state, e);
      Direction direction = steps.direction(e, state);
      if (from_best)
        {
          // e is evaluated anew below: the best keeps it without a copy.
          keep_as_best(state, std::move(e));
          best_direction = direction;
        }
      steps.move(1., direction, state);
      e = steps.evaluate(state);
      return std::isfinite(e.residual_norm);
    }

    /**
     * After the solver's own update where update() found no descent: the
     * iterate it reached is the start of the Newton steps that follow,
     * whatever its |R| (the best one so far led nowhere).
     */
    void
    restart()
    {
      best_norm  = std::numeric_limits<double>::infinity();
      since_best = 0;
    }

    /**
     * True once `patience` updates in a row have not lowered the smallest
     * |R| of the step: the states cycle and the step is to be cut.
     */
    bool
    stalled() const
    {
      return since_smallest > settings.patience;
    }

  private:
    /** Armijo fraction: a step alpha is taken if |R| falls by c1 alpha |R|. */
    static constexpr double armijo_fraction = 1e-4;

    void
    note_progress(const double residual_norm)
    {
      if (residual_norm < smallest_norm)
        smallest_norm = residual_norm, since_smallest = 0;
      else
        ++since_smallest;
    }

    void
    keep_as_best(const State &state, Evaluation &&e)
    {
      best_state      = state;
      best_norm       = e.residual_norm;
      best_evaluation = std::move(e);
      since_best      = 0;
    }

    bool
    search_from_best(State &state, Evaluation &e)
    {
      // Full steps may go on again from wherever the search leaves the
      // iterate (the solver's own update where it finds no descent).
      since_best        = 0;
      double best_alpha = 0., smallest_norm = best_norm;
      for (double alpha = 0.5; alpha >= settings.shortest_step; alpha /= 2.)
        {
          state = best_state;
          steps.move(alpha, best_direction, state);
          e = steps.evaluate(state);
          if (!std::isfinite(e.residual_norm))
            continue;
          if (e.residual_norm <= (1. - armijo_fraction * alpha) * best_norm)
            return true; // the next update() keeps it as the best
          if (e.residual_norm < smallest_norm)
            best_alpha = alpha, smallest_norm = e.residual_norm;
        }
      state = best_state;
      if (best_alpha == 0.)
        {
          e = best_evaluation;
          return false;
        }
      steps.move(best_alpha, best_direction, state);
      e = steps.evaluate(state);
      return true; // the next update() keeps it as the best
    }

    const Settings settings;
    const Steps   &steps;

    State        best_state;
    Evaluation   best_evaluation;
    Direction    best_direction;
    double       best_norm      = std::numeric_limits<double>::infinity();
    unsigned int since_best     = 0;
    double       smallest_norm  = std::numeric_limits<double>::infinity();
    unsigned int since_smallest = 0;
  };
} // namespace FourierSSI

#endif
