/**
 * The states a coupled solver keeps along the load path (LoadPath): the
 * last converged one, the one before it (the secant predictor's) and the
 * step being solved, with what the solver reads of a state: the total
 * displacement u = lambda K^-1 F + K^-1 c + rho K^-1 F_held (LoadPattern),
 * its rigid motion (rigid_motion_of), its controlled motion on every MPI
 * rank and the applied foundation loads, the secant predictor of c and
 * K^-1 c (extrapolate), and the records of the converged steps
 * (load_step_result.h). The solver (CoupledSolver) gives the iteration of
 * a step (LoadPath::Iteration).
 */
#ifndef fourier_ssi_load_path_states_h
#define fourier_ssi_load_path_states_h

#include <array>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
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

  /**
   * The state of a coupled load step: lambda, rho, mu, c and K^-1 c, and
   * what the nonlinear sources keep. Condensed (interfaces only,
   * InterfaceCondensation), K^-1 c in correction_solution is exact at the
   * interface DoFs only while a step iterates, and whole once it converged.
   */
  struct CoupledStepState
  {
    double load_factor = 0.;
    /** rho: the held loads' part rho F_held of the load. */
    double held_fraction = 0.;
    /** mu: a swipe's change of the vertical load (LoadStep::swipe_force). */
    double swipe_force = 0.;
    /** K^-1 c per harmonic, and c (condensed). */
    std::vector<Vector<double>> correction_solution, correction_load;
    /** Plastic soil: s_p = D eps_p per (point, theta); empty without. */
    std::vector<StrainVector> plastic;
    /**
     * Nonlinear interfaces: d_p, the return's origin and p_c per
     * (interface point, theta); empty without.
     */
    InterfaceState interfaces;
    /** Condensed: the controlled motion of K^-1 c [m or rad]. */
    double controlled_motion = 0.;
  };

  class LoadPathStates : public LoadPath::Iteration
  {
  public:
    using State = CoupledStepState;

    /**
     * Total displacement amplitudes of harmonic i (last converged state).
     * Collective when the harmonics are distributed over ranks: every rank
     * calls it for the same i and gets the owner's field.
     */
    Vector<double>
    solution(const unsigned int i) const
    {
      Vector<double> u = total_displacement(committed, i);
      harmonic_set.broadcast_from_owner(i, u.begin(), u.size());
      return u;
    }

    /**
     * The applied rigid-foundation loads (F_x, F_y, F_z, M_x, M_y, M_z) at
     * load factor lambda with the fraction held_fraction of the held loads,
     * M about the origin (H at the reference elevation).
     */
    std::array<double, 6>
    applied_loads(const double load_factor,
                  const double held_fraction = 0.) const
    {
      return applied_foundation_loads(foundation_parameters,
                                      load_factor,
                                      held_fraction);
    }

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
    write_csv(const std::string &filename) const
    {
      write_load_path_csv(filename, steps, foundation_parameters, sources);
    }

  protected:
    LoadPathStates(const HarmonicSet &set, const AllParameters &parameters)
      : harmonic_set(set)
      , foundation_parameters(parameters.rigid_foundation)
      , controlled(parameters.load_path.motion)
    {}

    /**
     * Index of the harmonic that carries Load path/Controlled motion
     * (controlled_harmonic); one line if the scene does not solve it or
     * has no Rigid foundation in it.
     */
    unsigned int
    controlled_harmonic_index() const
    {
      const Harmonic wanted = controlled_harmonic(controlled);
      for (unsigned int h = 0; h < harmonic_set.size(); ++h)
        if (harmonic_set.harmonic(h).n == wanted.n &&
            harmonic_set.harmonic(h).family == wanted.family)
          {
            AssertThrow(harmonic_set.problem(h).get_foundation() != nullptr,
                        ExcMessage("Load path/Control: displacement control "
                                   "needs a Rigid foundation"));
            return h;
          }
      AssertThrow(false,
                  ExcMessage("Load path/Controlled motion: its harmonic is "
                             "not solved (n = 0 for vertical and twist, n = 1 "
                             "symmetric for horizontal and rotation)"));
      return 0;
    }

    /**
     * The controlled motion [m or rad] of a field v of the controlled
     * harmonic (on its owner).
     */
    double
    controlled_motion_of(const Vector<double> &v) const
    {
      return controlled_component(harmonic_set
                                    .problem(controlled_harmonic_index())
                                    .get_foundation()
                                    ->motion(v),
                                  controlled);
    }

    /**
     * The controlled motions of fields of the controlled harmonic (read on
     * its owner only) on every rank: the owner's values summed with the
     * others' zeros, exact (a collective).
     */
    std::vector<double>
    controlled_motions(const std::vector<const Vector<double> *> &fields) const
    {
      std::vector<double> motions(fields.size(), 0.);
      if (harmonic_set.owns(controlled_harmonic_index()))
        for (unsigned int i = 0; i < fields.size(); ++i)
          motions[i] = controlled_motion_of(*fields[i]);
      harmonic_set.sum_over_ranks(motions);
      return motions;
    }

    /**
     * One line if a harmonic has prescribed (non-zero) Dirichlet values:
     * the loads are scaled by lambda and held by rho, the constraints not
     * (not yet with `what`; `entry` names the solver's section).
     */
    void
    check_homogeneous_constraints(const std::string &entry,
                                  const std::string &what) const
    {
      for (unsigned int h = 0; h < harmonic_set.size(); ++h)
        AssertThrow(
          !harmonic_set.problem(h).get_constraints().has_inhomogeneities(),
          ExcMessage(entry +
                     ": not yet: prescribed (non-zero) Dirichlet "
                     "values with " +
                     what + "; load the scene through the Rigid foundation"));
    }

    /** The committed state before the first step: c = 0 on every harmonic. */
    void
    start_at_rest()
    {
      committed.correction_solution = loads.solution;
      for (Vector<double> &v : committed.correction_solution)
        v = 0.;
      committed.correction_load = committed.correction_solution;
    }

    /** The log line of Rigid foundation/Held motions (if any), `note` last. */
    void
    write_held_motions(std::ostream &log, const std::string &note) const
    {
      if (foundation_parameters.held_motions.empty())
        return;
      log << "held at zero (Rigid foundation/Held motions):";
      for (const FoundationMotion m : foundation_parameters.held_motions)
        log << ' ' << name_of(m)
            << (m == FoundationMotion::w && foundation_parameters.swipes() ?
                  " (at the value the held loads leave: a swipe, V changes "
                  "to keep it)" :
                  "");
      log << note << '\n';
    }

    /**
     * The load that holds each reported motion (Rigid foundation/Held
     * motions, a direction probe's loads) in a converged state: the work of
     * the internal force K u - G on the unit motion minus lambda f
     * (RigidFoundation::held_reactions). `nonlinear_load` is G, the nodal
     * force (unconstrained) of the nonlinear sources per harmonic: the
     * soil's plastic part and the interfaces' (their tractions). One value
     * per motion from the owner of its harmonic, summed over the ranks (a
     * collective). Empty without reported motions.
     */
    std::vector<std::pair<FoundationMotion, double>>
    held_reactions_of(const State                       &state,
                      const std::vector<Vector<double>> &nonlinear_load) const
    {
      const std::vector<FoundationMotion> held =
        foundation_parameters.reported_motions();
      if (held.empty())
        return {};
      std::vector<double> values(held.size(), 0.);
      for (unsigned int h = 0; h < harmonic_set.size(); ++h)
        {
          const RigidFoundation *foundation =
            harmonic_set.problem(h).get_foundation();
          if (!harmonic_set.owns(h) || foundation == nullptr ||
              !foundation->holds_motion())
            continue;
          Vector<double> force =
            harmonic_set.problem(h).nodal_forces(total_displacement(state, h),
                                                 state.load_factor);
          force -= nonlinear_load[h];
          for (const auto &[motion, load] : foundation->held_reactions(force))
            for (unsigned int i = 0; i < held.size(); ++i)
              if (held[i] == motion)
                values[i] = load;
        }
      harmonic_set.sum_over_ranks(values);
      std::vector<std::pair<FoundationMotion, double>> reactions;
      for (unsigned int i = 0; i < held.size(); ++i)
        reactions.emplace_back(held[i], values[i]);
      return reactions;
    }

    /** The held loads (V, H, M about the reference point, T). */
    void
    write_held_loads(std::ostream &log) const override
    {
      const auto held = applied_loads(0., 1.);
      log << "V " << held[2] << " kN, H " << held[0] << " kN, M "
          << moment_about_reference(held, foundation_parameters) << " kN m, T "
          << held[5] << " kN m";
    }

    /**
     * Secant predictor: state's correction c and K^-1 c moved on by ratio
     * times their change over the last converged step (before_last to
     * committed); a solver that keeps more of a state linear in c moves
     * that on too. At a plateau the plastic mechanism goes on as in the
     * last step, so Newton starts next to the answer, where the elastic
     * predictor (c kept) would spread the increment as elastic strain and
     * overshoot the capacity (doc/soil-plasticity.md 3b).
     */
    virtual void
    extrapolate(const State &before_last,
                const double ratio,
                State       &state) const
    {
      const auto move_on = [ratio](Vector<double>       &v,
                                   const Vector<double> &last,
                                   const Vector<double> &before) {
        v.add(ratio, last);
        v.add(-ratio, before);
      };
      for (unsigned int h = 0; h < harmonic_set.size(); ++h)
        {
          move_on(state.correction_load[h],
                  committed.correction_load[h],
                  before_last.correction_load[h]);
          move_on(state.correction_solution[h],
                  committed.correction_solution[h],
                  before_last.correction_solution[h]);
        }
    }

    /**
     * u_h = lambda u_F + K^-1 c + rho u_held (+ mu K^-1 e_V in a swipe) of
     * a state (owner's field).
     */
    Vector<double>
    total_displacement(const State &state, const unsigned int h) const
    {
      return loads.total_displacement(h,
                                      state.load_factor,
                                      state.correction_solution[h],
                                      state.held_fraction,
                                      state.swipe_force);
    }

    /** The rigid motion of a state (rigid_motion_of). */
    RigidMotion
    motion_of(const State &state) const
    {
      return rigid_motion_of(harmonic_set, [&](const unsigned int h) {
        return total_displacement(state, h);
      });
    }

    /**
     * The converged trial becomes the committed state; its record
     * (trial_result) gets the load factor, held fraction and swipe force,
     * the motion and wall time of `step` and the harmonics solved.
     */
    void
    commit(const LoadStep &step)
    {
      before_last                = std::move(committed);
      committed                  = trial;
      trial_result.load_factor   = committed.load_factor;
      trial_result.held_fraction = committed.held_fraction;
      trial_result.swipe_force   = committed.swipe_force;
      trial_result.motion        = step.motion;
      trial_result.time          = step.time;
      trial_result.n_harmonics   = harmonic_set.size();
    }

    /**
     * The interfaces' part of the trial's record, once per converged step:
     * their largest f and their resultant on the foundation, from the
     * tractions of trial_result.interface_state (at `sampling`'s angles).
     */
    void
    record_interfaces(const NonlinearInterfacePoints &interfaces,
                      const ThetaSampling            &sampling)
    {
      const std::vector<LocalVector> &traction =
        trial_result.interface_state.traction;
      trial_result.largest_interface_yield_value =
        interfaces.largest_yield_value(traction);
      trial_result.resultant =
        interfaces.foundation_resultant(traction,
                                        sampling,
                                        foundation_parameters);
    }

    /**
     * The trial's record becomes a converged step's: stored, handed to
     * `observer` (if any), and its log line written (write_step_line).
     * Call after commit() and after the solver has filled its sources'
     * parts of trial_result.
     */
    void
    record_trial(
      const bool                                         holding,
      std::ostream                                      &log,
      const std::function<void(const LoadStepResult &)> &observer = {})
    {
      // The next trial starts from a fresh record (solve_trial).
      steps.push_back(std::move(trial_result));
      if (observer)
        observer(steps.back());
      write_step_line(log,
                      steps.size(),
                      holding,
                      steps.back(),
                      foundation_parameters,
                      sources);
    }

    unsigned int
    n_converged_steps() const override
    {
      return steps.size();
    }

    void
    start_trial(const double ratio) override
    {
      trial = committed;
      if (ratio > 0.)
        extrapolate(before_last, ratio, trial);
    }

    RigidMotion
    trial_motion() const override
    {
      return motion_of(trial);
    }

    RigidMotion
    committed_motion() const override
    {
      return motion_of(committed);
    }

    bool
    holds_loads() const override
    {
      return loads.holds_loads();
    }

    const HarmonicSet               &harmonic_set;
    const RigidFoundationParameters &foundation_parameters;
    /** Load path/Controlled motion (under displacement control). */
    const LoadPathParameters::Motion controlled;
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
