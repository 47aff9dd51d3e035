/**
 * The load control of a coupled load step (doc/driver.md, "one load
 * step"): which multipliers of the loads an iterate has, and how they are
 * set.
 *   - Load control: lambda is the step's target.
 *   - Displacement control (Load path/Control = displacement, not in the
 *     held stage): lambda puts the controlled motion at the target, from
 *     the motion of K^-1 c, of the held loads and of the pattern.
 *   - The held stage: rho is the target, lambda stays.
 *   - A swipe (Rigid foundation/Held motions = w with a Held vertical
 *     force, RigidFoundationParameters::swipes()): after the held stage mu,
 *     the change of the vertical load e_V, is a second unknown beside
 *     lambda, chosen with it so that w stays where the held stage left it
 *     (swipe_multipliers); no constraint changes along the path.
 * It also gives the loads that hold the reported motions (held_reactions).
 * What is decided once per step (displacement control, swiping) is set by
 * start_step().
 */
#ifndef fourier_ssi_load_control_h
#define fourier_ssi_load_control_h

#include <array>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_step_state.h>
#include <fourier_ssi/coupled/load_path_states.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class LoadControl
  {
  public:
    /**
     * `motion_kept_in_state`: the linearisation keeps the controlled
     * motion of K^-1 c in the state (condensed: K^-1 c is not whole while a
     * step iterates) rather than reading it off the field.
     */
    LoadControl(const HarmonicSet    &set,
                const AllParameters  &parameters,
                const LoadPathStates &states,
                const bool            motion_kept_in_state);

    /**
     * The constants of the run read off the loads' elastic solutions: the
     * controlled motions of u_F and u_held, and in a swipe the rigid
     * motions of u_F and u_V = K^-1 e_V. Again after the harmonics grow.
     */
    void
    read_load_motions();

    /**
     * The step to `target` begins: displacement control and a swipe's
     * multipliers are decided for it; in the held stage rho is the target.
     */
    void
    start_step(const double      target,
               const bool        holding,
               CoupledStepState &state);

    /**
     * The multipliers of an iterate of the step: lambda (load or
     * displacement control) or a swipe's (lambda, mu); nothing in the held
     * stage.
     */
    void
    set_multipliers(const double target, CoupledStepState &state) const;

    /**
     * The changes (dlambda, dmu) of the multipliers with a Newton update
     * du, by_pattern = K_t^-1 F and by_swipe = K_t^-1 e_V (a swipe; null
     * otherwise), all whole on every rank: du + dlambda K_t^-1 F + dmu
     * K_t^-1 e_V keeps the controlled motion and, in a swipe, w. Zeros
     * under load control without a swipe.
     */
    std::array<double, 2>
    newton_multiplier_changes(
      const std::vector<Vector<double>> &du,
      const std::vector<Vector<double>> &by_pattern,
      const std::vector<Vector<double>> *by_swipe) const;

    /** A swipe holds w from here on [m] (the end of the held stage). */
    void
    hold_settlement(const double w)
    {
      swipe_settlement = w;
    }

    /** The step solved is under displacement control. */
    bool
    displacement_control() const
    {
      return controls_motion;
    }

    /** The step solved is a swipe's (not in its held stage): mu keeps w. */
    bool
    swiping() const
    {
      return swiping_now;
    }

    /** The controlled motion of u_F (displacement control) [m or rad]. */
    double
    pattern_motion() const
    {
      return pattern_controlled_motion;
    }

    /**
     * Index of the harmonic that carries Load path/Controlled motion
     * (controlled_harmonic); one line if the scene does not solve it or
     * has no Rigid foundation in it.
     */
    unsigned int
    controlled_harmonic_index() const;

    /**
     * The controlled motion [m or rad] of a field v of the controlled
     * harmonic (on its owner).
     */
    double
    controlled_motion_of(const Vector<double> &v) const;

    /**
     * The controlled motions of fields of the controlled harmonic (read on
     * its owner only) on every rank: the owner's values summed with the
     * others' zeros, exact (a collective).
     */
    std::vector<double>
    controlled_motions(const std::vector<const Vector<double> *> &fields) const;

    /** The scene reports loads that hold motions (held_reactions). */
    bool
    reports_reactions() const;

    /**
     * The load that holds each reported motion (Rigid foundation/Held
     * motions, a direction probe's loads) in a converged state: the work of
     * the internal force K u - G on the unit motion minus lambda f
     * (RigidFoundation::held_reactions). `nonlinear_load` is G, the nodal
     * force (unconstrained) of the nonlinear sources per harmonic: the
     * soil's plastic part and the interfaces' (their tractions). One value
     * per motion from the owner of its harmonic, summed over the ranks (a
     * collective).
     */
    std::vector<std::pair<FoundationMotion, double>>
    held_reactions(const CoupledStepState            &state,
                   const std::vector<Vector<double>> &nonlinear_load) const;

  private:
    /**
     * lambda that puts the controlled motion of the state at target: the
     * motion of K^-1 c (kept in the state, or from the field) and of the
     * held loads, and of the pattern.
     */
    double
    controlled_load_factor(const CoupledStepState &state,
                           const double            target) const;

    /**
     * A swipe: the multipliers (lambda, mu) of the load pattern F and of
     * the unit vertical load e_V that move the foundation from the motion
     * `now` to the controlled motion `target` (load control: lambda =
     * target) and to w = `settlement`, where F moves it by `by_pattern` and
     * e_V by `by_swipe`:
     *   [m(by_pattern)  m(by_swipe)] [lambda]   [target - m(now)]
     *   [w(by_pattern)  w(by_swipe)] [mu    ] = [settlement - w(now)],
     * the first row [1 0 | target] under load control. The motions are
     * linear in the fields, so this holds them exactly, with the elastic
     * patterns for an iterate and the tangent ones for a Newton update.
     */
    std::array<double, 2>
    swipe_multipliers(const RigidMotion &now,
                      const RigidMotion &by_pattern,
                      const RigidMotion &by_swipe,
                      const double       target,
                      const double       settlement) const;

    const HarmonicSet               &set;
    const LoadPathParameters        &settings;
    const RigidFoundationParameters &foundation_parameters;
    const LoadPathStates            &states;
    const bool                       motion_kept_in_state;
    /** The step solved: displacement control, a swipe's, the held stage's. */
    bool controls_motion = false, swiping_now = false, holding_now = false;
    /** Controlled motions of u_F and u_held (0: no held loads). */
    double pattern_controlled_motion = 0., held_motion = 0.;
    /** A swipe: the rigid motions of u_F and of u_V = K^-1 e_V. */
    RigidMotion pattern_rigid_motion, swipe_rigid_motion;
    /** A swipe: w where the held stage left it [m], the value held. */
    double swipe_settlement = 0.;
  };
} // namespace FourierSSI

#endif
