#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/cyclic_output.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/load_cycles.h>

namespace FourierSSI
{
  namespace
  {
    using Motion = LoadPathParameters::Motion;

    /**
     * The motion whose loops are drawn: the controlled one, or under load
     * control that of the first load the foundation carries (H, M, T, V).
     */
    Motion
    cycled_motion(const AllParameters &parameters)
    {
      const LoadPathParameters        &path = parameters.load_path;
      const RigidFoundationParameters &f    = parameters.rigid_foundation;
      if (path.control == LoadPathParameters::Control::displacement)
        return path.motion;
      if (f.horizontal_force != 0.)
        return Motion::horizontal;
      if (f.moment != 0.)
        return Motion::rotation;
      if (f.torque != 0.)
        return Motion::twist;
      return Motion::vertical;
    }

    CycleQuantities
    quantities_of(const NamedLoad &load, const Motion motion)
    {
      switch (motion)
        {
          case Motion::vertical:
            return {load.name, "kN", "vertical", "m"};
          case Motion::horizontal:
            return {load.name, "kN", "horizontal", "m"};
          case Motion::rotation:
            return {load.name, "kNm", "rotation", "rad"};
          case Motion::twist:
            return {load.name, "kNm", "twist", "rad"};
        }
      return {};
    }

    /** The path's points: the state before segment 1, then every step. */
    std::vector<CyclePoint>
    path_points(const CoupledSolver &solver,
                const AllParameters &parameters,
                const Motion         motion)
    {
      std::vector<CyclePoint> path(1);
      for (const LoadStepResult &step : solver.get_steps())
        {
          CyclePoint point;
          point.segment = step.segment;
          point.motion  = controlled_component(step.motion, motion);
          point.load    = conjugate_load(solver.applied_loads(step.load_factor,
                                                           step.held_fraction),
                                      parameters.rigid_foundation,
                                      motion)
                         .value;
          point.rigid = step.motion;
          // The held stage's last step is where segment 1 starts.
          if (step.segment == 0)
            path.front() = point;
          else
            path.push_back(point);
        }
      return path;
    }

    /** A loop of a perfectly plastic law below first yield is a line. */
    void
    note_elastic_loops(const std::vector<LoadCycle> &cycles,
                       const AllParameters          &parameters,
                       std::ostream                 &log)
    {
      bool hardening = false;
      for (const auto &[id, law] : parameters.soil_plasticity.laws)
        hardening = hardening || law.hardening();
      for (unsigned int j = 0; j < cycles.size(); ++j)
        if (!hardening && std::abs(cycles[j].dissipated_energy) <=
                            1e-6 * cycles[j].stored_energy)
          {
            log << "note: cycle " << j + 1
                << " dissipates nothing: it stays below first yield of "
                   "the perfectly plastic laws, which have no small-strain "
                   "hysteresis (an iwan clay or sand has)\n";
            return;
          }
    }

    /** The loops' main values per cycle, as results.csv rows. */
    void
    add_cycle_rows(const std::vector<LoadCycle> &cycles,
                   const CycleQuantities        &names,
                   const Motion                  motion,
                   ResultsTable                 &results)
    {
      const Harmonic    any{0, Family::symmetric};
      const std::string per = names.load_unit + "/" + names.motion_unit;
      for (unsigned int j = 0; j < cycles.size(); ++j)
        {
          const LoadCycle   &c = cycles[j];
          const unsigned int k = j + 1;
          results.add(
            "load_cycle_end_load", any, k, c.end_load, names.load_unit);
          results.add("load_cycle_reversal_load",
                      any,
                      k,
                      c.reversal_load,
                      names.load_unit);
          results.add(
            "load_cycle_secant_stiffness", any, k, c.secant_stiffness, per);
          results.add(
            "load_cycle_dissipated_energy", any, k, c.dissipated_energy, "kJ");
          results.add("load_cycle_dissipated_energy_error",
                      any,
                      k,
                      c.dissipated_energy_error,
                      "kJ");
          results.add("load_cycle_damping_ratio", any, k, c.damping_ratio, "-");
          results.add("load_cycle_damping_ratio_error",
                      any,
                      k,
                      c.damping_ratio_error,
                      "-");
          if (c.passes_zero_load)
            results.add("load_cycle_zero_load_" + names.motion,
                        any,
                        k,
                        controlled_component(c.at_zero_load, motion),
                        names.motion_unit);
        }
    }

    /** The cycles of the solver's path and the names they are drawn in. */
    struct Loops
    {
      Motion                 motion;
      std::vector<LoadCycle> cycles;
      CycleQuantities        names;
    };

    Loops
    loops_of(const CoupledSolver &solver, const AllParameters &parameters)
    {
      Loops loops;
      loops.motion = cycled_motion(parameters);
      loops.cycles = load_cycles(path_points(solver, parameters, loops.motion));
      loops.names  = quantities_of(conjugate_load(solver.applied_loads(0.),
                                                 parameters.rigid_foundation,
                                                 loops.motion),
                                  loops.motion);
      return loops;
    }
  } // namespace

  void
  LoadCycleOutput::add_rows(const CoupledSolver     &solver,
                            const CoupledRunContext &context,
                            std::ostream &)
  {
    if (!context.parameters.load_path.is_cyclic())
      return;
    const Loops loops = loops_of(solver, context.parameters);
    add_cycle_rows(loops.cycles, loops.names, loops.motion, context.results);
  }

  void
  LoadCycleOutput::write_files(const CoupledSolver     &solver,
                               const CoupledRunContext &context,
                               std::ostream            &log)
  {
    if (!context.writes_csv || !context.parameters.load_path.is_cyclic())
      return;
    const Loops loops = loops_of(solver, context.parameters);
    log_load_cycles(log, loops.cycles, loops.names);
    if (loops.cycles.empty())
      log << "load cycles: none complete (a cycle returns to the turning "
             "point it starts from: Targets = a, b, a, or Cycles)\n";
    note_elastic_loops(loops.cycles, context.parameters, log);
    AtomicFile file(context.result_files.claim("load-cycles.csv"));
    write_load_cycles(file.stream(), loops.cycles, loops.names);
    file.commit();
    log << "load cycles written to "
        << context.result_files.path_of("load-cycles.csv") << '\n';
  }
} // namespace FourierSSI
