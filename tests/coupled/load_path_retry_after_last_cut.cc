// The load path's step sizes and its retry after the last cut (load_path.h,
// doc/soil-plasticity.md section 3b), on a scripted iteration: a trial
// converges when its step (target minus the committed value) is at most
// `plain_size`, or, on the retry (retry_persistently), at most
// `retry_size`. One stage of 1 step, Maximum step cuts = 2, so a step is
// tried at 1, 1/2, 1/4 of what is left of its size. Under displacement
// control (the scripted vertical motion follows the target):
//  (1) plain_size = 0.3: 1 and 1/2 fail, 1/4 converges; no retry; the path
//      ends at 1.
//  (2) plain_size = 0.05, retry_size = 0.25: the first step fails at 1,
//      1/2, 1/4 and is retried once at 1/4, which converges; the next
//      (1/4 again) fails at 1/4, 1/8, 1/16 and converges on its retry; the
//      rest converge at 1/32 and its regrowth. Exactly 2 retries, each
//      after 3 failed trials at sizes 4:2:1; the path ends at 1.
//  (3) the retry fails too (retry_size = 0): one line naming the solver's
//      section and the cuts, after exactly 4 trials (3 sizes and 1 retry)
//      and 1 retry: a retry is not repeated.
//  (4) a path that converges only ever closer to its end (a step converges
//      when it is at most 0.3 of what is left, as a path approaching a
//      limit): the cuts reset at every converged step, but the size has a
//      floor, 2^-20 of the stage's step, so the run ends with the one-line
//      error after fewer than 200 trials (measured 78, 55 converged steps).
//      Without the floor the path took 120 steps and passed for complete
//      once what was left fell below 1e-12.
// Under load control the floor is 2^-(Maximum step cuts) of the step:
//  (5) the path of (4) stops at the limit with the one line that names
//      the load step and the fraction carried, once a step would fall
//      below 1/4 (fewer than 20 trials).
#include "check.h"

#include <cmath>
#include <fourier_ssi/coupled/load_path.h>
#include <sstream>

using namespace FourierSSI;

namespace
{
  class ScriptedIteration : public LoadPath::Iteration
  {
  public:
    ScriptedIteration(const double plain_size,
                      const double retry_size,
                      const bool   of_what_is_left = false)
      : plain_size(plain_size)
      , retry_size(retry_size)
      , of_what_is_left(of_what_is_left)
    {}

    void
    start_trial(const double) override
    {
      trial = committed;
    }

    bool
    solve_trial(const double target, const bool) override
    {
      const double size    = target - committed;
      const double largest = (persistent ? retry_size : plain_size) *
                             (of_what_is_left ? 1. - committed : 1.);
      const bool converged = size <= largest + 1e-12 * (1. - committed);
      sizes.push_back(size);
      retried.push_back(persistent);
      persistent = false;
      if (converged)
        trial = target;
      return converged;
    }

    RigidMotion
    trial_motion() const override
    {
      RigidMotion motion;
      motion.vertical_displacement = trial;
      return motion;
    }

    void
    commit_trial(const LoadStep &, const bool, std::ostream &) override
    {
      committed = trial;
      ++n_steps;
    }

    RigidMotion
    committed_motion() const override
    {
      RigidMotion motion;
      motion.vertical_displacement = committed;
      return motion;
    }

    double
    committed_load_factor() const override
    {
      // Under load control the scripted state is the load factor.
      return committed;
    }

    unsigned int
    n_converged_steps() const override
    {
      return n_steps;
    }

    bool
    holds_loads() const override
    {
      return false;
    }

    void
    write_held_loads(std::ostream &) const override
    {}

    bool
    retry_persistently(std::ostream &) override
    {
      ++n_retries;
      persistent = true;
      return true;
    }

    const double        plain_size, retry_size;
    const bool          of_what_is_left;
    double              committed = 0., trial = 0.;
    bool                persistent = false;
    unsigned int        n_steps = 0, n_retries = 0;
    std::vector<double> sizes;
    std::vector<bool>   retried;
  };

  /** The error a stage of one step ends with (empty: none). */
  std::string
  error_of(const LoadPathParameters &settings, ScriptedIteration &iteration)
  {
    std::ostringstream log;
    try
      {
        LoadPath(settings, "Scripted", iteration)
          .run_stage(false, 1, 1., 1, log);
      }
    catch (const std::exception &error)
      {
        return error.what();
      }
    return "";
  }

  /** One step to 1 (a vertical motion of 1 m under displacement control). */
  LoadPathParameters
  one_step_two_cuts(const LoadPathParameters::Control control)
  {
    LoadPathParameters settings;
    settings.load_steps        = 1;
    settings.maximum_step_cuts = 2;
    settings.control           = control;
    settings.motion            = LoadPathParameters::Motion::vertical;
    settings.target            = 1.;
    return settings;
  }
} // namespace

int
main()
{
  const LoadPathParameters settings =
    one_step_two_cuts(LoadPathParameters::Control::displacement);
  std::ostringstream log;

  // (1)
  {
    ScriptedIteration iteration(0.3, 0.);
    LoadPath(settings, "Scripted", iteration).run_stage(false, 1, 1., 1, log);
    check::relative("(1) the path ends at", iteration.committed, 1., 1e-12);
    check::equal("(1) retries", iteration.n_retries, 0);
    check::relative("(1) first converged size",
                    iteration.sizes[2],
                    0.25,
                    1e-12);
  }

  // (2)
  {
    ScriptedIteration iteration(0.05, 0.25);
    LoadPath(settings, "Scripted", iteration).run_stage(false, 1, 1., 1, log);
    check::relative("(2) the path ends at", iteration.committed, 1., 1e-12);
    check::equal("(2) retries", iteration.n_retries, 2);
    bool         as_scripted = iteration.sizes.size() >= 8;
    const double expected[8] = {
      1., 0.5, 0.25, 0.25, 0.25, 0.125, 0.0625, 0.0625};
    for (unsigned int k = 0; as_scripted && k < 8; ++k)
      as_scripted = std::abs(iteration.sizes[k] - expected[k]) < 1e-12 &&
                    iteration.retried[k] == (k == 3 || k == 7);
    check::that("(2) trials 1, 1/2, 1/4, retry 1/4, then 1/4, 1/8, 1/16, "
                "retry 1/16",
                as_scripted);
  }

  // (3)
  {
    ScriptedIteration iteration(0.05, 0.);
    const std::string message = error_of(settings, iteration);
    check::that("(3) the error names the section and the cuts",
                message.find("Scripted: load step 1 of 1 (after 2 cuts) did "
                             "not converge") != std::string::npos);
    check::equal("(3) trials", iteration.sizes.size(), 4);
    check::equal("(3) retries", iteration.n_retries, 1);
  }
  // (4)
  {
    ScriptedIteration iteration(0.3, 0.3, true);
    const std::string message = error_of(settings, iteration);
    check::that("(4) the path ends with the one-line error, naming the "
                "floor its last step started at",
                message.find("Scripted: load step 1 of 1 (after 0 cuts, at "
                             "the smallest step size") != std::string::npos);
    check::in_range("(4) trials", iteration.sizes.size(), 1, 200);
    check::in_range("(4) converged steps", iteration.n_steps, 1, 200);
  }
  // (5)
  {
    ScriptedIteration iteration(0.3, 0.3, true);
    const std::string message =
      error_of(one_step_two_cuts(LoadPathParameters::Control::load), iteration);
    check::that("(5) the path stops at its limit with the one line naming "
                "the step and the fraction carried",
                message.find("Scripted: load step 1 of 1: the loads are "
                             "carried only up to 0.") != std::string::npos);
    check::in_range("(5) trials", iteration.sizes.size(), 1, 20);
  }
  return check::summary();
}
