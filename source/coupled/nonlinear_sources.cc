#include <algorithm>
#include <fourier_ssi/coupled/nonlinear_sources.h>

namespace FourierSSI
{
  namespace
  {
    /**
     * The interfaces' theta samples without soil. With growth n_max is
     * Maximum harmonic, so that the samples (and the state kept at them)
     * stay valid when harmonics are added. Exact contact and a stiff
     * penalty (InterfaceParameters::is_stiff) take one sample per value of
     * the gap, whichever solver steps the path (so that both give the same
     * answer); softer laws the general default.
     */
    unsigned int
    interface_theta_samples(const std::vector<Harmonic> &list,
                            const LoadPathParameters    &settings,
                            const InterfaceParameters   &interfaces)
    {
      const unsigned int n_max =
        std::max(highest_harmonic(list), settings.maximum_harmonic);
      return interfaces.is_stiff() ?
               constrained_theta_samples(n_max, settings.theta_samples) :
               theta_samples_for(n_max, settings.theta_samples);
    }

    /**
     * The theta samples of the soil (of the interfaces without soil). With
     * growth n_max is Maximum harmonic, as for the interfaces: the
     * committed plastic state lives at the samples, and samples that never
     * change carry it over exactly when harmonics are added.
     */
    unsigned int
    soil_theta_samples(const std::vector<Harmonic> &list,
                       const AllParameters         &parameters,
                       const bool                   condensed)
    {
      const LoadPathParameters &settings = parameters.load_path;
      return condensed ?
               interface_theta_samples(list, settings, parameters.interfaces) :
               theta_samples_for(std::max(highest_harmonic(list),
                                          settings.maximum_harmonic),
                                 settings.theta_samples);
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

    /**
     * One line if a harmonic has prescribed (non-zero) Dirichlet values:
     * the loads are scaled by lambda and held by rho, the constraints not
     * (not yet).
     */
    void
    check_homogeneous_constraints(const HarmonicSet &set, const bool condensed)
    {
      const std::string entry = condensed ? "Load path" : "Soil plasticity";
      const std::string what =
        condensed ? "nonlinear interfaces" : "plastic soil";
      for (unsigned int h = 0; h < set.size(); ++h)
        AssertThrow(!set.problem(h).get_constraints().has_inhomogeneities(),
                    ExcMessage(
                      entry +
                      ": not yet: prescribed (non-zero) Dirichlet "
                      "values with " +
                      what + "; load the scene through the Rigid foundation"));
    }
  } // namespace

  NonlinearSources::NonlinearSources(const HarmonicSet   &set,
                                     const AllParameters &parameters,
                                     const LoadPattern   &loads,
                                     const bool           condensed)
    : set(set)
    , settings(parameters.load_path)
    , loads(loads)
    , condensed(condensed)
    , harmonics(set.get_harmonics())
    , sampling(harmonics, soil_theta_samples(harmonics, parameters, condensed))
    , candidates(candidate_harmonics(harmonics, settings.maximum_harmonic))
    , interface_samples(
        harmonics,
        !condensed && holds_gaps_by_multipliers(set, parameters) ?
          minimum_theta_samples(
            std::max(highest_harmonic(harmonics), settings.maximum_harmonic)) :
          sampling.n_samples())
    , spectrum(candidates, interface_samples.n_samples())
    , soil_spectrum(candidates, sampling.n_samples())
    , soil(set, parameters, sampling)
  {
    check_homogeneous_constraints(set, condensed);
    if (parameters.interfaces.any_nonlinear())
      interface = std::make_unique<NonlinearInterfacePoints>(
        set,
        parameters,
        augments_stiff_laws(
          condensed, harmonics, settings, parameters.interfaces));
  }

  void
  NonlinearSources::read_loads()
  {
    if (soil.size() > 0)
      {
        pattern_strain = soil.strain_amplitudes(loads.solution);
        if (loads.holds_loads())
          held_strain = soil.strain_amplitudes(loads.held_solution);
        if (!loads.swipe_solution.empty())
          swipe_strain = soil.strain_amplitudes(loads.swipe_solution);
      }
    if (interface)
      interface_cases = interface->load_cases(loads, interface_samples);
  }

  void
  NonlinearSources::start_at_rest(CoupledStepState &state) const
  {
    state.plastic.assign(soil.size() * sampling.n_samples(),
                         {{0., 0., 0., 0., 0., 0.}});
    state.soil_history.assign(soil.history_size(), {{0., 0., 0., 0., 0., 0.}});
    if (interface)
      state.interfaces = interface->at_rest(interface_samples);
  }

  std::vector<StrainVector>
  NonlinearSources::strain_samples(
    const std::vector<Vector<double>> &correction,
    const double                       load_factor,
    const double                       held_fraction,
    const double                       swipe_force) const
  {
    const StrainAmplitudes amplitude = soil.strain_amplitudes(correction);
    return soil.strain_samples({{1., &amplitude},
                                {load_factor, &pattern_strain},
                                {held_fraction, &held_strain},
                                {swipe_force, &swipe_strain}});
  }

  std::vector<LocalVector>
  NonlinearSources::relative_displacements(
    const std::vector<Vector<double>> &correction,
    const double                       load_factor,
    const double                       held_fraction,
    const double                       swipe_force) const
  {
    if (!interface)
      return {};
    return interface->iterate_relative(correction,
                                       interface_samples,
                                       interface_cases,
                                       load_factor,
                                       held_fraction,
                                       swipe_force);
  }

  CoupledEvaluation
  NonlinearSources::evaluate(const CoupledStepState &state,
                             const CoupledStepState &committed,
                             LoadStepResult         &result) const
  {
    CoupledEvaluation e;
    if (soil.size() > 0)
      {
        // 1-2: strains at every (point, theta), the return mapping.
        e.strain = strain_samples(state.correction_solution,
                                  state.load_factor,
                                  state.held_fraction,
                                  state.swipe_force);
        static_cast<SoilYieldCounts &>(result) =
          soil.return_map(e.strain,
                          committed.plastic,
                          committed.soil_history,
                          e.plastic,
                          e.soil_history);
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
    e.scale = {loads.applied_norm(state.load_factor, state.held_fraction),
               interface_load_norm};
    return e;
  }

  std::vector<Vector<double>>
  NonlinearSources::out_of_balance_load(
    const std::vector<Vector<double>> &fields,
    const CoupledStepState            &committed) const
  {
    std::vector<StrainVector> plastic, history;
    soil.return_map(strain_samples(fields, 0., 0.),
                    committed.plastic,
                    committed.soil_history,
                    plastic,
                    history);
    CoupledEvaluation e;
    e.residual = soil.load_of(plastic);
    if (interface)
      {
        // The fields as K^-1 c of a state without loads, from the committed
        // interface state.
        CoupledStepState at;
        at.correction_solution = fields;
        at.interfaces          = committed.interfaces;
        add_interface_residual(at, e);
      }
    return e.residual;
  }

  double
  NonlinearSources::add_interface_residual(const CoupledStepState &state,
                                           CoupledEvaluation      &e) const
  {
    e.relative = relative_displacements(state.correction_solution,
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
      interface_samples);
    const double norm = norm_over_harmonics(interface_load);
    // Without soil the interfaces' load is the whole G.
    if (e.residual.empty())
      e.residual = std::move(interface_load);
    else
      for (unsigned int h = 0; h < set.size(); ++h)
        e.residual[h] += interface_load[h];
    return norm;
  }

  bool
  NonlinearSources::augments() const
  {
    return interface && interface->any_augmented();
  }

  NonlinearSources::MultiplierUpdate
  NonlinearSources::update_multipliers(const CoupledEvaluation &e,
                                       const double             tolerance,
                                       const unsigned int       update,
                                       CoupledStepState        &state) const
  {
    return interface->update_and_test_multipliers(e.traction,
                                                  state.interfaces.slip,
                                                  interface_samples,
                                                  state.interfaces.origin,
                                                  tolerance * e.scale.largest(),
                                                  update);
  }

  void
  NonlinearSources::accept(CoupledEvaluation &e,
                           CoupledStepState  &state,
                           LoadStepResult    &result) const
  {
    if (soil.size() > 0)
      soil.count_over_ranks(result);
    state.plastic      = std::move(e.plastic);
    state.soil_history = std::move(e.soil_history);
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
  }

  std::vector<Vector<double>>
  NonlinearSources::nodal_load(const CoupledStepState  &state,
                               const InterfaceSnapshot &interface_state) const
  {
    std::vector<Vector<double>> nonlinear_load;
    if (soil.size() > 0)
      nonlinear_load = soil.load_of(state.plastic, false);
    else
      {
        nonlinear_load.resize(set.size());
        for (unsigned int h = 0; h < set.size(); ++h)
          nonlinear_load[h].reinit(set.problem(h).get_dof_handler().n_dofs());
      }
    if (interface)
      {
        const std::vector<Vector<double>> interface_load =
          interface->load_of(interface->spring_plastic(interface_state),
                             interface_samples,
                             false);
        for (unsigned int h = 0; h < set.size(); ++h)
          nonlinear_load[h] += interface_load[h];
      }
    return nonlinear_load;
  }

  std::vector<std::vector<std::vector<types::global_dof_index>>>
  NonlinearSources::tangent_dofs() const
  {
    std::vector<std::vector<std::vector<types::global_dof_index>>> dofs =
      soil.cell_dofs();
    // The coulomb interfaces' pairs couple the harmonics too.
    if (interface)
      for (auto &pair : interface->pair_dofs())
        dofs.push_back(std::move(pair));
    return dofs;
  }

  void
  NonlinearSources::add_softening(
    const std::vector<StrainVector> &strain,
    const CoupledStepState          &committed,
    const std::vector<LocalVector>  &relative,
    const std::vector<LocalVector>  &interface_origin,
    CoupledTangent                  &tangent) const
  {
    soil.add_softening(strain,
                       committed.plastic,
                       committed.soil_history,
                       tangent);
    if (interface)
      interface->add_softening(relative,
                               interface_origin,
                               interface_samples,
                               tangent);
  }

  void
  NonlinearSources::resample()
  {
    harmonics = set.get_harmonics();
    // The same angles (chosen for Maximum harmonic), every harmonic's
    // factors.
    sampling          = ThetaSampling(harmonics, sampling.n_samples());
    interface_samples = ThetaSampling(harmonics, interface_samples.n_samples());
    if (soil.size() > 0)
      soil.grow(sampling);
  }

  void
  NonlinearSources::describe_points(std::ostream &log) const
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
  }

  void
  NonlinearSources::describe_interfaces(std::ostream &log) const
  {
    if (interface)
      interface->describe(log,
                          interface_samples.n_samples(),
                          highest_harmonic(harmonics));
  }

  bool
  NonlinearSources::lacks_strength() const
  {
    // With soil, its self-weight (the held stage) gives a c = 0 interface
    // its normal stress; without, nothing does.
    return soil.size() == 0 && interface && interface->without_strength();
  }
} // namespace FourierSSI
