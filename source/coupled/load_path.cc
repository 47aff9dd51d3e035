#include <algorithm>
#include <chrono>
#include <cmath>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/harmonic/rigid_foundation.h>
#include <iomanip>
#include <sstream>

namespace FourierSSI
{
  std::vector<double>
  sum_over_harmonics(const HarmonicSet  &set,
                     std::vector<double> values,
                     const unsigned int  n)
  {
    set.sum_over_ranks(values);
    std::vector<double> sum(n, 0.);
    for (unsigned int h = 0; h < values.size() / n; ++h)
      for (unsigned int c = 0; c < n; ++c)
        sum[c] += values[h * n + c];
    return sum;
  }

  bool
  carries_rigid_motion(const HarmonicSet &set, const unsigned int h)
  {
    const Harmonic &harmonic = set.harmonic(h);
    return set.owns(h) && set.problem(h).get_foundation() != nullptr &&
           (harmonic.n == 0 ||
            (harmonic.n == 1 && harmonic.family == Family::symmetric));
  }

  void
  add_rigid_motion(const HarmonicSet    &set,
                   const unsigned int    h,
                   const Vector<double> &displacement,
                   std::vector<double>  &parts)
  {
    const RigidMotion m = set.problem(h).get_foundation()->motion(displacement);
    parts[4 * h]        = m.vertical_displacement;
    parts[4 * h + 1]    = m.twist;
    parts[4 * h + 2]    = m.horizontal_displacement;
    parts[4 * h + 3]    = m.rotation;
  }

  RigidMotion
  sum_rigid_motions(const HarmonicSet &set, std::vector<double> parts)
  {
    const std::vector<double> sum = sum_over_harmonics(set, parts, 4);
    RigidMotion               total;
    total.vertical_displacement   = sum[0];
    total.twist                   = sum[1];
    total.horizontal_displacement = sum[2];
    total.rotation                = sum[3];
    return total;
  }

  LoadPath::LoadPath(const LoadPathParameters &settings,
                     const std::string        &entry,
                     Iteration                &iteration)
    : settings(settings)
    , entry(entry)
    , iteration(iteration)
  {}

  bool
  LoadPath::controls_motion(const bool holding) const
  {
    return !holding &&
           settings.control == LoadPathParameters::Control::displacement;
  }

  bool
  LoadPath::misses_target(const RigidMotion &motion,
                          const double       target,
                          const double       scale,
                          const bool         holding) const
  {
    // A diverged iterate can pass the relative force test with a huge load
    // factor; the controlled motion then misses its target (cancellation
    // of lambda m(u_F) against m(v)).
    return controls_motion(holding) &&
           std::abs(controlled_component(motion, settings.motion) - target) >
             1e-8 * scale;
  }

  std::string
  LoadPath::segment_label(const unsigned int segment) const
  {
    const std::vector<double> ends = settings.segment_targets();
    if (ends.size() < 2 || segment == 0)
      return "";
    std::ostringstream label;
    label << " of segment " << segment << " of " << ends.size() << " (to "
          << ends[segment - 1] << ")";
    return label.str();
  }

  unsigned int
  LoadPath::floor_cuts(const bool holding) const
  {
    return controls_motion(holding) ? LoadPathParameters::most_step_cuts :
                                      settings.maximum_step_cuts;
  }

  bool
  LoadPath::StepSize::can_cut(const unsigned int floor_cuts) const
  {
    // Cuts reset at every converged step, so without a floor a path that
    // converges only ever closer to a limit would take steps without end.
    return increment / 2. >= step * std::ldexp(1., -int(floor_cuts));
  }

  void
  LoadPath::StepSize::cut()
  {
    increment /= 2.;
    ++cuts;
    easy_steps = 0;
    if (just_grown)
      needed *= 2;
    just_grown = false;
  }

  void
  LoadPath::StepSize::converged()
  {
    cuts    = 0;
    retried = false;
    if (just_grown) // the doubled size converged: back to the default
      needed = 2;
    just_grown = false;
    if (increment < step && ++easy_steps == needed)
      {
        increment  = std::min(step, 2. * increment);
        easy_steps = 0;
        just_grown = true;
      }
  }

  void
  LoadPath::run(std::ostream &log)
  {
    if (iteration.holds_loads())
      {
        log << "held loads first (" << settings.held_load_steps
            << " load-controlled steps), then held: body force, tractions; "
               "foundation ";
        iteration.write_held_loads(log);
        log << '\n';
        run_stage(true, settings.held_load_steps, 1., 0, log);
      }
    const std::vector<double> ends = settings.segment_targets();
    for (unsigned int s = 0; s < ends.size(); ++s)
      {
        if (ends.size() > 1)
          log << "segment " << s + 1 << " of " << ends.size() << ": "
              << (controls_motion(false) ? "the controlled motion" :
                                           "the load factor")
              << " to " << ends[s] << '\n';
        run_stage(false, settings.load_steps, ends[s], s + 1, log);
      }
  }

  void
  LoadPath::run_stage(const bool         holding,
                      const unsigned int n_steps,
                      const double       end,
                      const unsigned int segment,
                      std::ostream      &log)
  {
    // Displacement control moves from where the held loads (or the last
    // segment) left the controlled motion to `end`; load control from the
    // committed load factor (0 on the first segment).
    const double start =
      controls_motion(holding) ?
        controlled_component(iteration.committed_motion(), settings.motion) :
      holding ? 0. :
                iteration.committed_load_factor();
    const double motion_scale =
      settings.is_cyclic() ? std::max(std::abs(start), std::abs(end)) : 0.;
    StepSize size;
    size.step = size.increment = 1. / n_steps;
    bool   estimated           = false;
    double done                = 0.;
    // The size of the last converged step of this stage (0: none, or the
    // harmonics grew since): the secant predictor's denominator.
    double last_increment = 0.;
    while (done < 1. - 1e-12)
      {
        const double fraction = std::min(1., done + size.increment);
        const double target   = start + fraction * (end - start);
        iteration.start_trial(
          last_increment > 0. ? size.increment / last_increment : 0.);
        const auto clock     = std::chrono::steady_clock::now();
        bool       converged = iteration.solve_trial(target, holding);
        LoadStep   step;
        if (converged)
          {
            step.motion = iteration.trial_motion();
            converged   = !misses_target(step.motion,
                                       target,
                                       std::max(std::abs(target), motion_scale),
                                       holding);
          }
        if (!converged)
          {
            const bool at_floor = !size.can_cut(floor_cuts(holding));
            const bool last_cut =
              size.cuts == settings.maximum_step_cuts || at_floor;
            if (last_cut && !size.retried && iteration.retry_persistently(log))
              {
                size.retried = true;
                continue;
              }
            // The floor, not the count of cuts in a row, stopped a
            // load-controlled stage: its steps had converged at ever
            // smaller sizes towards a load it cannot pass.
            AssertThrow(!at_floor || controls_motion(holding) ||
                          size.cuts == settings.maximum_step_cuts,
                        ExcMessage(
                          limit_load_message(entry,
                                             done,
                                             n_steps,
                                             holding,
                                             settings,
                                             iteration.n_converged_steps(),
                                             segment_label(segment))));
            AssertThrow(
              !last_cut,
              ExcMessage(unconverged_step_message(entry,
                                                  done,
                                                  n_steps,
                                                  holding,
                                                  size.cuts,
                                                  iteration.n_converged_steps(),
                                                  settings,
                                                  segment_label(segment))));
            size.cut();
            log << "  step cut to " << size.increment << " of the "
                << (holding ? "held loads" : "loading") << '\n';
            continue;
          }
        if (iteration.grows(log))
          {
            last_increment = 0.;
            continue;
          }
        last_increment = fraction - done;
        done           = fraction;
        size.converged();
        step.segment = segment;
        step.time    = std::chrono::duration<double>(
                      std::chrono::steady_clock::now() - clock)
                      .count();
        iteration.commit_trial(step, holding, log);
        if (!estimated)
          report_remaining_time(done, size.increment, step.time, log);
        estimated = true;
      }
  }

  void
  LoadPath::report_remaining_time(const double  done,
                                  const double  increment,
                                  const double  step_time,
                                  std::ostream &log) const
  {
    // From the first converged step of a stage: its time times the steps
    // still to come at its size (cuts make it longer, a plateau shorter).
    const double remaining_steps = std::ceil((1. - done) / increment - 1e-9);
    const double remaining_time  = remaining_steps * step_time;
    if (remaining_time > long_stage_seconds)
      {
        std::ostringstream line;
        line << "  estimated: about " << std::lround(remaining_time)
             << " s for the remaining " << remaining_steps
             << " steps of this stage, at this step's " << std::setprecision(3)
             << step_time << " s each\n";
        log << line.str();
      }
  }
} // namespace FourierSSI
