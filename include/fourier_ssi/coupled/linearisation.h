/**
 * How a coupled load step moves its correction load c (doc/driver.md, "one
 * load step"): the one decision that differs between scenes
 * (AllParameters::linearises_on_coupled_tangent), with two
 * implementations:
 *   - TangentLinearisation (plastic soil, or a swipe): K^-1 dc re-solved
 *     for every harmonic with the kept factorizations; Newton on the
 *     coupled tangent K_t of every harmonic (coupled_tangent.h);
 *   - CondensedInterfaces (interfaces only): condensed onto the interface
 *     DoFs (InterfaceCondensation): K^-1 dc a dense product with the
 *     flexibility blocks, Newton on the dense condensed Jacobian.
 * Each owns its Newton settings (the globalisation of
 * safeguarded_newton.h), its rule where Newton finds no descent and its
 * acceleration of the initial-stiffness updates. Whether Newton runs at
 * all is the user's (Stiffness = tangent).
 */
#ifndef fourier_ssi_linearisation_h
#define fourier_ssi_linearisation_h

#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_step_state.h>
#include <fourier_ssi/coupled/safeguarded_newton.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <string>

namespace FourierSSI
{
  /** What a linearisation does where Newton finds no descent. */
  enum class NoDescent
  {
    /** give the step up (it is cut) */
    cut,
    /** one initial-stiffness update, Newton going on as it stands */
    initial_stiffness_update,
    /** one initial-stiffness update, Newton starting again from it */
    initial_stiffness_update_and_restart
  };

  class Linearisation
  {
  public:
    /** `newton`: Stiffness = tangent (else initial stiffness only). */
    Linearisation(const LoadPathParameters &settings, const bool newton)
      : settings(settings)
      , newton(newton)
    {}

    virtual ~Linearisation() = default;

    /** Newton updates (Stiffness = tangent) rather than initial stiffness. */
    bool
    uses_newton() const
    {
      return newton;
    }

    /** How the log names the iteration. */
    virtual std::string
    name() const = 0;

    /** Newton's globalisation (SafeguardedNewton). */
    virtual NewtonSettings
    newton_settings() const = 0;

    /** The acceleration of the initial-stiffness updates. */
    virtual LoadPathParameters::Acceleration
    acceleration() const = 0;

    /**
     * The rule where Newton finds no descent; `persistent`: the step is
     * the retry after the last cut, `stalled`: Newton's |R| stalls.
     */
    virtual NoDescent
    no_descent(const bool persistent, const bool stalled) const = 0;

    /** The Newton correction at an iterate and its evaluation. */
    virtual CoupledCorrection
    newton_direction(const CoupledEvaluation &e,
                     const CoupledStepState  &state) = 0;

    /**
     * The initial-stiffness update of an iterate (Load path/Acceleration on
     * c and R): dc and its K^-1 dc.
     */
    virtual CoupledCorrection
    initial_stiffness_correction(FixedPointAcceleration  &acceleration,
                                 const CoupledStepState  &state,
                                 const CoupledEvaluation &e) const = 0;

    /** c <- c + alpha dc and K^-1 c <- K^-1 c + alpha K^-1 dc. */
    virtual void
    add(const double             alpha,
        const CoupledCorrection &correction,
        CoupledStepState        &state) const = 0;

    /**
     * True if K^-1 c is exact at the read DoFs only while a step iterates
     * (complete() makes it whole).
     */
    virtual bool
    keeps_partial_solution() const
    {
      return false;
    }

    /** K^-1 c of the state whole (and its controlled motion). */
    virtual void
    complete(CoupledStepState &state) const
    {
      (void)state;
    }

    /**
     * A step that failed after the last cut may be tried once more with
     * Newton going on past a missing descent (retry_persistently).
     */
    virtual bool
    retries_persistently() const
    {
      return false;
    }

    /** The set grew by the harmonics from `first` on. */
    virtual void
    grow(const unsigned int first) = 0;

    /** The log's note on the sums over MPI ranks of an iteration. */
    virtual std::string
    rank_sums() const = 0;

  protected:
    const LoadPathParameters &settings;
    const bool                newton;
  };
} // namespace FourierSSI

#endif
