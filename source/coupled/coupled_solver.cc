#include <algorithm>
#include <chrono>
#include <cmath>
#include <fourier_ssi/coupled/balance_iteration.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/coupled/load_pattern.h>
#include <fourier_ssi/coupled/safeguarded_newton.h>

namespace FourierSSI
{
  namespace
  {
    /**
     * The acceleration of the out-of-balance iteration: Newton updates on
     * the coupled tangent are taken as they are (relaxing them by Aitken or
     * Anderson was measured to double the iterations, doc/soil-plasticity.md
     * section 3); the initial-stiffness iteration, and the condensed one's
     * updates where Newton finds no descent, take Load path/Acceleration.
     */
    LoadPathParameters::Acceleration
    acceleration_of(const LoadPathParameters &settings,
                    const bool                condensed,
                    const bool                newton)
    {
      return newton && !condensed ? LoadPathParameters::Acceleration::none :
                                    settings.acceleration;
    }

    /** How the log names the iteration. */
    std::string
    iteration_name(const LoadPathParameters &settings,
                   const bool                condensed,
                   const bool                newton)
    {
      using Acceleration = LoadPathParameters::Acceleration;
      if (condensed)
        return newton ?
                 "Newton (consistent tangent, line search)" :
               settings.acceleration == Acceleration::anderson ?
                 "Anderson m = " + std::to_string(settings.anderson_depth) :
               settings.acceleration == Acceleration::aitken ?
                 "Aitken" :
                 "no acceleration";
      if (newton)
        return "Newton on the coupled tangent, backtracking";
      return settings.acceleration == Acceleration::aitken ?
               "initial stiffness, Aitken" :
             settings.acceleration == Acceleration::anderson ?
               "initial stiffness, Anderson" :
               "initial stiffness";
    }

    /**
     * The interfaces' theta samples without soil. With growth n_max is
     * Maximum harmonic, so that the samples (and the state kept at them)
     * stay valid when harmonics are added. Exact contact and Newton on a
     * stiff penalty take one sample per value of the gap; the
     * initial-stiffness iteration keeps the general default.
     */
    unsigned int
    interface_theta_samples(const std::vector<Harmonic> &list,
                            const LoadPathParameters    &settings,
                            const InterfaceParameters   &interfaces)
    {
      const unsigned int n_max =
        std::max(highest_harmonic(list), settings.maximum_harmonic);
      return interfaces.any_contact() || settings.tangent_stiffness ?
               constrained_theta_samples(n_max, settings.theta_samples) :
               theta_samples_for(n_max, settings.theta_samples);
    }

    /**
     * Without soil, a coulomb law stiffer than Newton's cap on K's springs
     * is solved by the augmented Lagrangian (NonlinearInterfacePoints) where
     * the samples are no more than the 2 n_max + 1 values of the
     * band-limited gap (the default): its multipliers settle in a few
     * updates. Where they are more (Theta samples set above that), the
     * extra samples' multipliers at the contact edge move without nodal
     * force and contract by only 1 - r/k an update (the disc at kappa = 1e4
     * with 132 samples: 50 updates without settling), so Newton iterates on
     * the stiff law itself. With soil, the coupled tangent always augments
     * them (its interface samples are 2 n_max + 1 then,
     * holds_gaps_by_multipliers).
     */
    bool
    augments_stiff_laws(const bool                   condensed,
                        const std::vector<Harmonic> &list,
                        const LoadPathParameters    &settings,
                        const InterfaceParameters   &interfaces)
    {
      if (!condensed)
        return true;
      const unsigned int n_max =
        std::max(highest_harmonic(list), settings.maximum_harmonic);
      return interface_theta_samples(list, settings, interfaces) <=
             minimum_theta_samples(n_max);
    }

    /**
     * Growth (interfaces only): every n <= Maximum harmonic in the families
     * of the set, if that is above the highest harmonic of the set; else
     * none.
     */
    std::vector<Harmonic>
    candidate_harmonics(const bool                   condensed,
                        const std::vector<Harmonic> &list,
                        const unsigned int           maximum_harmonic)
    {
      std::vector<Harmonic> result;
      if (!condensed || maximum_harmonic <= highest_harmonic(list))
        return result;
      for (const Family family : {Family::symmetric, Family::antisymmetric})
        if (std::any_of(list.begin(), list.end(), [&](const Harmonic &h) {
              return h.family == family;
            }))
          for (unsigned int n = 0; n <= maximum_harmonic; ++n)
            result.push_back({n, family});
      return result;
    }

    /** Zero fields, one per harmonic of the set. */
    std::vector<Vector<double>>
    zero_fields(const HarmonicSet &set)
    {
      std::vector<Vector<double>> fields(set.size());
      for (unsigned int h = 0; h < set.size(); ++h)
        fields[h].reinit(set.problem(h).get_dof_handler().n_dofs());
      return fields;
    }

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

    /**
     * Some nonlinear interface holds faces that can open by multipliers
     * (NonlinearInterfacePoints::augments: `contact`, or a coulomb law with
     * a tension cut-off above Newton's cap). Its samples are then
     * 2 n_max + 1, one per value of the band-limited gap (more ask it to
     * vanish where it has no values, and the multipliers at the contact
     * edge drift; constrained_theta_samples()).
     */
    bool
    holds_gaps_by_multipliers(const HarmonicSet   &set,
                              const AllParameters &parameters)
    {
      const InterfaceIntegrator *interfaces = set.problem(0).get_interfaces();
      if (interfaces == nullptr || !parameters.interfaces.any_nonlinear())
        return false;
      const std::vector<InterfacePair> &pairs = interfaces->get_pairs();
      for (unsigned int i = 0; i < pairs.size(); ++i)
        {
          const InterfaceLaw &law =
            parameters.interfaces.laws.at(pairs[i].boundary_id);
          if (law.can_open() && NonlinearInterfacePoints::augments(
                                  law,
                                  interfaces->get_law_stiffness()[i],
                                  interfaces->get_stiffness()[i],
                                  true))
            return true;
        }
      return false;
    }

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

  CoupledSolver::CoupledSolver(HarmonicSet         &set,
                               const AllParameters &parameters)
    : LoadPathStates(set, parameters)
    , set(set)
    , parameters(parameters)
    , settings(parameters.load_path)
    , condensed(!parameters.linearises_on_coupled_tangent())
    , newton(parameters.newton_on_load_path())
    , entry(condensed ? "Load path" : "Soil plasticity")
    , harmonics(set.get_harmonics())
    , sampling(harmonics,
               condensed ? interface_theta_samples(harmonics,
                                                   settings,
                                                   parameters.interfaces) :
                           theta_samples_for(highest_harmonic(harmonics),
                                             settings.theta_samples))
    , candidates(
        candidate_harmonics(condensed, harmonics, settings.maximum_harmonic))
    , spectrum(candidates, sampling.n_samples())
    , interface_sampling(harmonics,
                         !condensed &&
                             holds_gaps_by_multipliers(set, parameters) ?
                           minimum_theta_samples(highest_harmonic(harmonics)) :
                           sampling.n_samples())
    , soil(set, parameters, sampling)
  {
    check_homogeneous_constraints(entry,
                                  condensed ? "nonlinear interfaces" :
                                              "plastic soil");
    if (parameters.interfaces.any_nonlinear())
      interface = std::make_unique<NonlinearInterfacePoints>(
        set,
        parameters,
        augments_stiff_laws(
          condensed, harmonics, settings, parameters.interfaces));
    sources = {soil.size() > 0, interface.get()};
    solve_loads();
    start_at_rest();
    committed.plastic.assign(soil.size() * sampling.n_samples(),
                             {{0., 0., 0., 0., 0., 0.}});
    if (interface)
      committed.interfaces = interface->at_rest(interface_sampling);
    if (condensed)
      condensation = std::make_unique<InterfaceCondensation>(
        set,
        *interface,
        settings.control == LoadPathParameters::Control::displacement ?
          controlled_harmonic_index() :
          set.size(),
        [this](const Vector<double> &v) { return controlled_motion_of(v); });
  }

  void
  CoupledSolver::solve_loads()
  {
    loads = LoadPattern(set);
    if (loads.holds_loads() && parameters.rigid_foundation.swipes())
      loads.add_swipe_pattern(set);
    if (soil.size() > 0)
      {
        pattern_strain = soil.strain_amplitudes(loads.solution);
        if (loads.holds_loads())
          held_strain = soil.strain_amplitudes(loads.held_solution);
        if (!loads.swipe_solution.empty())
          swipe_strain = soil.strain_amplitudes(loads.swipe_solution);
      }
    // A swipe's multipliers read the rigid motions of u_F and u_V at every
    // iterate: constants of the run.
    if (!loads.swipe_solution.empty())
      {
        pattern_rigid_motion = motion_of_fields(set, loads.solution);
        swipe_rigid_motion   = motion_of_fields(set, loads.swipe_solution);
      }
    if (interface)
      interface_cases = interface->load_cases(loads, interface_sampling);
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
    pattern_motion = motion[0];
    held_motion    = loads.holds_loads() ? motion[1] : 0.;
    AssertThrow(pattern_motion != 0.,
                ExcMessage("Load path/Controlled motion: the Rigid foundation "
                           "loads do not drive this motion (give the load "
                           "that does, e.g. V for vertical)"));
  }

  double
  CoupledSolver::applied_load_norm(const StepState &state) const
  {
    return loads.applied_norm(state.load_factor, state.held_fraction);
  }

  std::vector<StrainVector>
  CoupledSolver::strain_samples(const std::vector<Vector<double>> &correction,
                                const double                       load_factor,
                                const double held_fraction,
                                const double swipe_force) const
  {
    const StrainAmplitudes amplitude = soil.strain_amplitudes(correction);
    return soil.strain_samples({{1., &amplitude},
                                {load_factor, &pattern_strain},
                                {held_fraction, &held_strain},
                                {swipe_force, &swipe_strain}});
  }

  std::vector<Vector<double>>
  CoupledSolver::soil_nodal_force(
    const std::function<bool(const Point<2> &)> &selected) const
  {
    return soil.nodal_force(strain_samples(committed.correction_solution,
                                           committed.load_factor,
                                           committed.held_fraction),
                            committed.plastic,
                            selected);
  }

  std::vector<Vector<double>>
  CoupledSolver::soil_force(const std::vector<Vector<double>> &fields) const
  {
    return soil.elastic_force(fields);
  }

  std::vector<Vector<double>>
  CoupledSolver::out_of_balance_load(const std::vector<Vector<double>> &fields)
  {
    std::vector<StrainVector> plastic;
    soil.return_map(strain_samples(fields, 0., 0.), committed.plastic, plastic);
    Evaluation e;
    e.residual = soil.load_of(plastic);
    if (interface)
      {
        // The fields as K^-1 c of a state without loads, from the committed
        // interface state.
        StepState at;
        at.correction_solution = fields;
        at.interfaces          = committed.interfaces;
        add_interface_residual(at, e);
      }
    return e.residual;
  }

  std::vector<Vector<double>>
  CoupledSolver::interface_force(
    const std::vector<Vector<double>> &fields) const
  {
    AssertThrow(interface != nullptr,
                ExcMessage(entry + ": the scene has no nonlinear interface"));
    return interface->load_of(
      interface->relative_displacements(fields, interface_sampling),
      interface_sampling);
  }

  std::vector<Vector<double>>
  CoupledSolver::tangent_product(const std::vector<Vector<double>> &fields,
                                 const std::vector<Vector<double>> &x)
  {
    update_tangent(strain_samples(fields, 0., 0.),
                   interface ?
                     interface->iterate_relative(
                       fields, interface_sampling, interface_cases, 0., 0.) :
                     std::vector<LocalVector>(),
                   committed.interfaces.origin);
    std::vector<Vector<double>> y;
    tangent->vmult(y, x);
    return y;
  }

  double
  CoupledSolver::controlled_load_factor(const StepState &state,
                                        const double     target) const
  {
    // Condensed, K^-1 c is not whole while a step iterates: its motion is
    // kept with c (InterfaceCondensation::add).
    const double correction_motion =
      condensed ?
        state.controlled_motion :
        controlled_motions(
          {&state.correction_solution[controlled_harmonic_index()]})[0];
    const double now = correction_motion + state.held_fraction * held_motion;
    return (target - now) / pattern_motion;
  }

  std::array<double, 2>
  CoupledSolver::swipe_multipliers(const RigidMotion &now,
                                   const RigidMotion &by_pattern,
                                   const RigidMotion &by_swipe,
                                   const double       target,
                                   const double       settlement,
                                   const bool displacement_control) const
  {
    const auto m = [this](const RigidMotion &motion) {
      return controlled_component(motion, settings.motion);
    };
    // Row 1: the controlled motion (or lambda itself), row 2: w.
    const double a   = displacement_control ? m(by_pattern) : 1.,
                 b   = displacement_control ? m(by_swipe) : 0.,
                 e   = displacement_control ? target - m(now) : target;
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

  void
  CoupledSolver::set_swipe_multipliers(StepState   &state,
                                       const double target,
                                       const bool   displacement_control) const
  {
    // The state without lambda and mu: K^-1 c + rho u_held.
    const RigidMotion now = rigid_motion_of(set, [&](const unsigned int h) {
      return loads.total_displacement(h,
                                      0.,
                                      state.correction_solution[h],
                                      state.held_fraction);
    });
    const auto [load_factor, swipe_force] =
      swipe_multipliers(now,
                        pattern_rigid_motion,
                        swipe_rigid_motion,
                        target,
                        swipe_settlement,
                        displacement_control);
    state.load_factor = load_factor;
    state.swipe_force = swipe_force;
  }

  void
  CoupledSolver::make_tangent()
  {
    std::vector<std::vector<std::vector<types::global_dof_index>>> dofs =
      soil.cell_dofs();
    // The coulomb interfaces' pairs couple the harmonics too.
    if (interface)
      for (auto &pair : interface->pair_dofs())
        dofs.push_back(std::move(pair));
    tangent = std::make_unique<CoupledTangent>(set, dofs);
  }

  void
  CoupledSolver::update_tangent(
    const std::vector<StrainVector> &strain,
    const std::vector<LocalVector>  &relative,
    const std::vector<LocalVector>  &interface_origin,
    const bool                       displacement_control)
  {
    const unsigned int H = set.size();
    // K_t = diag(K_h) - the soil's softening at the points that yield -
    // the interfaces' at the samples that slip or open.
    if (!tangent)
      make_tangent();
    tangent->reset_to_elastic();
    soil.add_softening(strain, committed.plastic, *tangent);
    if (interface)
      interface->add_softening(relative,
                               interface_origin,
                               interface_sampling,
                               *tangent);
    if (displacement_control)
      add_control_stiffening();
    tangent->factorize();
    tangent_pattern.resize(H);
    for (unsigned int h = 0; h < H; ++h)
      tangent_pattern[h] = loads.load[h];
    // F_h is on h's owner only (LoadPattern); the solve takes all of F.
    sum_fields_over_ranks(set, tangent_pattern);
    tangent->solve(tangent_pattern);
  }

  void
  CoupledSolver::add_control_stiffening()
  {
    stiffen_motion(controlled_harmonic(settings.motion),
                   [this](const RigidMotion &m) {
                     return controlled_component(m, settings.motion);
                   });
    if (swiping)
      stiffen_motion({0, Family::symmetric}, [](const RigidMotion &m) {
        return m.vertical_displacement;
      });
  }

  void
  CoupledSolver::stiffen_motion(
    const Harmonic                                   &wanted,
    const std::function<double(const RigidMotion &)> &component)
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      if (harmonics[h].n == wanted.n && harmonics[h].family == wanted.family)
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
              c[k]             = component(foundation->motion(unit));
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
  CoupledSolver::tangent_correction(const std::vector<Vector<double>> &residual,
                                    const bool displacement_control) const
  {
    std::vector<Vector<double>> du = residual;
    tangent->solve(du);
    double load_change = 0., swipe_change = 0.;
    // A swipe: K_t^-1 e_V (one more solve with the factorization).
    std::vector<Vector<double>> swipe_pattern;
    if (swiping)
      {
        // e_V is on the owner of harmonic 0 only; the solve takes all of it.
        swipe_pattern = loads.swipe_load;
        sum_fields_over_ranks(set, swipe_pattern);
        tangent->solve(swipe_pattern);
        // The iterate holds both motions already: du must keep them.
        const std::array<double, 2> changes =
          swipe_multipliers(motion_of_fields(set, du),
                            motion_of_fields(set, tangent_pattern),
                            motion_of_fields(set, swipe_pattern),
                            0.,
                            0.,
                            displacement_control);
        load_change  = changes[0];
        swipe_change = changes[1];
      }
    else if (displacement_control)
      {
        // K_t^-1 F and du are whole on every rank (the tangent's solve).
        const unsigned int h    = controlled_harmonic_index();
        const double by_pattern = controlled_motion_of(tangent_pattern[h]);
        if (by_pattern != 0.)
          load_change = -controlled_motion_of(du[h]) / by_pattern;
      }
    std::vector<Vector<double>> change(set.size());
    set.for_each([&](const unsigned int h) {
      change[h].reinit(du[h].size());
      if (!set.owns(h))
        return; // K_h is on its owner only
      du[h].add(load_change, tangent_pattern[h]);
      if (swiping)
        du[h].add(swipe_change, swipe_pattern[h]);
      set.problem(h).get_system_matrix().vmult(change[h], du[h]);
      change[h].add(-load_change, loads.load[h]);
      if (swiping)
        change[h].add(-swipe_change, loads.swipe_load[h]);
      set.problem(h).get_homogeneous_constraints().set_zero(change[h]);
    });
    sum_fields_over_ranks(set, change);
    return change;
  }

  CoupledSolver::Evaluation
  CoupledSolver::evaluate(const StepState &state, LoadStepResult &result) const
  {
    Evaluation e;
    if (soil.size() > 0)
      {
        // 1-2: strains at every (point, theta), the return mapping.
        e.strain = strain_samples(state.correction_solution,
                                  state.load_factor,
                                  state.held_fraction,
                                  state.swipe_force);
        static_cast<SoilYieldCounts &>(result) =
          soil.return_map(e.strain, committed.plastic, e.plastic);
        // 3: the soil's out-of-balance load.
        e.residual = soil.load_of(e.plastic);
      }
    // 1-3 of the nonlinear interfaces: theirs added (one c for both
    // sources); 4: the force residual R = G - c.
    const double interface_load_norm =
      interface ? add_interface_residual(state, e) : 0.;
    for (unsigned int h = 0; h < set.size(); ++h)
      e.residual[h] -= state.correction_load[h];
    e.residual_norm = norm_over_harmonics(e.residual);
    // The scale is |lambda F| and the interfaces' G (kn times a gap, the
    // internal force of a stiff penalty), never the soil's G: that is D
    // times the plastic strain, which grows without bound when the soil
    // collapses, and would pass a residual of any size.
    e.scale = {applied_load_norm(state), interface_load_norm};
    return e;
  }

  double
  CoupledSolver::add_interface_residual(const StepState &state,
                                        Evaluation      &e) const
  {
    e.relative = interface->iterate_relative(state.correction_solution,
                                             interface_sampling,
                                             interface_cases,
                                             state.load_factor,
                                             state.held_fraction,
                                             state.swipe_force);
    e.counts   = interface->return_map(e.relative,
                                     state.interfaces.origin,
                                     e.interface_plastic,
                                     e.traction,
                                     e.contact);
    // G = int B^T (D_K d - (t - t0)), D_K the springs in K.
    std::vector<Vector<double>> interface_load = interface->load_of(
      interface->iteration_plastic(e.relative, e.traction, e.interface_plastic),
      interface_sampling);
    const double norm = norm_over_harmonics(interface_load);
    // Without soil the interfaces' load is the whole G.
    if (e.residual.empty())
      e.residual = std::move(interface_load);
    else
      for (unsigned int h = 0; h < set.size(); ++h)
        e.residual[h] += interface_load[h];
    return norm;
  }

  void
  CoupledSolver::accept(Evaluation        &e,
                        const unsigned int iteration,
                        StepState         &state,
                        LoadStepResult    &result) const
  {
    // Condensed Newton's force test completed K^-1 c already (iterate()).
    if (condensed && !newton)
      complete(state);
    if (soil.size() > 0)
      soil.count_over_ranks(result);
    state.plastic = std::move(e.plastic);
    if (interface)
      {
        interface->commit(e.relative,
                          e.traction,
                          std::move(e.interface_plastic),
                          state.interfaces);
        result.contact         = e.counts;
        result.interface_state = {std::move(e.relative),
                                  std::move(e.traction),
                                  std::move(e.contact)};
      }
    result.iterations = iteration;
    result.residual   = e.scale.relative(e.residual_norm);
  }

  CoupledSolver::Correction
  CoupledSolver::newton_correction(const Evaluation &e,
                                   const StepState  &state,
                                   const bool        displacement_control)
  {
    if (condensed)
      return {condensation->newton_update(e.relative,
                                          state.interfaces.origin,
                                          e.residual,
                                          interface_sampling,
                                          displacement_control,
                                          pattern_motion,
                                          interface_cases.pattern),
              {}};
    // Rebuilt at every update: keeping it for 3-10 updates (modified
    // Newton) was measured slower (doc/soil-plasticity.md 3b).
    update_tangent(e.strain,
                   e.relative,
                   state.interfaces.origin,
                   displacement_control);
    return correction_of(tangent_correction(e.residual, displacement_control));
  }

  CoupledSolver::Correction
  CoupledSolver::correction_of(std::vector<Vector<double>> load) const
  {
    std::vector<std::vector<Vector<double>>> increment(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      increment[h] = {load[h]};
    set.solve_increments(increment);
    Correction correction;
    correction.load = std::move(load);
    for (unsigned int h = 0; h < set.size(); ++h)
      correction.solution.push_back(std::move(increment[h][0]));
    return correction;
  }

  CoupledSolver::Correction
  CoupledSolver::initial_stiffness_correction(
    FixedPointAcceleration &acceleration,
    const StepState        &state,
    const Evaluation       &e) const
  {
    // Condensed, c and R live on the write DoFs: the acceleration works
    // there, and K^-1 dc follows through the flexibility blocks.
    if (condensed)
      return {acceleration.increment(condensation->on_write_dofs(
                                       state.correction_load),
                                     condensation->on_write_dofs(e.residual)),
              {}};
    return correction_of(
      acceleration.increment(state.correction_load, e.residual));
  }

  void
  CoupledSolver::add_correction(const double      alpha,
                                const Correction &correction,
                                StepState        &state) const
  {
    if (condensed)
      {
        std::vector<Vector<double>> step = correction.load;
        for (Vector<double> &v : step)
          v *= alpha;
        condensation->add(step,
                          state.correction_load,
                          state.correction_solution,
                          state.controlled_motion);
        return;
      }
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        state.correction_load[h].add(alpha, correction.load[h]);
        // A harmonic's displacement is on its owner only.
        if (set.owns(h))
          state.correction_solution[h].add(alpha, correction.solution[h]);
      }
  }

  bool
  CoupledSolver::solve_step(const double    target,
                            const bool      holding,
                            StepState      &state,
                            LoadStepResult &result)
  {
    // Holding: the held loads come on at a fixed load factor.
    if (holding)
      state.held_fraction = target;
    // A swipe holds w from the end of the held stage on.
    swiping = !holding && parameters.rigid_foundation.swipes();
    Evaluation   e;
    unsigned int iterations = 0;
    const auto   converge   = [&]() {
      return iterate(target, holding, state, result, e, iterations);
    };
    // With augmented interfaces the multipliers move between converged
    // iterations (augmented Lagrangian).
    const bool converged =
      interface ? interface->iterate_with_multipliers(
                    converge,
                    e.traction,
                    interface_sampling,
                    [&]() { return settings.tolerance * e.scale.largest(); },
                    state.interfaces,
                    result.multiplier_updates) :
                  converge();
    if (converged)
      accept(e, iterations, state, result);
    return converged;
  }

  CoupledSolver::Evaluation
  CoupledSolver::evaluate_at(const double    target,
                             const bool      holding,
                             StepState      &state,
                             LoadStepResult &result)
  {
    const bool displacement_control =
      !holding && settings.control == LoadPathParameters::Control::displacement;
    if (swiping)
      set_swipe_multipliers(state, target, displacement_control);
    else if (!holding)
      state.load_factor =
        displacement_control ? controlled_load_factor(state, target) : target;
    return evaluate(state, result);
  }

  bool
  CoupledSolver::iterate(const double    target,
                         const bool      holding,
                         StepState      &state,
                         LoadStepResult &result,
                         Evaluation     &e,
                         unsigned int   &iterations)
  {
    const bool displacement_control =
      !holding && settings.control == LoadPathParameters::Control::displacement;
    FixedPointAcceleration acceleration(
      acceleration_of(settings, condensed, newton), settings.anderson_depth);
    const auto evaluate_iterate = [&](StepState &iterate) {
      return evaluate_at(target, holding, iterate, result);
    };
    // The globalisation (safeguarded_newton.h).
    // - The coupled tangent: a full step that raises |R| is halved at once,
    //   down to 1/16, and the step is cut if even that does not lower |R|.
    //   Going on from a worse plastic state wanders off (measured: |R| / |F|
    //   up to 1e6 at a plateau, where the tangent is near-singular; with 4
    //   non-improving steps allowed, pile-adhesion converged to a state 20
    //   rad off), and taking initial-stiffness updates instead of cutting
    //   made steps that a cut settles 4-10 times slower
    //   (doc/soil-plasticity.md 3b). Those updates are the retry after the
    //   last cut only (retry_persistently).
    // - Condensed: up to 4 full steps may go on without a new best |R| (a
    //   gap that closes or a slip that reverses beyond the tangent's
    //   foresight is put right by the next tangent), then the line search
    //   from the best iterate halves down to 2^-16; its iterations are
    //   cheap, so no step is given up early.
    using Newton = SafeguardedNewton<StepState, Evaluation, Correction>;
    Newton newton_iteration(
      condensed ? Newton::Settings{4,
                                   1. / 65536.,
                                   std::numeric_limits<unsigned int>::max()} :
                  Newton::Settings{0, 1. / 16., 20},
      evaluate_iterate,
      [&](const Evaluation &at, const StepState &iterate) {
        return newton_correction(at, iterate, displacement_control);
      },
      [&](const double alpha, const Correction &dc, StepState &iterate) {
        add_correction(alpha, dc, iterate);
      });
    const auto balanced = [&](StepState &iterate, Evaluation &at) {
      if (!at.scale.converged(at.residual_norm, settings.tolerance))
        return false;
      if (!condensed || !newton)
        return true;
      // Condensed Newton: the iterate from the full solve K^-1 c, checked
      // again (iterative refinement of the flexibility blocks' round-off).
      complete(iterate);
      at = evaluate_iterate(iterate);
      return at.scale.converged(at.residual_norm, settings.tolerance);
    };
    const auto initial_stiffness_update = [&](StepState        &iterate,
                                              const Evaluation &at) {
      add_correction(1.,
                     initial_stiffness_correction(acceleration, iterate, at),
                     iterate);
    };
    // No descent: condensed, one initial-stiffness update (exact and cheap)
    // moves off the kink of the return mapping at the iterate. On the
    // coupled tangent the step is cut, unless this is its retry after the
    // last cut (retry_persistently): then one initial-stiffness update,
    // Newton starting again from there, until |R| stalls.
    const auto no_descent = [&]() {
      if (condensed)
        return NoDescent::initial_stiffness_update;
      return persistent && !newton_iteration.stalled() ?
               NoDescent::initial_stiffness_update_and_restart :
               NoDescent::cut;
    };
    e = evaluate_iterate(state);
    return iterate_to_balance(newton ? &newton_iteration : nullptr,
                              state,
                              e,
                              evaluate_iterate,
                              balanced,
                              initial_stiffness_update,
                              no_descent,
                              settings.maximum_iterations,
                              iterations);
  }

  void
  CoupledSolver::complete(StepState &state) const
  {
    condensation->complete(state.correction_load, state.correction_solution);
    if (settings.control == LoadPathParameters::Control::displacement)
      state.controlled_motion = controlled_motions(
        {&state.correction_solution[controlled_harmonic_index()]})[0];
  }

  void
  CoupledSolver::extrapolate(const StepState &before_last,
                             const double     ratio,
                             StepState       &state) const
  {
    LoadPathStates::extrapolate(before_last, ratio, state);
    state.controlled_motion +=
      ratio * (committed.controlled_motion - before_last.controlled_motion);
  }

  std::vector<std::pair<FoundationMotion, double>>
  CoupledSolver::held_reactions(const StepState         &state,
                                const InterfaceSnapshot &interface_state) const
  {
    if (parameters.rigid_foundation.reported_motions().empty())
      return {};
    std::vector<Vector<double>> nonlinear_load =
      soil.size() > 0 ? soil.load_of(state.plastic, false) : zero_fields(set);
    if (interface)
      {
        const std::vector<Vector<double>> interface_load =
          interface->load_of(interface->spring_plastic(interface_state),
                             interface_sampling,
                             false);
        for (unsigned int h = 0; h < set.size(); ++h)
          nonlinear_load[h] += interface_load[h];
      }
    return held_reactions_of(state, nonlinear_load);
  }

  Vector<double>
  CoupledSolver::held_load(const unsigned int h) const
  {
    return held_stage_load(set.problem(h));
  }

  double
  CoupledSolver::load_work() const
  {
    // Per harmonic on its owner, summed in the harmonics' order.
    std::vector<double> parts(set.size(), 0.);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.owns(h))
        {
          Vector<double> load = loads.load[h];
          load *= committed.load_factor;
          if (!loads.held_solution.empty())
            load.add(committed.held_fraction, held_load(h));
          if (!loads.swipe_load.empty())
            load.add(committed.swipe_force, loads.swipe_load[h]);
          parts[h] = load * total_displacement(committed, h);
        }
    return sum_over_harmonics(set, parts, 1)[0];
  }

  void
  CoupledSolver::run(std::ostream &log)
  {
    describe(log);
    LoadPath(settings, entry, *this).run(log);
    if (set.n_owning_ranks() > 1)
      log << "  MPI: " << set.n_rank_sums() << " sums over the ranks ("
          << (condensed ?
                "one per iteration, a few per step" :
                "strain amplitudes and theta integrals every iteration, the "
                "controlled motion under displacement control, a few per "
                "step; with Stiffness = tangent the softening, the "
                "tangent's values and the load correction every Newton "
                "update")
          << "), " << set.rank_sum_time()
          << " s in them on rank 0 (computing or waiting for the others)\n";
  }

  void
  CoupledSolver::describe(std::ostream &log) const
  {
    if (soil.size() > 0)
      log << "plastic soil: " << soil.size() << " quadrature points x "
          << sampling.n_samples() << " theta samples, ";
    else if (condensed)
      log << "nonlinear interfaces: " << interface->size() << " points x "
          << sampling.n_samples() << " theta samples, ";
    else
      log << "nonlinear interfaces on elastic soil, on the coupled tangent "
             "(a swipe; no soil points): ";
    log << set.size() << " harmonics"
        << (set.n_owning_ranks() > 1 ?
              " distributed over " + std::to_string(set.n_owning_ranks()) +
                " MPI ranks" :
              std::string())
        << ", "
        << (settings.control == LoadPathParameters::Control::load ?
              "load" :
              "displacement")
        << " control, " << settings.load_steps << " steps, tolerance "
        << settings.tolerance << ", "
        << iteration_name(settings, condensed, newton)
        << (soil.projects_dilatation() ? ", B-bar" : "");
    if (!candidates.empty())
      log << ", harmonics grow up to n = " << settings.maximum_harmonic
          << " where the interface traction calls for them (tolerance "
          << settings.harmonic_tolerance << ")";
    log << '\n';
    if (interface)
      interface->describe(log,
                          interface_sampling.n_samples(),
                          highest_harmonic(harmonics));
    write_held_motions(log, "");
    // With soil, its self-weight (the held stage) gives a c = 0 interface
    // its normal stress; without, nothing does.
    if (soil.size() == 0 && interface && interface->without_strength())
      log << "warning: " << entry
          << ": a coulomb interface has c = 0 and no Initial stress: it has "
             "no strength\n";
  }

  bool
  CoupledSolver::solve_trial(const double target, const bool holding)
  {
    trial_result         = LoadStepResult();
    const bool converged = solve_step(target, holding, trial, trial_result);
    persistent           = false;
    return converged;
  }

  bool
  CoupledSolver::retry_persistently(std::ostream &log)
  {
    // Condensed Newton never cuts for want of descent (iterate()).
    if (condensed || !newton)
      return false;
    persistent = true;
    log << "  step retried at that size, Newton going on with an "
           "initial-stiffness update where it finds no descent\n";
    return true;
  }

  void
  CoupledSolver::commit_trial(const LoadStep &step,
                              const bool      holding,
                              std::ostream   &log)
  {
    commit(step);
    if (holding)
      swipe_settlement = trial_result.motion.vertical_displacement;
    trial_result.held_reactions =
      held_reactions(committed, trial_result.interface_state);
    if (interface)
      record_interfaces(*interface, interface_sampling);
    record_trial(holding, log, step_observer);
  }

} // namespace FourierSSI
