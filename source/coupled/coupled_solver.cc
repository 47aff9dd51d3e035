#include <fourier_ssi/coupled/condensed_interfaces.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/coupled/load_pattern.h>
#include <fourier_ssi/coupled/tangent_linearisation.h>

namespace FourierSSI
{
  namespace
  {
    /**
     * The linearisation of the scene (AllParameters::
     * linearises_on_coupled_tangent): the coupled tangent with plastic soil
     * or a swipe, otherwise condensed onto the interfaces.
     */
    std::unique_ptr<Linearisation>
    make_linearisation(HarmonicSet            &set,
                       const AllParameters    &parameters,
                       const NonlinearSources &sources,
                       const LoadControl      &control,
                       const LoadPathStates   &states)
    {
      if (parameters.linearises_on_coupled_tangent())
        return std::make_unique<TangentLinearisation>(
          set, parameters, sources, control, states);
      return std::make_unique<CondensedInterfaces>(set,
                                                   parameters,
                                                   sources,
                                                   control);
    }
  } // namespace

  CoupledSolver::CoupledSolver(HarmonicSet         &set,
                               const AllParameters &parameters)
    : set(set)
    , parameters(parameters)
    , entry(parameters.linearises_on_coupled_tangent() ? "Soil plasticity" :
                                                         "Load path")
    , states(set, parameters)
    , sources(set,
              parameters,
              states.loads,
              !parameters.linearises_on_coupled_tangent())
    , control(set,
              parameters,
              states,
              !parameters.linearises_on_coupled_tangent())
    , linearisation(
        make_linearisation(set, parameters, sources, control, states))
    , step_iteration(parameters.load_path,
                     sources,
                     *linearisation,
                     control,
                     states)
  {
    states.sources = {sources.soil_points().size() > 0,
                      sources.interface_points()};
    solve_loads();
    states.start_at_rest();
    sources.start_at_rest(states.committed);
  }

  CoupledSolver::~CoupledSolver() = default;

  void
  CoupledSolver::solve_loads()
  {
    states.loads = LoadPattern(set);
    if (states.loads.holds_loads() && parameters.rigid_foundation.swipes())
      states.loads.add_swipe_pattern(set);
    sources.read_loads();
    control.read_load_motions();
  }

  std::vector<Vector<double>>
  CoupledSolver::soil_nodal_force(
    const std::function<bool(const Point<2> &)> &selected) const
  {
    const CoupledStepState &committed = states.committed;
    return sources.soil_points().nodal_force(
      sources.strain_samples(committed.correction_solution,
                             committed.load_factor,
                             committed.held_fraction),
      committed.plastic,
      selected);
  }

  std::vector<SoilSample>
  CoupledSolver::committed_soil_samples() const
  {
    const CoupledStepState &committed = states.committed;
    return sources.soil_points().samples_of(
      sources.strain_samples(committed.correction_solution,
                             committed.load_factor,
                             committed.held_fraction,
                             committed.swipe_force),
      states.before_last.plastic,
      states.before_last.soil_history,
      committed.plastic);
  }

  std::vector<Vector<double>>
  CoupledSolver::soil_force(const std::vector<Vector<double>> &fields) const
  {
    return sources.soil_points().elastic_force(fields);
  }

  std::vector<Vector<double>>
  CoupledSolver::out_of_balance_load(
    const std::vector<Vector<double>> &fields) const
  {
    return sources.out_of_balance_load(fields, states.committed);
  }

  std::vector<Vector<double>>
  CoupledSolver::interface_force(
    const std::vector<Vector<double>> &fields) const
  {
    const NonlinearInterfacePoints *interface = sources.interface_points();
    AssertThrow(interface != nullptr,
                ExcMessage(entry + ": the scene has no nonlinear interface"));
    return interface->load_of(
      interface->relative_displacements(fields, sources.interface_sampling()),
      sources.interface_sampling());
  }

  std::vector<Vector<double>>
  CoupledSolver::tangent_product(const std::vector<Vector<double>> &fields,
                                 const std::vector<Vector<double>> &x)
  {
    auto *tangent = dynamic_cast<TangentLinearisation *>(linearisation.get());
    AssertThrow(tangent != nullptr,
                ExcMessage(entry + ": the scene is not linearised on the "
                                   "coupled tangent"));
    return tangent->tangent_product(fields, x);
  }

  double
  CoupledSolver::load_work() const
  {
    const LoadPattern      &loads     = states.loads;
    const CoupledStepState &committed = states.committed;
    // Per harmonic on its owner, summed in the harmonics' order.
    std::vector<double> parts(set.size(), 0.);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.owns(h))
        {
          Vector<double> load = loads.load[h];
          load *= committed.load_factor;
          if (!loads.held_solution.empty())
            load.add(committed.held_fraction, held_stage_load(set.problem(h)));
          if (!loads.swipe_load.empty())
            load.add(committed.swipe_force, loads.swipe_load[h]);
          parts[h] = load * states.total_displacement(committed, h);
        }
    return sum_over_harmonics(set, parts, 1)[0];
  }

  void
  CoupledSolver::run(std::ostream &log)
  {
    describe(log);
    LoadPath(parameters.load_path, entry, *this).run(log);
    if (set.n_owning_ranks() > 1)
      log << "  MPI: " << set.n_rank_sums() << " sums over the ranks ("
          << linearisation->rank_sums() << "), " << set.rank_sum_time()
          << " s in them on rank 0 (computing or waiting for the others)\n";
  }

  void
  CoupledSolver::describe(std::ostream &log) const
  {
    const LoadPathParameters &settings = parameters.load_path;
    sources.describe_points(log);
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
        << settings.tolerance << ", " << linearisation->name()
        << (sources.soil_points().projects_dilatation() ? ", B-bar" : "");
    if (sources.grows())
      log << ", harmonics grow up to n = " << settings.maximum_harmonic
          << " where the "
          << (sources.soil_points().size() == 0 ?
                "interface traction" :
              sources.interface_points() == nullptr ?
                "soil's stress" :
                "soil's stress or the interface traction")
          << " calls for them (tolerance " << settings.harmonic_tolerance
          << ")";
    log << '\n';
    sources.describe_interfaces(log);
    states.write_held_motions(log, "");
    if (sources.lacks_strength())
      log << "warning: " << entry
          << ": a coulomb interface has c = 0 and no Initial stress: it has "
             "no strength\n";
  }

  void
  CoupledSolver::start_trial(const double ratio)
  {
    states.start_trial(ratio);
  }

  bool
  CoupledSolver::solve_trial(const double target, const bool holding)
  {
    states.trial_result  = LoadStepResult();
    const bool converged = step_iteration.solve(
      target, holding, persistent, states.trial, states.trial_result);
    persistent = false;
    return converged;
  }

  RigidMotion
  CoupledSolver::trial_motion() const
  {
    return states.motion_of(states.trial);
  }

  bool
  CoupledSolver::grows(std::ostream &log)
  {
    const std::vector<Harmonic> added =
      sources.harmonics_called_for(states.trial,
                                   states.trial_result.interface_state,
                                   n_converged_steps() + 1,
                                   log);
    if (added.empty())
      return false;
    grow(added);
    return true;
  }

  void
  CoupledSolver::grow(const std::vector<Harmonic> &added)
  {
    set.add(added);
    sources.resample();
    solve_loads();
    const unsigned int first = states.committed.correction_solution.size();
    states.extend_at_rest(first);
    linearisation->grow(first);
  }

  bool
  CoupledSolver::retry_persistently(std::ostream &log)
  {
    // Condensed Newton never cuts for want of descent.
    if (!linearisation->retries_persistently())
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
    states.commit(step);
    LoadStepResult &result = states.trial_result;
    if (holding)
      control.hold_settlement(result.motion.vertical_displacement);
    if (control.reports_reactions())
      result.held_reactions =
        control.held_reactions(states.committed,
                               sources.nodal_load(states.committed,
                                                  result.interface_state));
    if (sources.interface_points())
      states.record_interfaces(*sources.interface_points(),
                               sources.interface_sampling());
    states.record_trial(holding, log, [this](const LoadStepResult &r) {
      for (const auto &observer : step_observers)
        observer(r);
    });
  }

  double
  CoupledSolver::committed_load_factor() const
  {
    return states.committed.load_factor;
  }

  RigidMotion
  CoupledSolver::committed_motion() const
  {
    return states.motion_of(states.committed);
  }

  unsigned int
  CoupledSolver::n_converged_steps() const
  {
    return states.steps.size();
  }

  bool
  CoupledSolver::holds_loads() const
  {
    return states.loads.holds_loads();
  }

  void
  CoupledSolver::write_held_loads(std::ostream &log) const
  {
    states.write_held_loads(log);
  }
} // namespace FourierSSI
