#include <fourier_ssi/coupled/load_path_states.h>

namespace FourierSSI
{
  LoadPathStates::LoadPathStates(const HarmonicSet   &set,
                                 const AllParameters &parameters)
    : harmonic_set(set)
    , foundation_parameters(parameters.rigid_foundation)
  {}

  Vector<double>
  LoadPathStates::solution(const unsigned int i) const
  {
    Vector<double> u = total_displacement(committed, i);
    harmonic_set.broadcast_from_owner(i, u.begin(), u.size());
    return u;
  }

  Vector<double>
  LoadPathStates::last_step_increment(const unsigned int i) const
  {
    Vector<double> du = total_displacement(committed, i);
    if (i < before_last.correction_solution.size())
      du -= total_displacement(before_last, i);
    harmonic_set.broadcast_from_owner(i, du.begin(), du.size());
    return du;
  }

  std::array<double, 6>
  LoadPathStates::applied_loads(const double load_factor,
                                const double held_fraction) const
  {
    return applied_foundation_loads(foundation_parameters,
                                    load_factor,
                                    held_fraction);
  }

  void
  LoadPathStates::write_csv(const std::string &filename) const
  {
    write_load_path_csv(filename, steps, foundation_parameters, sources);
  }

  void
  LoadPathStates::start_at_rest()
  {
    committed.correction_solution = loads.solution;
    for (Vector<double> &v : committed.correction_solution)
      v = 0.;
    committed.correction_load = committed.correction_solution;
  }

  void
  LoadPathStates::extend_at_rest(const unsigned int first)
  {
    for (unsigned int h = first; h < harmonic_set.size(); ++h)
      {
        committed.correction_solution.emplace_back(loads.solution[h].size());
        committed.correction_load.emplace_back(loads.solution[h].size());
      }
  }

  void
  LoadPathStates::write_held_motions(std::ostream      &log,
                                     const std::string &note) const
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

  void
  LoadPathStates::write_held_loads(std::ostream &log) const
  {
    const auto held = applied_loads(0., 1.);
    log << "V " << held[2] << " kN, H " << held[0] << " kN, M "
        << moment_about_reference(held, foundation_parameters) << " kN m, T "
        << held[5] << " kN m";
  }

  void
  LoadPathStates::start_trial(const double ratio)
  {
    trial = committed;
    if (!(ratio > 0.))
      return;
    const auto move_on = [ratio](Vector<double>       &v,
                                 const Vector<double> &last,
                                 const Vector<double> &before) {
      v.add(ratio, last);
      v.add(-ratio, before);
    };
    for (unsigned int h = 0; h < harmonic_set.size(); ++h)
      {
        move_on(trial.correction_load[h],
                committed.correction_load[h],
                before_last.correction_load[h]);
        move_on(trial.correction_solution[h],
                committed.correction_solution[h],
                before_last.correction_solution[h]);
      }
    trial.controlled_motion +=
      ratio * (committed.controlled_motion - before_last.controlled_motion);
  }

  Vector<double>
  LoadPathStates::total_displacement(const State       &state,
                                     const unsigned int h) const
  {
    return loads.total_displacement(h,
                                    state.load_factor,
                                    state.correction_solution[h],
                                    state.held_fraction,
                                    state.swipe_force);
  }

  RigidMotion
  LoadPathStates::motion_of(const State &state) const
  {
    return rigid_motion_of(harmonic_set, [&](const unsigned int h) {
      return total_displacement(state, h);
    });
  }

  void
  LoadPathStates::commit(const LoadStep &step)
  {
    before_last                = std::move(committed);
    committed                  = trial;
    trial_result.load_factor   = committed.load_factor;
    trial_result.held_fraction = committed.held_fraction;
    trial_result.swipe_force   = committed.swipe_force;
    trial_result.motion        = step.motion;
    trial_result.time          = step.time;
    trial_result.segment       = step.segment;
    trial_result.n_harmonics   = harmonic_set.size();
  }

  void
  LoadPathStates::record_interfaces(const NonlinearInterfacePoints &interfaces,
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

  void
  LoadPathStates::record_trial(
    const bool                                         holding,
    std::ostream                                      &log,
    const std::function<void(const LoadStepResult &)> &observer)
  {
    // The next trial starts from a fresh record (CoupledSolver::solve_trial).
    steps.push_back(std::move(trial_result));
    if (observer)
      observer(steps.back());
    write_step_line(
      log, steps.size(), holding, steps.back(), foundation_parameters, sources);
  }
} // namespace FourierSSI
