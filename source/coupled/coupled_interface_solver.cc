#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <fourier_ssi/coupled/balance_iteration.h>
#include <fourier_ssi/coupled/coupled_interface_solver.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/safeguarded_newton.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Load path";

    /**
     * With growth n_max is Maximum harmonic, so that the samples (and the
     * state kept at them) stay valid when harmonics are added.
     */
    unsigned int
    theta_samples_for(const std::vector<Harmonic> &list,
                      const LoadPathParameters    &settings,
                      const InterfaceParameters   &interfaces)
    {
      const unsigned int n_max =
        std::max(highest_harmonic(list), settings.maximum_harmonic);
      // Exact contact and Newton on a stiff penalty take one sample per
      // value of the gap; the initial-stiffness iteration keeps the general
      // default.
      return interfaces.any_contact() || settings.tangent_stiffness ?
               constrained_theta_samples(n_max, settings.theta_samples) :
               FourierSSI::theta_samples_for(n_max, settings.theta_samples);
    }

    /**
     * A coulomb law stiffer than Newton's cap on K's springs is solved by
     * the augmented Lagrangian (NonlinearInterfacePoints) where the samples
     * are no more than the 2 n_max + 1 values of the band-limited gap (the
     * default): its multipliers settle in a few updates. Where they are more
     * (Theta samples set above that), the extra samples' multipliers at the
     * contact edge move without nodal force and contract by only 1 - r/k an
     * update (the disc at kappa = 1e4 with 132 samples: 50 updates without
     * settling), so Newton iterates on the stiff law itself.
     */
    bool
    augments_stiff_laws(const std::vector<Harmonic> &list,
                        const LoadPathParameters    &settings,
                        const InterfaceParameters   &interfaces)
    {
      const unsigned int n_max =
        std::max(highest_harmonic(list), settings.maximum_harmonic);
      return theta_samples_for(list, settings, interfaces) <=
             minimum_theta_samples(n_max);
    }

    std::string
    name_of(const LoadPathParameters &settings)
    {
      using Kind = LoadPathParameters::Acceleration;
      if (settings.tangent_stiffness)
        return ", Newton (consistent tangent, line search)";
      return settings.acceleration == Kind::anderson ?
               ", Anderson m = " + std::to_string(settings.anderson_depth) :
             settings.acceleration == Kind::aitken ? ", Aitken" :
                                                     ", no acceleration";
    }

    /**
     * Growth: every n <= Maximum harmonic in the families of the set, if
     * that is above the highest harmonic of the set; else none.
     */
    std::vector<Harmonic>
    candidate_harmonics(const std::vector<Harmonic> &list,
                        const unsigned int           maximum_harmonic)
    {
      std::vector<Harmonic> result;
      if (maximum_harmonic <= highest_harmonic(list))
        return result;
      for (const Family family : {Family::symmetric, Family::antisymmetric})
        if (std::any_of(list.begin(), list.end(), [&](const Harmonic &h) {
              return h.family == family;
            }))
          for (unsigned int n = 0; n <= maximum_harmonic; ++n)
            result.push_back({n, family});
      return result;
    }

    bool
    contains(const std::vector<Harmonic> &list, const Harmonic &h)
    {
      return std::any_of(list.begin(), list.end(), [&](const Harmonic &g) {
        return g.n == h.n && g.family == h.family;
      });
    }

    const InterfaceIntegrator &
    interfaces_of(const HarmonicProblem &problem)
    {
      AssertThrow(problem.get_interfaces() != nullptr,
                  ExcMessage(entry + ": the scene has no interfaces"));
      return *problem.get_interfaces();
    }
  } // namespace

  CoupledInterfaceSolver::CoupledInterfaceSolver(
    HarmonicSet         &set,
    const AllParameters &parameters)
    : LoadPathStates(set, parameters)
    , set(set)
    , parameters(parameters)
    , settings(parameters.load_path)
    , harmonics(set.get_harmonics())
    , sampling(harmonics,
               theta_samples_for(harmonics, settings, parameters.interfaces))
    , candidates(candidate_harmonics(harmonics, settings.maximum_harmonic))
    , spectrum(candidates, sampling.n_samples())
    , interface(set,
                parameters,
                augments_stiff_laws(harmonics, settings, parameters.interfaces))
    , points(interface.get_points())
    , pattern_solution(loads.solution)
  {
    check_homogeneous_constraints(entry, "nonlinear interfaces");
    sources.interfaces = &interface;
    solve_loads();
    start_at_rest();
    committed.interface_solution = committed.correction_solution;
    condense(0);
    committed.interfaces = interface.at_rest(sampling);
  }

  void
  CoupledInterfaceSolver::solve_loads()
  {
    loads       = LoadPattern(set);
    cases       = interface.load_cases(loads, sampling);
    held_motion = 0.;
    if (settings.control != LoadPathParameters::Control::displacement)
      return;
    const unsigned int        h      = controlled_harmonic_index();
    const std::vector<double> motion = controlled_motions(
      loads.holds_loads() ?
        std::vector<const Vector<double> *>{&pattern_solution[h],
                                            &loads.held_solution[h]} :
        std::vector<const Vector<double> *>{&pattern_solution[h]});
    pattern_motion = motion[0];
    held_motion    = loads.holds_loads() ? motion[1] : 0.;
    AssertThrow(pattern_motion != 0.,
                ExcMessage(entry + "/Controlled motion: the Rigid foundation "
                                   "loads do not drive this motion (give the "
                                   "load that does, e.g. V for vertical)"));
  }

  bool
  CoupledInterfaceSolver::controls_motion() const
  {
    return settings.control == LoadPathParameters::Control::displacement &&
           !holding_stage;
  }

  std::vector<Vector<double>>
  CoupledInterfaceSolver::interface_force(
    const std::vector<Vector<double>> &fields) const
  {
    return interface.load_of(interface.relative_displacements(fields, sampling),
                             sampling);
  }

  void
  CoupledInterfaceSolver::condense(const unsigned int first)
  {
    const bool displacement_control =
      settings.control == LoadPathParameters::Control::displacement;
    const unsigned int carrier =
      displacement_control ? controlled_harmonic_index() : set.size();
    condensed.resize(set.size());
    // 1. Per harmonic, the DoFs c reaches (write) and the DoFs the relative
    //    displacements read, from the nonlinear pairs.
    std::set<unsigned int> nonlinear_pairs;
    for (const InterfacePoint &point : points)
      nonlinear_pairs.insert(point.pair);
    for (unsigned int h = first; h < set.size(); ++h)
      {
        const AffineConstraints<double> &constraints =
          set.problem(h).get_homogeneous_constraints();
        const auto &pairs = interfaces_of(set.problem(h)).get_pairs();
        std::set<types::global_dof_index> write, read;
        for (const unsigned int i : nonlinear_pairs)
          for (const types::global_dof_index d : pairs[i].dof_indices)
            {
              read.insert(d);
              if (!constraints.is_constrained(d))
                write.insert(d);
              else if (const auto *entries =
                         constraints.get_constraint_entries(d))
                for (const auto &entry : *entries)
                  write.insert(entry.first);
            }
        condensed[h].write.assign(write.begin(), write.end());
        condensed[h].read.assign(read.begin(), read.end());
        if (set.owns(h))
          condensed[h].flexibility.reinit(read.size(), write.size());
        condensed[h].controlled_motion.assign(write.size(), 0.);
      }
    // 2. K^-1 e_j for every write DoF j, in batches (memory), every
    //    harmonic this rank owns concurrently with the kept factorizations.
    //    The number of batches is the same on every rank (solve_increments
    //    is collective when the harmonics are distributed).
    std::size_t n_write = 0;
    for (unsigned int h = first; h < set.size(); ++h)
      n_write = std::max(n_write, condensed[h].write.size());
    const unsigned int batch = 64;
    for (unsigned int start = 0; start < n_write; start += batch)
      {
        std::vector<std::vector<Vector<double>>> x(set.size());
        for (unsigned int h = first; h < set.size(); ++h)
          if (set.owns(h))
            for (unsigned int j = start;
                 j < std::min<std::size_t>(start + batch,
                                           condensed[h].write.size());
                 ++j)
              {
                x[h].emplace_back(pattern_solution[h].size());
                x[h].back()(condensed[h].write[j]) = 1.;
              }
        set.solve_increments(x);
        for (unsigned int h = first; h < set.size(); ++h)
          for (unsigned int k = 0; k < x[h].size(); ++k)
            {
              Condensation &c = condensed[h];
              for (unsigned int i = 0; i < c.read.size(); ++i)
                c.flexibility(i, start + k) = x[h][k](c.read[i]);
              if (h == carrier)
                c.controlled_motion[start + k] = controlled_motion_of(x[h][k]);
            }
      }
    // 3. The controlled motion of every column on every rank (the owner's,
    //    zeros elsewhere: an exact sum): the iteration updates the motion
    //    (and so lambda) redundantly.
    if (carrier >= first && carrier < set.size())
      set.sum_over_ranks(condensed[carrier].controlled_motion);
  }

  std::vector<Vector<double>>
  CoupledInterfaceSolver::on_write_dofs(
    const std::vector<Vector<double>> &full) const
  {
    std::vector<Vector<double>> result(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const Condensation &c = condensed[h];
        result[h].reinit(c.write.size());
        for (unsigned int j = 0; j < c.write.size(); ++j)
          result[h](j) = full[h](c.write[j]);
      }
    return result;
  }

  void
  CoupledInterfaceSolver::add_correction(
    const std::vector<Vector<double>> &dc_write,
    StepState                         &state) const
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const Condensation &c = condensed[h];
        if (set.owns(h))
          {
            Vector<double> dv_read(c.read.size());
            c.flexibility.vmult(dv_read, dc_write[h]);
            for (unsigned int i = 0; i < c.read.size(); ++i)
              state.interface_solution[h](c.read[i]) += dv_read(i);
          }
        for (unsigned int j = 0; j < c.write.size(); ++j)
          {
            state.correction_load[h](c.write[j]) += dc_write[h](j);
            state.controlled_motion += c.controlled_motion[j] * dc_write[h](j);
          }
      }
  }

  void
  CoupledInterfaceSolver::complete(StepState &state) const
  {
    std::vector<std::vector<Vector<double>>> x(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.owns(h))
        x[h] = {state.correction_load[h]};
    set.solve_increments(x);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.owns(h))
        state.correction_solution[h] = x[h][0];
    // Restart the next step's condensed view from the exact field (no
    // accumulation of round-off over the steps).
    state.interface_solution = state.correction_solution;
    if (settings.control == LoadPathParameters::Control::displacement)
      state.controlled_motion = controlled_motions(
        {&state.correction_solution[controlled_harmonic_index()]})[0];
  }

  void
  CoupledInterfaceSolver::extrapolate(const StepState &before_last,
                                      const double     ratio,
                                      StepState       &state) const
  {
    LoadPathStates::extrapolate(before_last, ratio, state);
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        state.interface_solution[h].add(ratio, committed.interface_solution[h]);
        state.interface_solution[h].add(-ratio,
                                        before_last.interface_solution[h]);
      }
    state.controlled_motion +=
      ratio * (committed.controlled_motion - before_last.controlled_motion);
  }

  CoupledInterfaceSolver::Evaluation
  CoupledInterfaceSolver::evaluate(const double target, StepState &state) const
  {
    // The held stage brings rho to its target at lambda = 0; then rho stays
    // and lambda follows the load or displacement control (the held loads'
    // motion is part of the controlled one).
    if (holding_stage)
      state.held_fraction = target;
    else
      state.load_factor = controls_motion() ?
                            (target - state.controlled_motion -
                             state.held_fraction * held_motion) /
                              pattern_motion :
                            target;
    Evaluation e;
    // 1-2: relative displacements at every (point, theta), the law.
    e.relative = interface.iterate_relative(state.interface_solution,
                                            sampling,
                                            cases,
                                            state.load_factor,
                                            state.held_fraction);
    e.counts   = interface.return_map(
      e.relative, state.interfaces.origin, e.plastic, e.traction, e.contact);
    // 3-4: out-of-balance load G = int B^T (D_K d - (t - t0)) (D_K the
    //      springs in K) and force residual R = G - c, measured against
    //      the internal force scale (coupled_iteration.h).
    e.residual = interface.load_of(
      interface.iteration_plastic(e.relative, e.traction, e.plastic), sampling);
    e.scale = {loads.applied_norm(state.load_factor, state.held_fraction),
               norm_over_harmonics(e.residual)};
    for (unsigned int h = 0; h < set.size(); ++h)
      e.residual[h] -= state.correction_load[h];
    e.residual_norm = norm_over_harmonics(e.residual);
    return e;
  }

  void
  CoupledInterfaceSolver::accept(Evaluation        &e,
                                 const unsigned int iteration,
                                 StepState         &state,
                                 LoadStepResult    &result) const
  {
    complete(state);
    interface.commit(e.relative,
                     e.traction,
                     std::move(e.plastic),
                     state.interfaces);
    result.iterations      = iteration;
    result.residual        = e.scale.relative(e.residual_norm);
    result.contact         = e.counts;
    result.interface_state = {std::move(e.relative),
                              std::move(e.traction),
                              std::move(e.contact)};
  }

  bool
  CoupledInterfaceSolver::iterate(const double  target,
                                  StepState    &state,
                                  Evaluation   &e,
                                  unsigned int &iterations) const
  {
    FixedPointAcceleration acceleration(settings.acceleration,
                                        settings.anderson_depth);
    // The globalisation (safeguarded_newton.h): up to 4 full steps may go on
    // without a new best |R| (a gap that closes or a slip that reverses
    // beyond the tangent's foresight is put right by the next tangent),
    // then the line search from the best iterate halves down to 2^-16; its
    // iterations are cheap (condensed), so no step is given up early.
    const auto evaluate_iterate = [&](StepState &iterate) {
      return evaluate(target, iterate);
    };
    using Newton = SafeguardedNewton<StepState, Evaluation, Vector<double>>;
    Newton newton(
      Newton::Settings{4,
                       1. / 65536.,
                       std::numeric_limits<unsigned int>::max()},
      evaluate_iterate,
      [&](const Evaluation &at, const StepState &iterate) {
        return newton_direction(at, iterate);
      },
      [&](const double alpha, const Vector<double> &dc, StepState &iterate) {
        add_scaled_correction(alpha, dc, iterate);
      });
    const auto balanced = [&](StepState &iterate, Evaluation &at) {
      if (!at.scale.converged(at.residual_norm, settings.tolerance))
        return false;
      if (!settings.tangent_stiffness)
        return true;
      // Newton: the iterate from the full solve K^-1 c, checked again
      // (iterative refinement of the flexibility blocks' round-off).
      complete(iterate);
      at = evaluate(target, iterate);
      return at.scale.converged(at.residual_norm, settings.tolerance);
    };
    // 5: c <- c + dc and v <- v + K^-1 dc at the interface (section 5,
    //    condensed: exact, without a re-solve). c and R live on the write
    //    DoFs: the acceleration works there.
    const auto initial_stiffness_update = [&](StepState        &iterate,
                                              const Evaluation &at) {
      add_correction(acceleration.increment(on_write_dofs(
                                              iterate.correction_load),
                                            on_write_dofs(at.residual)),
                     iterate);
    };
    // Where no step along the Newton direction lowers |R| (a kink of the
    // return mapping right at the iterate), one initial-stiffness update
    // (exact and cheap, condensed) moves off it.
    e = evaluate(target, state);
    return iterate_to_balance(
      settings.tangent_stiffness ? &newton : nullptr,
      state,
      e,
      evaluate_iterate,
      balanced,
      initial_stiffness_update,
      []() { return NoDescent::initial_stiffness_update; },
      settings.maximum_iterations,
      iterations);
  }

  bool
  CoupledInterfaceSolver::solve_step(const double    target,
                                     StepState      &state,
                                     LoadStepResult &result)
  {
    Evaluation   e;
    unsigned int iterations = 0;
    // Augmented Lagrangian (section 5d) with contact interfaces.
    const bool converged = interface.iterate_with_multipliers(
      [&]() { return iterate(target, state, e, iterations); },
      e.traction,
      sampling,
      [&]() { return settings.tolerance * e.scale.largest(); },
      state.interfaces,
      result.multiplier_updates);
    if (converged)
      accept(e, iterations, state, result);
    return converged;
  }

  std::vector<Harmonic>
  CoupledInterfaceSolver::harmonics_called_for(
    const InterfaceSnapshot &snapshot,
    std::ostream            &log) const
  {
    std::vector<Harmonic> added;
    if (candidates.empty())
      return added;
    // 1. The spectrum of t - t0: per candidate harmonic, the amplitudes of
    //    the three components at every point, squared and weighted by the
    //    point's area (an L2 norm over the interface of that harmonic).
    const unsigned int  N = sampling.n_samples();
    std::vector<double> norm_sqr(candidates.size(), 0.), samples(N), amplitude;
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int c = 0; c < 3; ++c)
        {
          for (unsigned int j = 0; j < N; ++j)
            samples[j] =
              snapshot.traction[i * N + j][c] - points[i].initial_traction[c];
          spectrum.project(samples,
                           c == 2 ? ThetaFactor::circumferential :
                                    ThetaFactor::in_plane,
                           amplitude);
          for (unsigned int h = 0; h < candidates.size(); ++h)
            norm_sqr[h] +=
              points[i].area_per_radian * amplitude[h] * amplitude[h];
        }
    // 2. Harmonics not solved whose amplitude has not decayed below the
    //    tolerance relative to the largest one.
    const double largest =
      std::sqrt(*std::max_element(norm_sqr.begin(), norm_sqr.end()));
    std::ostringstream why;
    for (unsigned int h = 0; h < candidates.size(); ++h)
      {
        const double relative =
          largest > 0. ? std::sqrt(norm_sqr[h]) / largest : 0.;
        if (contains(harmonics, candidates[h]) ||
            relative <= settings.harmonic_tolerance)
          continue;
        added.push_back(candidates[h]);
        why << ' ' << candidates[h].name() << " (" << std::setprecision(3)
            << relative << ')';
      }
    if (!added.empty())
      log << "  harmonics added, interface-traction amplitude relative to "
             "the largest above "
          << settings.harmonic_tolerance << ":" << why.str()
          << "; the step is solved again\n";
    return added;
  }

  void
  CoupledInterfaceSolver::grow(const std::vector<Harmonic> &added)
  {
    set.add(added);
    harmonics = set.get_harmonics();
    sampling  = ThetaSampling(harmonics, sampling.n_samples());
    solve_loads();
    const unsigned int first = committed.correction_solution.size();
    for (unsigned int h = first; h < set.size(); ++h)
      {
        committed.correction_solution.emplace_back(pattern_solution[h].size());
        committed.correction_load.emplace_back(pattern_solution[h].size());
        committed.interface_solution.emplace_back(pattern_solution[h].size());
      }
    condense(first);
  }

  void
  CoupledInterfaceSolver::run(std::ostream &log)
  {
    const bool load_control =
      settings.control == LoadPathParameters::Control::load;
    log << "nonlinear interfaces: " << points.size() << " points x "
        << sampling.n_samples() << " theta samples, " << set.size()
        << " harmonics";
    if (set.n_owning_ranks() > 1)
      log << " distributed over " << set.n_owning_ranks() << " MPI ranks";
    log << ", " << (load_control ? "load" : "displacement") << " control, "
        << settings.load_steps << " steps, tolerance " << settings.tolerance
        << name_of(settings);
    if (!candidates.empty())
      log << ", harmonics grow up to n = " << settings.maximum_harmonic
          << " where the interface traction calls for them (tolerance "
          << settings.harmonic_tolerance << ")";
    log << '\n';
    interface.describe(log, sampling.n_samples(), highest_harmonic(harmonics));
    write_held_motions(log, "");
    if (interface.without_strength())
      log << "warning: " << entry
          << ": a coulomb interface has c = 0 and no Initial stress: it has "
             "no strength\n";
    LoadPath(settings, entry, *this).run(log);
    if (set.n_owning_ranks() > 1)
      log << "  MPI: " << set.n_rank_sums() << " sums over the ranks ("
          << "one per iteration, a few per step), " << set.rank_sum_time()
          << " s in them on rank 0 (computing or waiting for the others)\n";
  }

  bool
  CoupledInterfaceSolver::solve_trial(const double target, const bool holding)
  {
    holding_stage = holding;
    trial_result  = LoadStepResult();
    return solve_step(target, trial, trial_result);
  }

  bool
  CoupledInterfaceSolver::grows(std::ostream &log)
  {
    const std::vector<Harmonic> added =
      harmonics_called_for(trial_result.interface_state, log);
    if (added.empty())
      return false;
    grow(added);
    return true;
  }

  void
  CoupledInterfaceSolver::commit_trial(const LoadStep &step,
                                       const bool      holding,
                                       std::ostream   &log)
  {
    commit(step);
    record_interfaces(interface, sampling);
    const InterfaceSnapshot &state = trial_result.interface_state;
    // The interfaces are the only nonlinear source: their part of G is that
    // of the tractions they carry.
    if (!parameters.rigid_foundation.reported_motions().empty())
      trial_result.held_reactions = held_reactions_of(
        committed,
        interface.load_of(interface.spring_plastic(state), sampling, false));
    record_trial(holding, log);
  }
} // namespace FourierSSI
