#include <deal.II/base/exceptions.h>
#include <fourier_ssi/coupled/load_control.h>

namespace FourierSSI
{
  namespace
  {
    /** The rigid motion of fields given per harmonic (rigid_motion_of). */
    RigidMotion
    motion_of_fields(const HarmonicSet                 &set,
                     const std::vector<Vector<double>> &fields)
    {
      return rigid_motion_of(set, [&fields](const unsigned int h) {
        return fields[h];
      });
    }
  } // namespace

  LoadControl::LoadControl(const HarmonicSet    &set,
                           const AllParameters  &parameters,
                           const LoadPathStates &states,
                           const bool            motion_kept_in_state)
    : set(set)
    , settings(parameters.load_path)
    , foundation_parameters(parameters.rigid_foundation)
    , states(states)
    , motion_kept_in_state(motion_kept_in_state)
  {}

  void
  LoadControl::read_load_motions()
  {
    const LoadPattern &loads = states.loads;
    // A swipe's multipliers read the rigid motions of u_F and u_V at every
    // iterate: constants of the run.
    if (!loads.swipe_solution.empty())
      {
        pattern_rigid_motion = motion_of_fields(set, loads.solution);
        swipe_rigid_motion   = motion_of_fields(set, loads.swipe_solution);
      }
    // The controlled motions of u_F and u_held: constants of the run.
    held_motion = 0.;
    if (settings.control != LoadPathParameters::Control::displacement)
      return;
    const unsigned int        h      = controlled_harmonic_index();
    const std::vector<double> motion = controlled_motions(
      loads.holds_loads() ?
        std::vector<const Vector<double> *>{&loads.solution[h],
                                            &loads.held_solution[h]} :
        std::vector<const Vector<double> *>{&loads.solution[h]});
    pattern_controlled_motion = motion[0];
    held_motion               = loads.holds_loads() ? motion[1] : 0.;
    AssertThrow(pattern_controlled_motion != 0.,
                ExcMessage("Load path/Controlled motion: the Rigid foundation "
                           "loads do not drive this motion (give the load "
                           "that does, e.g. V for vertical)"));
  }

  void
  LoadControl::start_step(const double      target,
                          const bool        holding,
                          CoupledStepState &state)
  {
    controls_motion =
      !holding && settings.control == LoadPathParameters::Control::displacement;
    // A swipe holds w from the end of the held stage on.
    swiping_now = !holding && foundation_parameters.swipes();
    // Holding: the held loads come on at a fixed load factor.
    if (holding)
      state.held_fraction = target;
    holding_now = holding;
  }

  void
  LoadControl::set_multipliers(const double      target,
                               CoupledStepState &state) const
  {
    if (swiping_now)
      {
        // The state without lambda and mu: K^-1 c + rho u_held.
        const RigidMotion now = rigid_motion_of(set, [&](const unsigned int h) {
          return states.loads.total_displacement(h,
                                                 0.,
                                                 state.correction_solution[h],
                                                 state.held_fraction);
        });
        const auto [load_factor, swipe_force] =
          swipe_multipliers(now,
                            pattern_rigid_motion,
                            swipe_rigid_motion,
                            target,
                            swipe_settlement);
        state.load_factor = load_factor;
        state.swipe_force = swipe_force;
      }
    else if (!holding_now)
      state.load_factor =
        controls_motion ? controlled_load_factor(state, target) : target;
  }

  std::array<double, 2>
  LoadControl::newton_multiplier_changes(
    const std::vector<Vector<double>> &du,
    const std::vector<Vector<double>> &by_pattern,
    const std::vector<Vector<double>> *by_swipe) const
  {
    // The iterate holds both motions already: du must keep them.
    if (swiping_now)
      return swipe_multipliers(motion_of_fields(set, du),
                               motion_of_fields(set, by_pattern),
                               motion_of_fields(set, *by_swipe),
                               0.,
                               0.);
    std::array<double, 2> changes = {{0., 0.}};
    if (controls_motion)
      {
        const unsigned int h       = controlled_harmonic_index();
        const double       pattern = controlled_motion_of(by_pattern[h]);
        if (pattern != 0.)
          changes[0] = -controlled_motion_of(du[h]) / pattern;
      }
    return changes;
  }

  unsigned int
  LoadControl::controlled_harmonic_index() const
  {
    const Harmonic wanted = controlled_harmonic(settings.motion);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.harmonic(h).n == wanted.n &&
          set.harmonic(h).family == wanted.family)
        {
          AssertThrow(set.problem(h).get_foundation() != nullptr,
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

  double
  LoadControl::controlled_motion_of(const Vector<double> &v) const
  {
    return controlled_component(
      set.problem(controlled_harmonic_index()).get_foundation()->motion(v),
      settings.motion);
  }

  std::vector<double>
  LoadControl::controlled_motions(
    const std::vector<const Vector<double> *> &fields) const
  {
    std::vector<double> motions(fields.size(), 0.);
    if (set.owns(controlled_harmonic_index()))
      for (unsigned int i = 0; i < fields.size(); ++i)
        motions[i] = controlled_motion_of(*fields[i]);
    set.sum_over_ranks(motions);
    return motions;
  }

  bool
  LoadControl::reports_reactions() const
  {
    return !foundation_parameters.reported_motions().empty();
  }

  std::vector<std::pair<FoundationMotion, double>>
  LoadControl::held_reactions(
    const CoupledStepState            &state,
    const std::vector<Vector<double>> &nonlinear_load) const
  {
    const std::vector<FoundationMotion> held =
      foundation_parameters.reported_motions();
    if (held.empty())
      return {};
    std::vector<double> values(held.size(), 0.);
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const RigidFoundation *foundation = set.problem(h).get_foundation();
        if (!set.owns(h) || foundation == nullptr ||
            !foundation->holds_motion())
          continue;
        Vector<double> force =
          set.problem(h).nodal_forces(states.total_displacement(state, h),
                                      state.load_factor);
        force -= nonlinear_load[h];
        for (const auto &[motion, load] : foundation->held_reactions(force))
          for (unsigned int i = 0; i < held.size(); ++i)
            if (held[i] == motion)
              values[i] = load;
      }
    set.sum_over_ranks(values);
    std::vector<std::pair<FoundationMotion, double>> reactions;
    for (unsigned int i = 0; i < held.size(); ++i)
      reactions.emplace_back(held[i], values[i]);
    return reactions;
  }

  double
  LoadControl::controlled_load_factor(const CoupledStepState &state,
                                      const double            target) const
  {
    // Condensed, K^-1 c is not whole while a step iterates: its motion is
    // kept with c (InterfaceCondensation::add).
    const double correction_motion =
      motion_kept_in_state ?
        state.controlled_motion :
        controlled_motions(
          {&state.correction_solution[controlled_harmonic_index()]})[0];
    const double now = correction_motion + state.held_fraction * held_motion;
    return (target - now) / pattern_controlled_motion;
  }

  std::array<double, 2>
  LoadControl::swipe_multipliers(const RigidMotion &now,
                                 const RigidMotion &by_pattern,
                                 const RigidMotion &by_swipe,
                                 const double       target,
                                 const double       settlement) const
  {
    const auto m = [this](const RigidMotion &motion) {
      return controlled_component(motion, settings.motion);
    };
    // Row 1: the controlled motion (or lambda itself), row 2: w.
    const double a   = controls_motion ? m(by_pattern) : 1.,
                 b   = controls_motion ? m(by_swipe) : 0.,
                 e   = controls_motion ? target - m(now) : target;
    const double c   = by_pattern.vertical_displacement,
                 d   = by_swipe.vertical_displacement,
                 f   = settlement - now.vertical_displacement;
    const double det = a * d - b * c;
    AssertThrow(det != 0.,
                ExcMessage("Rigid foundation/Held motions: the swipe's "
                           "vertical load does not move w, or the Rigid "
                           "foundation loads do not drive the Load "
                           "path/Controlled motion with w held"));
    return {{(e * d - b * f) / det, (a * f - e * c) / det}};
  }
} // namespace FourierSSI
