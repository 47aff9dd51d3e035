#include <fourier_ssi/coupled/condensed_interfaces.h>
#include <limits>

namespace FourierSSI
{
  namespace
  {
    /**
     * The interfaces' Newton: 4 non-improving full steps, the line search
     * down to 2^-16, never given up for stalling.
     */
    constexpr NewtonSettings condensed_newton =
      {4, 1. / 65536., std::numeric_limits<unsigned int>::max()};
  } // namespace

  CondensedInterfaces::CondensedInterfaces(const HarmonicSet      &set,
                                           const AllParameters    &parameters,
                                           const NonlinearSources &sources,
                                           const LoadControl      &control)
    : Linearisation(parameters.load_path, parameters.newton_on_load_path())
    , control_kind(parameters.load_path.control)
    , sources(sources)
    , control(control)
    , condensation(std::make_unique<InterfaceCondensation>(
        set,
        *sources.interface_points(),
        control_kind == LoadPathParameters::Control::displacement ?
          control.controlled_harmonic_index() :
          set.size(),
        [&control](const Vector<double> &v) {
          return control.controlled_motion_of(v);
        }))
  {}

  std::string
  CondensedInterfaces::name() const
  {
    using Acceleration = LoadPathParameters::Acceleration;
    return newton ? "Newton (consistent tangent, line search)" :
           settings.acceleration == Acceleration::anderson ?
                    "Anderson m = " + std::to_string(settings.anderson_depth) :
           settings.acceleration == Acceleration::aitken ? "Aitken" :
                                                           "no acceleration";
  }

  NewtonSettings
  CondensedInterfaces::newton_settings() const
  {
    return condensed_newton;
  }

  LoadPathParameters::Acceleration
  CondensedInterfaces::acceleration() const
  {
    return settings.acceleration;
  }

  NoDescent
  CondensedInterfaces::no_descent(const bool persistent,
                                  const bool stalled) const
  {
    (void)persistent;
    (void)stalled;
    return NoDescent::initial_stiffness_update;
  }

  CoupledCorrection
  CondensedInterfaces::newton_direction(const CoupledEvaluation &e,
                                        const CoupledStepState  &state)
  {
    return {condensation->newton_update(e.relative,
                                        state.interfaces.origin,
                                        e.residual,
                                        sources.interface_sampling(),
                                        control.displacement_control(),
                                        control.pattern_motion(),
                                        sources.interface_load_cases().pattern),
            {}};
  }

  CoupledCorrection
  CondensedInterfaces::initial_stiffness_correction(
    FixedPointAcceleration  &acceleration,
    const CoupledStepState  &state,
    const CoupledEvaluation &e) const
  {
    return {acceleration.increment(condensation->on_write_dofs(
                                     state.correction_load),
                                   condensation->on_write_dofs(e.residual)),
            {}};
  }

  void
  CondensedInterfaces::add(const double             alpha,
                           const CoupledCorrection &correction,
                           CoupledStepState        &state) const
  {
    std::vector<Vector<double>> step = correction.load;
    for (Vector<double> &v : step)
      v *= alpha;
    condensation->add(step,
                      state.correction_load,
                      state.correction_solution,
                      state.controlled_motion);
  }

  void
  CondensedInterfaces::complete(CoupledStepState &state) const
  {
    condensation->complete(state.correction_load, state.correction_solution);
    if (control_kind == LoadPathParameters::Control::displacement)
      state.controlled_motion = control.controlled_motions(
        {&state.correction_solution[control.controlled_harmonic_index()]})[0];
  }

  void
  CondensedInterfaces::grow(const unsigned int first)
  {
    condensation->condense(first);
  }

  std::string
  CondensedInterfaces::rank_sums() const
  {
    return "one per iteration, a few per step";
  }
} // namespace FourierSSI
