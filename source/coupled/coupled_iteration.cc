#include <algorithm>
#include <cmath>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/harmonic/rigid_foundation.h>
#include <iomanip>
#include <sstream>

namespace FourierSSI
{
  Vector<double>
  load_factor_pattern(const HarmonicProblem &problem)
  {
    const RigidFoundation *foundation = problem.get_foundation();
    if (foundation == nullptr)
      return problem.get_system_rhs();
    Vector<double> pattern(problem.get_system_rhs().size());
    foundation->add_loads(pattern);
    return pattern;
  }

  Vector<double>
  held_stage_load(const HarmonicProblem &problem)
  {
    const RigidFoundation *foundation = problem.get_foundation();
    Vector<double>         held(problem.get_system_rhs().size());
    if (foundation == nullptr)
      return held;
    // The scene's load is body force + tractions + the foundation's loads
    // (HarmonicProblem::assemble_system): the first two are held.
    held = problem.get_system_rhs();
    held -= load_factor_pattern(problem);
    foundation->add_held_loads(held);
    return held;
  }

  double
  combined_load_norm(const double load_factor,
                     const double held_fraction,
                     const double pattern_norm,
                     const double pattern_held_dot,
                     const double held_norm)
  {
    const double lambda = load_factor, rho = held_fraction;
    const double norm_sqr = lambda * lambda * pattern_norm * pattern_norm +
                            2. * lambda * rho * pattern_held_dot +
                            rho * rho * held_norm * held_norm;
    return std::sqrt(std::max(norm_sqr, 0.));
  }

  double
  norm_over_harmonics(const std::vector<Vector<double>> &vectors)
  {
    double sum = 0.;
    for (const Vector<double> &v : vectors)
      sum += v.norm_sqr();
    return std::sqrt(sum);
  }

  double
  dot_over_harmonics(const std::vector<Vector<double>> &a,
                     const std::vector<Vector<double>> &b)
  {
    double sum = 0.;
    for (unsigned int h = 0; h < a.size(); ++h)
      sum += a[h] * b[h];
    return sum;
  }

  Harmonic
  controlled_harmonic(const LoadPathParameters::Motion motion)
  {
    using M = LoadPathParameters::Motion;
    if (motion == M::vertical)
      return {0, Family::symmetric};
    if (motion == M::twist)
      return {0, Family::antisymmetric};
    return {1, Family::symmetric};
  }

  double
  controlled_component(const RigidMotion               &motion,
                       const LoadPathParameters::Motion controlled)
  {
    using M = LoadPathParameters::Motion;
    switch (controlled)
      {
        case M::vertical:
          return motion.vertical_displacement;
        case M::twist:
          return motion.twist;
        case M::horizontal:
          return motion.horizontal_displacement;
        case M::rotation:
          return motion.rotation;
      }
    return 0.;
  }

  std::array<double, 6>
  applied_foundation_loads(const RigidFoundationParameters &f,
                           const double                     load_factor,
                           const double                     held_fraction)
  {
    const double z_ref = f.reference_elevation;
    const double H     = load_factor * f.horizontal_force +
                     held_fraction * f.held_horizontal_force;
    const double M = load_factor * f.moment + held_fraction * f.held_moment;
    return {
      {H,
       load_factor * f.horizontal_force_y,
       load_factor * f.vertical_force + held_fraction * f.held_vertical_force,
       load_factor * (f.moment_x - z_ref * f.horizontal_force_y),
       M + z_ref * H,
       load_factor * f.torque + held_fraction * f.held_torque}};
  }

  double
  moment_about_reference(const std::array<double, 6>     &loads,
                         const RigidFoundationParameters &foundation)
  {
    return loads[4] - foundation.reference_elevation * loads[0];
  }

  NamedLoad
  conjugate_load(const std::array<double, 6>     &loads,
                 const RigidFoundationParameters &foundation,
                 const LoadPathParameters::Motion controlled)
  {
    using M = LoadPathParameters::Motion;
    switch (controlled)
      {
        case M::vertical:
          return {"V", "kN", loads[2]};
        case M::horizontal:
          return {"H", "kN", loads[0]};
        case M::rotation:
          return {"M", "kN.m", moment_about_reference(loads, foundation)};
        case M::twist:
          return {"T", "kN.m", loads[5]};
      }
    return {};
  }

  std::string
  held_reaction_columns(
    const RigidFoundationParameters                        &foundation,
    const std::vector<std::pair<FoundationMotion, double>> &reactions)
  {
    std::string columns;
    for (const auto &[motion, load] : reactions)
      {
        std::string unit = load_unit_of(motion);
        unit.erase(std::remove(unit.begin(), unit.end(), '.'), unit.end());
        columns += ',' + foundation.reaction_row(motion) + '_' + unit;
      }
    return columns;
  }

  void
  write_load_step_columns(std::ostream                    &out,
                          const unsigned int               step,
                          const double                     load_factor,
                          const double                     held_fraction,
                          const double                     swipe_force,
                          const RigidFoundationParameters &f,
                          const RigidMotion               &motion,
                          const unsigned int               iterations,
                          const double                     residual)
  {
    // M about the reference point, as given in the prm.
    const auto loads = applied_foundation_loads(f, load_factor, held_fraction);
    const double moment = moment_about_reference(loads, f);
    out << step << ',' << load_factor << ','
        << vertical_force_of(loads, swipe_force) << ',' << loads[0] << ','
        << moment << ',' << loads[5] << ',' << motion.vertical_displacement
        << ',' << motion.horizontal_displacement << ',' << motion.rotation
        << ',' << motion.twist << ',' << iterations << ',' << residual;
  }

  namespace
  {
    /**
     * The step whose interval [k-1, k] / n_steps the path was in, as the
     * user counts them; the round-off guard keeps a completed step's end
     * out of the next.
     */
    unsigned int
    step_of(const double done, const unsigned int n_steps)
    {
      return std::min<unsigned int>(
        n_steps,
        static_cast<unsigned int>(std::floor(done * n_steps + 1e-9)) + 1);
    }
  } // namespace

  std::string
  unconverged_step_message(const std::string        &entry,
                           const double              done,
                           const unsigned int        n_steps,
                           const bool                held,
                           const unsigned int        cuts,
                           const unsigned int        converged_steps,
                           const LoadPathParameters &settings,
                           const std::string        &segment)
  {
    return entry + ": load step " + std::to_string(step_of(done, n_steps)) +
           " of " + std::to_string(n_steps) +
           (held ? " of the held loads" : segment) + " (after " +
           std::to_string(cuts) + " cuts" +
           (cuts < settings.maximum_step_cuts ?
              ", at the smallest step size, 2^-" +
                std::to_string(LoadPathParameters::most_step_cuts) +
                " of a load step" :
              "") +
           ") did not converge in " +
           std::to_string(settings.maximum_iterations) + " iterations; the " +
           std::to_string(converged_steps) + " converged steps are kept";
  }

  std::string
  limit_load_message(const std::string        &entry,
                     const double              done,
                     const unsigned int        n_steps,
                     const bool                held,
                     const LoadPathParameters &settings,
                     const unsigned int        converged_steps,
                     const std::string        &segment)
  {
    std::ostringstream line;
    line << entry << ": load step " << step_of(done, n_steps) << " of "
         << n_steps << (held ? " of the held loads" : segment) << ": "
         << (held ? "the held loads (body force, tractions, held foundation "
                    "loads) are" :
                    "the loads are")
         << " carried only up to " << std::setprecision(4) << done
         << " of their full value: the steps converge ever closer to a "
            "limit load and the next would be below 2^-"
         << settings.maximum_step_cuts
         << " of a load step (Maximum step cuts); "
         << (held ? "the soil cannot carry them (check the supports that "
                    "hold it, or lower them)" :
                    "Load path/Control = displacement follows a foundation "
                    "past its limit")
         << "; the " << converged_steps << " converged steps are kept";
    return line.str();
  }

  FixedPointAcceleration::FixedPointAcceleration(
    const Kind         kind,
    const unsigned int anderson_depth)
    : kind(kind)
    , anderson(anderson_depth)
  {}

  std::vector<Vector<double>>
  FixedPointAcceleration::increment(const std::vector<Vector<double>> &load,
                                    const std::vector<Vector<double>> &residual)
  {
    if (kind == Kind::anderson)
      return anderson.increment(load, residual);
    if (kind == Kind::aitken)
      {
        restart_aitken_if_stalled(residual);
        if (!previous_residual.empty())
          omega = aitken_factor(residual);
      }
    previous_residual                  = residual;
    std::vector<Vector<double>> result = residual;
    for (Vector<double> &block : result)
      block *= omega;
    return result;
  }

  void
  FixedPointAcceleration::restart_aitken_if_stalled(
    const std::vector<Vector<double>> &residual)
  {
    // Near a limit the Aitken factor can collapse towards zero, where the
    // updates omega R no longer move the plastic state and each new factor
    // is a ratio of round-off: |R| then freezes short of the tolerance
    // (measured: a swipe at |R| / |F| = 3.6e-5 for 2900 iterations, omega
    // 1e-6 ... 1e-3 of either sign, under one BLAS kernel and not another).
    // Restarting from the plain initial-stiffness update (omega = 1) moves
    // the state again.
    const double norm = std::sqrt(dot_over_harmonics(residual, residual));
    if (norm < best_residual_norm)
      {
        best_residual_norm      = norm;
        updates_since_best_norm = 0;
        return;
      }
    if (++updates_since_best_norm < stalled_aitken_updates)
      return;
    omega = 1.;
    previous_residual.clear();
    best_residual_norm      = norm;
    updates_since_best_norm = 0;
  }

  double
  FixedPointAcceleration::aitken_factor(
    const std::vector<Vector<double>> &residual) const
  {
    std::vector<Vector<double>> change = residual;
    for (unsigned int h = 0; h < change.size(); ++h)
      change[h] -= previous_residual[h];
    const double change_sqr = dot_over_harmonics(change, change);
    if (!(change_sqr > 0.))
      return omega;
    const double factor =
      -omega * dot_over_harmonics(previous_residual, change) / change_sqr;
    // A factor <= 0 reverses or freezes the update (R grew along itself):
    // that is no relaxation, so take the plain update (measured on the
    // stalled swipe step: 169 updates instead of 681).
    return factor > 0. ? factor : 1.;
  }

  Vector<double>
  total_displacement(const Vector<double> &pattern,
                     const double          load_factor,
                     const Vector<double> &correction,
                     const Vector<double> *held,
                     const double          held_fraction)
  {
    Vector<double> u = pattern;
    u.sadd(load_factor, 1., correction);
    if (held != nullptr)
      u.add(held_fraction, *held);
    return u;
  }
} // namespace FourierSSI
