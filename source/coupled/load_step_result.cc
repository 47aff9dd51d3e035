// The record of a converged load step: its log line and its row of
// load-displacement.csv, each nonlinear source adding only its own part.
#include <algorithm>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/input/atomic_file.h>
#include <iomanip>

namespace FourierSSI
{
  namespace
  {
    /**
     * "factor lambda, V .. kN, H .. kN[, M .. kN m][, T .. kN m]; w .. m,
     * u .. m[, rotation .. rad][, twist .. rad]": the loads the scene
     * applies (M about the reference point, as in load-displacement.csv),
     * each with the motion it works on.
     */
    void
    write_foundation_state(std::ostream                    &log,
                           const LoadStepResult            &result,
                           const RigidFoundationParameters &f)
    {
      const auto loads =
        applied_foundation_loads(f, result.load_factor, result.held_fraction);
      const RigidMotion &motion = result.motion;
      const bool         moment = f.moment != 0. || f.held_moment != 0.;
      const bool         torque = f.torque != 0. || f.held_torque != 0.;
      log << "factor " << result.load_factor << ", V "
          << vertical_force_of(loads, result.swipe_force) << " kN, H "
          << loads[0] << " kN";
      if (moment)
        log << ", M " << moment_about_reference(loads, f) << " kN m";
      if (torque)
        log << ", T " << loads[5] << " kN m";
      log << "; w " << motion.vertical_displacement << " m, u "
          << motion.horizontal_displacement << " m";
      if (moment)
        log << ", rotation " << motion.rotation << " rad";
      if (torque)
        log << ", twist " << motion.twist << " rad";
      for (const auto &[held, load] : result.held_reactions)
        log << "; " << f.reaction_label(held) << " " << load << " "
            << load_unit_of(held);
    }
  } // namespace

  void
  write_step_line(std::ostream                    &log,
                  const unsigned int               step,
                  const bool                       holding,
                  const LoadStepResult            &result,
                  const RigidFoundationParameters &foundation,
                  const RecordedSources           &sources)
  {
    log << "  step " << step << (holding ? " (held loads): " : ": ");
    write_foundation_state(log, result, foundation);
    log << "; " << result.iterations << " iterations";
    if (sources.soil)
      log << "; plastic samples " << result.n_plastic << " of "
          << result.n_plastic + result.n_elastic << "; max f "
          << result.largest_yield_value << " kPa";
    if (sources.interfaces != nullptr)
      {
        log << "; interface stick/slip/open " << result.contact[0] << '/'
            << result.contact[1] << '/' << result.contact[2];
        sources.interfaces->write_multiplier_updates(
          log, result.multiplier_updates, result.interface_state.relative);
      }
    log << "; " << result.n_harmonics << " harmonics; " << result.time << " s"
        << std::endl;
  }

  void
  write_load_path_csv(const std::string                 &filename,
                      const std::vector<LoadStepResult> &steps,
                      const RigidFoundationParameters   &foundation,
                      const RecordedSources             &sources)
  {
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    // A cyclic path (Load path/Targets) numbers the segment of each step.
    const bool cyclic =
      std::any_of(steps.begin(), steps.end(), [](const LoadStepResult &r) {
        return r.segment > 1;
      });
    // The loads that hold the held motions, or a direction probe's H and M,
    // one column each: the H and M columns before them are the applied
    // drive.
    out << load_step_csv_header
        << (sources.soil ? ",elastic,plastic,max_yield_kPa" : "")
        << (sources.interfaces != nullptr ? ",stick,slip,open" : "")
        << ",harmonics,time_s,held_fraction"
        << (steps.empty() ?
              std::string() :
              held_reaction_columns(foundation, steps.back().held_reactions))
        << (cyclic ? ",segment" : "") << ",converged\n"
        << std::setprecision(12);
    for (unsigned int s = 0; s < steps.size(); ++s)
      {
        const LoadStepResult &r = steps[s];
        write_load_step_columns(out,
                                s + 1,
                                r.load_factor,
                                r.held_fraction,
                                r.swipe_force,
                                foundation,
                                r.motion,
                                r.iterations,
                                r.residual);
        if (sources.soil)
          out << ',' << r.n_elastic << ',' << r.n_plastic << ','
              << r.largest_yield_value;
        if (sources.interfaces != nullptr)
          out << ',' << r.contact[0] << ',' << r.contact[1] << ','
              << r.contact[2];
        out << ',' << r.n_harmonics << ',' << r.time << ',' << r.held_fraction;
        for (const auto &reaction : r.held_reactions)
          out << ',' << reaction.second;
        if (cyclic)
          out << ',' << r.segment;
        out << ",1\n";
      }
    file.commit();
  }

  std::vector<InterfaceSnapshot>
  interface_states(const std::vector<LoadStepResult> &steps)
  {
    std::vector<InterfaceSnapshot> states;
    states.reserve(steps.size());
    for (const LoadStepResult &step : steps)
      states.push_back(step.interface_state);
    return states;
  }
} // namespace FourierSSI
