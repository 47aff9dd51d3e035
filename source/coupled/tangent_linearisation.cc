#include <deal.II/base/exceptions.h>
#include <fourier_ssi/coupled/tangent_linearisation.h>
#include <set>

namespace FourierSSI
{
  namespace
  {
    /**
     * fields[h] := its sum over the ranks the harmonics are distributed
     * over (one sum; on one rank nothing): each field computed by its
     * harmonic's owner, zero elsewhere, becomes the same bits on every rank.
     */
    void
    sum_fields_over_ranks(const HarmonicSet           &set,
                          std::vector<Vector<double>> &fields)
    {
      if (set.n_owning_ranks() == 1)
        return;
      std::vector<double> flat;
      for (const Vector<double> &field : fields)
        flat.insert(flat.end(), field.begin(), field.end());
      set.sum_over_ranks(flat);
      auto next = flat.begin();
      for (Vector<double> &field : fields)
        {
          std::copy(next, next + field.size(), field.begin());
          next += field.size();
        }
    }

    /** The soil's Newton: no non-improving full step, halving to 1/16. */
    constexpr NewtonSettings coupled_tangent_newton = {0, 1. / 16., 20};
  } // namespace

  TangentLinearisation::TangentLinearisation(HarmonicSet            &set,
                                             const AllParameters    &parameters,
                                             const NonlinearSources &sources,
                                             const LoadControl      &control,
                                             const LoadPathStates   &states)
    : Linearisation(parameters.load_path, parameters.newton_on_load_path())
    , set(set)
    , sources(sources)
    , control(control)
    , states(states)
    , tangent_over_ranks(parameters.distributes_coupled_tangent())
  {}

  std::string
  TangentLinearisation::name() const
  {
    using Acceleration = LoadPathParameters::Acceleration;
    if (newton)
      return "Newton on the coupled tangent, backtracking";
    return settings.acceleration == Acceleration::aitken ?
             "initial stiffness, Aitken" :
           settings.acceleration == Acceleration::anderson ?
             "initial stiffness, Anderson" :
             "initial stiffness";
  }

  NewtonSettings
  TangentLinearisation::newton_settings() const
  {
    return coupled_tangent_newton;
  }

  LoadPathParameters::Acceleration
  TangentLinearisation::acceleration() const
  {
    return newton ? LoadPathParameters::Acceleration::none :
                    settings.acceleration;
  }

  NoDescent
  TangentLinearisation::no_descent(const bool persistent,
                                   const bool stalled) const
  {
    return persistent && !stalled ?
             NoDescent::initial_stiffness_update_and_restart :
             NoDescent::cut;
  }

  CoupledCorrection
  TangentLinearisation::newton_direction(const CoupledEvaluation &e,
                                         const CoupledStepState  &state)
  {
    update_tangent(e.strain,
                   e.relative,
                   state.interfaces.origin,
                   control.displacement_control());
    return correction_of(tangent_correction(e.residual));
  }

  CoupledCorrection
  TangentLinearisation::initial_stiffness_correction(
    FixedPointAcceleration  &acceleration,
    const CoupledStepState  &state,
    const CoupledEvaluation &e) const
  {
    return correction_of(
      acceleration.increment(state.correction_load, e.residual));
  }

  CoupledCorrection
  TangentLinearisation::correction_of(std::vector<Vector<double>> load) const
  {
    std::vector<std::vector<Vector<double>>> increment(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      increment[h] = {load[h]};
    set.solve_increments(increment);
    CoupledCorrection correction;
    correction.load = std::move(load);
    for (unsigned int h = 0; h < set.size(); ++h)
      correction.solution.push_back(std::move(increment[h][0]));
    return correction;
  }

  void
  TangentLinearisation::add(const double             alpha,
                            const CoupledCorrection &correction,
                            CoupledStepState        &state) const
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        state.correction_load[h].add(alpha, correction.load[h]);
        // A harmonic's displacement is on its owner only.
        if (set.owns(h))
          state.correction_solution[h].add(alpha, correction.solution[h]);
      }
  }

  void
  TangentLinearisation::grow(const unsigned int first)
  {
    (void)first;
    // The coupled tangent's blocks and pattern are those of the set it was
    // built on: the next Newton update builds it anew over every harmonic
    // (the kept factorizations of the earlier K_h serve the re-solves).
    tangent.reset();
    tangent_pattern.clear();
  }

  std::string
  TangentLinearisation::rank_sums() const
  {
    return "strain amplitudes and theta integrals every iteration, the "
           "controlled motion under displacement control, a few per "
           "step; with Stiffness = tangent the softening, the "
           "tangent's values and the load correction every Newton "
           "update";
  }

  std::vector<Vector<double>>
  TangentLinearisation::tangent_product(
    const std::vector<Vector<double>> &fields,
    const std::vector<Vector<double>> &x)
  {
    update_tangent(sources.strain_samples(fields, 0., 0.),
                   sources.relative_displacements(fields, 0., 0.),
                   states.committed.interfaces.origin,
                   false);
    std::vector<Vector<double>> y;
    tangent->vmult(y, x);
    return y;
  }

  void
  TangentLinearisation::update_tangent(
    const std::vector<StrainVector> &strain,
    const std::vector<LocalVector>  &relative,
    const std::vector<LocalVector>  &interface_origin,
    const bool                       displacement_control)
  {
    const unsigned int H = set.size();
    // K_t = diag(K_h) - the soil's softening at the points that yield -
    // the interfaces' at the samples that slip or open.
    if (!tangent)
      tangent = std::make_unique<CoupledTangent>(set,
                                                 sources.tangent_dofs(),
                                                 tangent_over_ranks);
    tangent->reset_to_elastic();
    sources.add_softening(
      strain, states.committed, relative, interface_origin, *tangent);
    if (displacement_control)
      add_control_stiffening();
    tangent->factorize();
    tangent_pattern.resize(H);
    for (unsigned int h = 0; h < H; ++h)
      tangent_pattern[h] = states.loads.load[h];
    // F_h is on h's owner only (LoadPattern); the solve takes all of F.
    sum_fields_over_ranks(set, tangent_pattern);
    tangent->solve(tangent_pattern);
  }

  void
  TangentLinearisation::add_control_stiffening()
  {
    stiffen_motion(controlled_harmonic(settings.motion), settings.motion);
    if (control.swiping())
      stiffen_motion({0, Family::symmetric},
                     LoadPathParameters::Motion::vertical);
  }

  void
  TangentLinearisation::stiffen_motion(
    const Harmonic                  &wanted,
    const LoadPathParameters::Motion component)
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.harmonic(h).n == wanted.n &&
          set.harmonic(h).family == wanted.family)
        {
          const RigidFoundation *foundation = set.problem(h).get_foundation();
          const std::set<types::global_dof_index> master_set =
            foundation->master_dofs();
          const std::vector<types::global_dof_index> masters(master_set.begin(),
                                                             master_set.end());
          const SparseMatrix<double> &K = set.problem(h).get_system_matrix();
          // c_k = m(e_k) on each master DoF; alpha scales c c^T to the
          // masters' own stiffness.
          Vector<double>      unit(K.m());
          std::vector<double> c(masters.size());
          double              diagonal = 0., c_squared = 0.;
          for (unsigned int k = 0; k < masters.size(); ++k)
            {
              unit[masters[k]] = 1.;
              c[k] = controlled_component(foundation->motion(unit), component);
              unit[masters[k]] = 0.;
              diagonal =
                std::max(diagonal, std::abs(K.diag_element(masters[k])));
              c_squared += c[k] * c[k];
            }
          if (c_squared == 0.)
            continue;
          const double       alpha = diagonal / c_squared;
          FullMatrix<double> local(masters.size(), masters.size());
          for (unsigned int i = 0; i < masters.size(); ++i)
            for (unsigned int j = 0; j < masters.size(); ++j)
              local(i, j) = alpha * c[i] * c[j];
          tangent->add(h, h, local, masters, masters);
        }
  }

  std::vector<Vector<double>>
  TangentLinearisation::tangent_correction(
    const std::vector<Vector<double>> &residual) const
  {
    const LoadPattern          &loads = states.loads;
    std::vector<Vector<double>> du    = residual;
    tangent->solve(du);
    // A swipe: K_t^-1 e_V (one more solve with the factorization).
    std::vector<Vector<double>> swipe_pattern;
    if (control.swiping())
      {
        // e_V is on the owner of harmonic 0 only; the solve takes all of it.
        swipe_pattern = loads.swipe_load;
        sum_fields_over_ranks(set, swipe_pattern);
        tangent->solve(swipe_pattern);
      }
    // K_t^-1 F and du are whole on every rank (the tangent's solve).
    const std::array<double, 2> changes = control.newton_multiplier_changes(
      du, tangent_pattern, control.swiping() ? &swipe_pattern : nullptr);
    const double load_change = changes[0], swipe_change = changes[1];
    std::vector<Vector<double>> change(set.size());
    set.for_each([&](const unsigned int h) {
      change[h].reinit(du[h].size());
      if (!set.owns(h))
        return; // K_h is on its owner only
      du[h].add(load_change, tangent_pattern[h]);
      if (control.swiping())
        du[h].add(swipe_change, swipe_pattern[h]);
      set.problem(h).get_system_matrix().vmult(change[h], du[h]);
      change[h].add(-load_change, loads.load[h]);
      if (control.swiping())
        change[h].add(-swipe_change, loads.swipe_load[h]);
      set.problem(h).get_homogeneous_constraints().set_zero(change[h]);
    });
    sum_fields_over_ranks(set, change);
    return change;
  }
} // namespace FourierSSI
