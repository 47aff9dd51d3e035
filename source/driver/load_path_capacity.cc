#include <cmath>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/load_path_capacity.h>
#include <fourier_ssi/estimation/capacity_plateau.h>
#include <iomanip>
#include <vector>

namespace FourierSSI
{
  LoadAtStep
  applied_load(const CoupledSolver &solver, const AllParameters &parameters)
  {
    return [&](const LoadStepResult &s) {
      return conjugate_load(solver.applied_loads(s.load_factor,
                                                 s.held_fraction),
                            parameters.rigid_foundation,
                            parameters.load_path.motion);
    };
  }

  LoadAtStep
  probe_load(const FoundationMotion motion, const AllParameters &parameters)
  {
    return [motion, &parameters](const LoadStepResult &s) {
      NamedLoad load{parameters.rigid_foundation.reaction_row(motion),
                     load_unit_of(motion)};
      for (const auto &[held, value] : s.held_reactions)
        if (held == motion)
          load.value = value;
      return load;
    };
  }

  LoadAtStep
  goal_load(const CoupledSolver &solver, const AllParameters &parameters)
  {
    if (!parameters.rigid_foundation.probes_direction())
      return applied_load(solver, parameters);
    return probe_load(parameters.load_path.motion ==
                          LoadPathParameters::Motion::rotation ?
                        FoundationMotion::rotation :
                        FoundationMotion::u,
                      parameters);
  }

  Capacity
  capacity_of(const CoupledSolver &solver,
              const AllParameters &parameters,
              const LoadAtStep    &load_at)
  {
    const LoadPathParameters &settings  = parameters.load_path;
    const auto               &steps     = solver.get_steps();
    const auto                motion_at = [&](const LoadStepResult &s) {
      return controlled_component(s.motion, settings.motion);
    };
    // The controlled path starts where the held loads left it.
    double start = 0.;
    for (const LoadStepResult &s : steps)
      if (s.load_factor == 0.)
        start = motion_at(s);
    const double end     = motion_at(steps.back());
    Capacity     result  = {load_at(steps.back()), 0., 0.};
    double       earlier = 0.;
    for (const LoadStepResult &s : steps)
      if (std::abs(motion_at(s) - start) <=
          0.9 * std::abs(end - start) * (1. + 1e-12))
        earlier = load_at(s).value;
    result.rise = result.load.value != 0. ?
                    (result.load.value - earlier) / result.load.value :
                    0.;
    std::vector<double> motion, load;
    for (const LoadStepResult &s : steps)
      if (s.load_factor != 0.)
        {
          motion.push_back(motion_at(s) - start);
          load.push_back(load_at(s).value);
        }
    result.plateau_error = plateau_error(motion, load);
    return result;
  }

  bool
  has_capacity(const CoupledSolver &solver, const AllParameters &parameters)
  {
    // A cyclic path has loops, not a capacity (load-cycles.csv).
    return parameters.load_path.control ==
             LoadPathParameters::Control::displacement &&
           !parameters.load_path.is_cyclic() && solver.get_steps().size() >= 2;
  }

  void
  report_normalised_capacity(const RigidFoundationParameters &foundation,
                             const std::string               &name,
                             const double                     value,
                             const std::string               &unit,
                             const double                     relative_error,
                             const std::string               &error_parts,
                             const unsigned int               row,
                             ResultsTable                    &results,
                             std::ostream                    &log)
  {
    if (foundation.capacity_name.empty())
      return;
    // A capacity is a magnitude (a downward V is negative).
    const double normalised = std::abs(value) / foundation.capacity_reference;
    log << "    " << foundation.capacity_name << " = |" << name << "| / ("
        << foundation.capacity_reference << " " << unit
        << ") = " << std::setprecision(7) << normalised;
    if (std::isfinite(relative_error))
      log << " \u00b1 " << std::setprecision(2)
          << relative_error * std::abs(normalised) << " (" << error_parts
          << ")";
    log << std::setprecision(6) << std::endl;
    const Harmonic any{0, Family::symmetric};
    results.add("capacity_normalised", any, row, normalised, "-");
    results.add("capacity_normalised_error",
                any,
                row,
                relative_error * std::abs(normalised),
                "-");
  }
} // namespace FourierSSI
