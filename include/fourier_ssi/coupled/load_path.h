/**
 * The load path of every coupled (nonlinear) run: one object steps the held
 * loads and then the loading from the committed state to the end of the
 * path, whatever linearises a step (CoupledSolver: condensed onto the
 * interfaces, or on the coupled tangent). It owns
 *   - the two stages, the held loads first (Load path/Held load steps, the
 *     load factor at 0), then the loading (Load steps) by load or
 *     displacement control from where the held loads left the motion;
 *   - the step size: a step that does not converge is cut in half, up to
 *     Maximum step cuts in a row and never below 2^-20 of the stage's step
 *     (a path converging ever closer to a limit load ends); after a cut,
 *     `needed` converged steps at the cut size double it back toward the
 *     stage's step (a cut at a sharp change of state need not slow the
 *     rest of the path), and a doubled size that fails at once doubles
 *     `needed` (doc/soil-plasticity.md 3b);
 *   - the secant predictor: a step starts from the committed state moved
 *     on by the change over the last converged step, scaled to the step's
 *     size (none at a stage's start and after the harmonics grow);
 *   - the "target reached" check: under displacement control a converged
 *     step whose rigid motion misses its target by more than 1e-8 of it (a
 *     diverged iterate with a huge load factor cancelling the correction's
 *     motion) is not converged;
 *   - the rigid motion of a state, summed over the harmonics in their order
 *     after one exact sum over the MPI ranks (rigid_motion_of);
 *   - one more try of a step that failed at the last cut, where the solver
 *     has a surer iteration (Iteration::retry_persistently);
 *   - the one-line error of a step that does not converge after the cuts.
 * The iteration of a step, its records and its log line are the solver's
 * (LoadPath::Iteration).
 */
#ifndef fourier_ssi_load_path_h
#define fourier_ssi_load_path_h

#include <deal.II/lac/vector.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** What every converged load step records, whatever iterated it. */
  struct LoadStep
  {
    /** Factor on the scaled loads (load_factor_pattern). */
    double load_factor = 0.;
    /**
     * Fraction of the held loads (held_stage_load: Rigid foundation/Held
     * ..., body force, tractions) applied: rises to 1 in the held stage,
     * then stays 1 while the load factor scales the foundation's loads.
     */
    double held_fraction = 0.;
    /**
     * A swipe (RigidFoundationParameters::swipes()): the change mu of the
     * vertical load [kN] that keeps w at the preload's value; the V on the
     * foundation is the held one plus mu (0 without a swipe).
     */
    double swipe_force = 0.;
    /** Rigid motion of the foundation (RigidMotion fields). */
    RigidMotion motion;
    /** Out-of-balance solves of this step (0: elastic). */
    unsigned int iterations = 0;
    /** |R| over the force scale at convergence (ForceScale::relative). */
    double residual = 0.;
    /** Wall time of the step [s]. */
    double time = 0.;
    /**
     * The segment of the path the step belongs to: 0 the held stage, k
     * the loading towards the k-th of Load path/Targets (1 without a
     * list).
     */
    unsigned int segment = 0;
    /**
     * The load that holds each of Rigid foundation/Held motions, or a
     * direction probe's H and M [kN or kN m] (LoadControl::
     * held_reactions(); empty without).
     */
    std::vector<std::pair<FoundationMotion, double>> held_reactions;
  };

  /**
   * sum_h values[h * n + c] for c < n, summed over the ranks first: per
   * harmonic quantities, each non-zero on its owner only, added in the
   * harmonics' order as a serial run adds them (the same bits).
   */
  std::vector<double>
  sum_over_harmonics(const HarmonicSet  &set,
                     std::vector<double> values,
                     const unsigned int  n);

  /**
   * The rigid motion of the foundation in the total displacement
   * `displacement(h)` of every harmonic h this rank owns (n = 0 both
   * families, n = 1 symmetric; zero without a foundation), summed over the
   * harmonics by sum_over_harmonics.
   */
  /**
   * True if harmonic h carries a rigid motion of the foundation on this
   * rank: owned, with a foundation, and n = 0 (either family) or n = 1
   * symmetric.
   */
  bool
  carries_rigid_motion(const HarmonicSet &set, const unsigned int h);

  /** parts[4 h + c] := the rigid motion of `displacement` of harmonic h. */
  void
  add_rigid_motion(const HarmonicSet    &set,
                   const unsigned int    h,
                   const Vector<double> &displacement,
                   std::vector<double>  &parts);

  /** The rigid motion of per-harmonic parts, by sum_over_harmonics. */
  RigidMotion
  sum_rigid_motions(const HarmonicSet &set, std::vector<double> parts);

  /**
   * The rigid motion of the foundation in the total displacement
   * `displacement(h)` (a callable) of every harmonic h this rank owns (n =
   * 0 both families, n = 1 symmetric; zero without a foundation), summed
   * over the harmonics by sum_over_harmonics.
   */
  template <class Displacement>
  RigidMotion
  rigid_motion_of(const HarmonicSet &set, const Displacement &displacement)
  {
    // Per harmonic [h * 4 + c], on its owner; summed in the harmonics' order.
    std::vector<double> parts(4 * set.size(), 0.);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (carries_rigid_motion(set, h))
        add_rigid_motion(set, h, displacement(h), parts);
    return sum_rigid_motions(set, std::move(parts));
  }

  class LoadPath
  {
  public:
    /** What the load path asks of the solver that iterates its steps. */
    class Iteration
    {
    public:
      virtual ~Iteration() = default;

      /**
       * The trial state of a step: the committed one, its correction moved
       * on by ratio times the change over the last converged step (ratio
       * 0: kept).
       */
      virtual void
      start_trial(const double ratio) = 0;

      /**
       * Iterate the trial to `target`: the held fraction (holding), else
       * the load factor (load control) or the controlled motion. False if
       * it does not converge.
       */
      virtual bool
      solve_trial(const double target, const bool holding) = 0;

      /** The rigid motion of the trial state (rigid_motion_of). */
      virtual RigidMotion
      trial_motion() const = 0;

      /**
       * After a converged trial: true if the solver added harmonics it
       * calls for (the step is then solved again without a predictor).
       */
      virtual bool
      grows(std::ostream &log)
      {
        (void)log;
        return false;
      }

      /**
       * After a step failed at the last cut: true if the solver has a
       * slower, surer iteration for one more try of that step (then used
       * for the next solve_trial() only); it logs the retry.
       */
      virtual bool
      retry_persistently(std::ostream &log)
      {
        (void)log;
        return false;
      }

      /**
       * The converged trial becomes the committed state (the committed one
       * is kept for the predictor); `step` holds its motion and wall time.
       * The solver records the step and writes its log line.
       */
      virtual void
      commit_trial(const LoadStep &step,
                   const bool      holding,
                   std::ostream   &log) = 0;

      /** The rigid motion of the committed state. */
      virtual RigidMotion
      committed_motion() const = 0;

      /** The load factor of the committed state (load_factor_pattern). */
      virtual double
      committed_load_factor() const = 0;

      /** The converged steps so far. */
      virtual unsigned int
      n_converged_steps() const = 0;

      /** True if the scene holds loads (held_stage_load is not zero). */
      virtual bool
      holds_loads() const = 0;

      /** The held foundation loads, as the log names them. */
      virtual void
      write_held_loads(std::ostream &log) const = 0;
    };

    /**
     * `entry` names the solver's parameter section in the one-line error of
     * a step that does not converge.
     */
    LoadPath(const LoadPathParameters &settings,
             const std::string        &entry,
             Iteration                &iteration);

    /**
     * The held stage (Held load steps) if the scene holds loads, then the
     * loading (Load steps), in one segment per target of
     * LoadPathParameters::segment_targets (a cyclic path reverses at each).
     */
    void
    run(std::ostream &log);

    /**
     * One stage in `n_steps` equal steps: the held loads brought on
     * (holding, `end` 1) or the loads scaled by the load or displacement
     * control from where the path is to `end` (a load factor or the
     * controlled motion); `segment` numbers the target (0: the held
     * stage). Throws one line if a step does not converge after the cuts.
     */
    void
    run_stage(const bool         holding,
              const unsigned int n_steps,
              const double       end,
              const unsigned int segment,
              std::ostream      &log);

  private:
    /** The step size of a stage: its cuts and how it grows back. */
    struct StepSize
    {
      double       step = 1., increment = 1.;
      unsigned int cuts = 0, easy_steps = 0, needed = 2;
      bool         just_grown = false;
      /** This step had its retry after the last cut (retry_persistently). */
      bool retried = false;

      /**
       * A cut keeps the size at or above 2^-floor_cuts of the stage's step,
       * however many steps converged at cut sizes before.
       */
      bool
      can_cut(const unsigned int floor_cuts) const;
      /** Halves the size and counts the cut. */
      void
      cut();
      void
      converged();
    };

    /**
     * The smallest step of a stage is 2^-floor_cuts of its load step:
     * Maximum step cuts under load control, where a path whose steps
     * converge only ever closer to a load it cannot pass is at a limit
     * load (limit_load_message), and most_step_cuts under displacement
     * control, which passes limits.
     */
    unsigned int
    floor_cuts(const bool holding) const;

    /**
     * A stage whose remaining steps would take longer than this at the
     * first step's time gets an estimate in the log [s].
     */
    static constexpr double long_stage_seconds = 60.;

    /**
     * After the first converged step of a stage: prints the estimated time
     * of the rest if it is long.
     */
    void
    report_remaining_time(const double  done,
                          const double  increment,
                          const double  step_time,
                          std::ostream &log) const;

    /** Displacement control in this stage (not the held one). */
    bool
    controls_motion(const bool holding) const;

    /**
     * Under displacement control: the motion misses `target` by more than
     * 1e-8 of `scale` (|target|, or the segment's motions on a cyclic path,
     * whose targets pass through 0).
     */
    bool
    misses_target(const RigidMotion &motion,
                  const double       target,
                  const double       scale,
                  const bool         holding) const;

    /** " of segment 2 of 3 (to -0.01)" on a path of several targets. */
    std::string
    segment_label(const unsigned int segment) const;

    const LoadPathParameters &settings;
    const std::string         entry;
    Iteration                &iteration;
  };
} // namespace FourierSSI

#endif
