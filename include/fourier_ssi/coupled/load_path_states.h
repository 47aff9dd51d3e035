/**
 * The states a coupled solver keeps along the load path (LoadPath): the
 * last converged one, the one before it (the secant predictor's) and the
 * step being solved, with what is read of a state: the total displacement
 * u = lambda K^-1 F + K^-1 c + rho K^-1 F_held (LoadPattern), its rigid
 * motion (rigid_motion_of) and the applied foundation loads, the secant
 * predictor of c and K^-1 c (start_trial), and the records of the converged
 * steps (load_step_result.h) with their log lines.
 */
#ifndef fourier_ssi_load_path_states_h
#define fourier_ssi_load_path_states_h

#include <array>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_step_state.h>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/coupled/load_pattern.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/harmonic/rigid_foundation.h>
#include <fourier_ssi/input/parameters.h>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class LoadPathStates
  {
  public:
    using State = CoupledStepState;

    LoadPathStates(const HarmonicSet &set, const AllParameters &parameters);

    /**
     * Total displacement amplitudes of harmonic i (last converged state).
     * Collective when the harmonics are distributed over ranks: every rank
     * calls it for the same i and gets the owner's field.
     */
    Vector<double>
    solution(const unsigned int i) const;

    /**
     * The last converged step's displacement increment of harmonic i, the
     * last state less the one before it (the whole field where harmonic i
     * was added by the last step): the mechanism at the end of the path.
     * A collective under MPI, as solution().
     */
    Vector<double>
    last_step_increment(const unsigned int i) const;

    /**
     * The applied rigid-foundation loads (F_x, F_y, F_z, M_x, M_y, M_z) at
     * load factor lambda with the fraction held_fraction of the held loads,
     * M about the origin (H at the reference elevation).
     */
    std::array<double, 6>
    applied_loads(const double load_factor,
                  const double held_fraction = 0.) const;

    /** The record of every converged step, in order. */
    const std::vector<LoadStepResult> &
    get_steps() const
    {
      return steps;
    }

    /**
     * load-displacement.csv of the converged steps, with the columns of
     * the run's nonlinear sources (write_load_path_csv).
     */
    void
    write_csv(const std::string &filename) const;

    /** The committed state before the first step: c = 0 on every harmonic. */
    void
    start_at_rest();

    /**
     * The committed states gain harmonics [first, set size) at rest (the
     * harmonics grow).
     */
    void
    extend_at_rest(const unsigned int first);

    /** The log line of Rigid foundation/Held motions (if any), `note` last. */
    void
    write_held_motions(std::ostream &log, const std::string &note) const;

    /** The held loads (V, H, M about the reference point, T). */
    void
    write_held_loads(std::ostream &log) const;

    /**
     * The trial state of a step: the committed one, with the secant
     * predictor for ratio > 0: c, K^-1 c and the condensed controlled
     * motion moved on by ratio times their change over the last converged
     * step (before_last to committed). At a plateau the plastic mechanism
     * goes on as in the last step, so Newton starts next to the answer,
     * where the elastic predictor (c kept) would spread the increment as
     * elastic strain and overshoot the capacity (doc/soil-plasticity.md 3b).
     */
    void
    start_trial(const double ratio);

    /**
     * u_h = lambda u_F + K^-1 c + rho u_held (+ mu K^-1 e_V in a swipe) of
     * a state (owner's field).
     */
    Vector<double>
    total_displacement(const State &state, const unsigned int h) const;

    /** The rigid motion of a state (rigid_motion_of). */
    RigidMotion
    motion_of(const State &state) const;

    /**
     * The converged trial becomes the committed state; its record
     * (trial_result) gets the load factor, held fraction and swipe force,
     * the motion and wall time of `step` and the harmonics solved.
     */
    void
    commit(const LoadStep &step);

    /**
     * The interfaces' part of the trial's record, once per converged step:
     * their largest f and their resultant on the foundation, from the
     * tractions of trial_result.interface_state (at `sampling`'s angles).
     */
    void
    record_interfaces(const NonlinearInterfacePoints &interfaces,
                      const ThetaSampling            &sampling);

    /**
     * The trial's record becomes a converged step's: stored, handed to
     * `observer` (if any), and its log line written (write_step_line).
     * Call after commit() and after the sources' parts of trial_result are
     * filled in.
     */
    void
    record_trial(const bool                                         holding,
                 std::ostream                                      &log,
                 const std::function<void(const LoadStepResult &)> &observer);

    const HarmonicSet               &harmonic_set;
    const RigidFoundationParameters &foundation_parameters;
    /** F, F_held and their elastic solutions. */
    LoadPattern loads;
    /** The last converged state, the one before it, the step solved. */
    State committed, before_last, trial;
    /** The run's nonlinear sources: which parts the records show. */
    RecordedSources sources;
    /** The record of the step being solved, and of the converged ones. */
    LoadStepResult              trial_result;
    std::vector<LoadStepResult> steps;
  };
} // namespace FourierSSI

#endif
