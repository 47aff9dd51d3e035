// The driver's path for scenes with plastic soil: the harmonics are coupled
// through theta at the soil's quadrature points, so they are solved together
// by CoupledSoilSolver on one HarmonicSet (doc/soil-plasticity.md).
#include <deal.II/base/timer.h>
#include <fourier_ssi/coupled_soil_solver.h>
#include <fourier_ssi/distributed_linear_system.h>
#include <fourier_ssi/simulator.h>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Soil plasticity";

    /** What the plastic-soil path does not do yet: one line each. */
    void
    check_supported(const AllParameters &parameters, const MPI_Comm comm)
    {
      AssertThrow(!parameters.interfaces.any_nonlinear(),
                  ExcMessage(entry + ": not yet: plastic soil together with "
                                     "a coulomb interface (use a linear "
                                     "interface: rough, smooth, kn/ks)"));
      AssertThrow(parameters.discretization.refinement_cycles == 1,
                  ExcMessage(entry + ": not yet: Discretization/Refinement "
                                     "cycles > 1 with plastic soil"));
      AssertThrow(!uses_distributed_solve(parameters.solver, comm),
                  ExcMessage(entry + ": not yet: a distributed solve (MPI "
                                     "ranks or Distributed = always) with "
                                     "plastic soil"));
      AssertThrow(parameters.output.lines.empty() &&
                    !parameters.output.write_3d_vtu,
                  ExcMessage(entry + ": not yet: Output/Lines 3D and Write "
                                     "3d vtu with plastic soil"));
      AssertThrow(!parameters.rigid_foundation.stiffness_coefficients,
                  ExcMessage(entry + ": Rigid foundation/Stiffness "
                                     "coefficients are linear quantities; "
                                     "set it false with plastic soil"));
      AssertThrow(!parameters.initial_stress.enabled(),
                  ExcMessage(entry + ": not yet: Initial stress with plastic "
                                     "soil (Tresca needs none; Mohr-Coulomb "
                                     "soil has its strength from c' only)"));
    }

    void
    add_step_rows(const CoupledSoilSolver &solver, ResultsTable &results)
    {
      const Harmonic any{0, Family::symmetric};
      const auto    &steps = solver.get_steps();
      for (unsigned int s = 0; s < steps.size(); ++s)
        {
          const SoilStepResult &r     = steps[s];
          const auto            loads = solver.applied_loads(r.load_factor);
          results.add("step_load_factor", any, s + 1, r.load_factor, "-");
          results.add("step_vertical_force", any, s + 1, loads[2], "kN");
          results.add("step_horizontal_force", any, s + 1, loads[0], "kN");
          results.add("step_moment", any, s + 1, loads[4], "kN.m");
          results.add("step_vertical_displacement",
                      any,
                      s + 1,
                      r.motion.vertical_displacement,
                      "m");
          results.add("step_horizontal_displacement",
                      any,
                      s + 1,
                      r.motion.horizontal_displacement,
                      "m");
          results.add("step_rotation", any, s + 1, r.motion.rotation, "rad");
          results.add("step_iterations", any, s + 1, r.iterations, "-");
          results.add("step_residual", any, s + 1, r.residual, "-");
          results.add("step_plastic_samples", any, s + 1, r.n_plastic, "-");
          results.add("step_largest_yield_value",
                      any,
                      s + 1,
                      r.largest_yield_value,
                      "kPa");
          results.add("step_wall_time", any, s + 1, r.time, "s");
        }
    }
  } // namespace

  void
  Simulator::solve_plastic_soil(std::ostream &log)
  {
    check_supported(parameters, communicator);
    Timer timer;
    harmonic_set = std::make_unique<HarmonicSet>(
      parameters,
      plan.harmonics,
      triangulation,
      plan.loads,
      communicator,
      parameters.discretization.concurrent_harmonics);
    harmonic_set->setup_and_assemble();
    harmonic_set->factorize();
    log << "assembled and factorized " << harmonic_set->size()
        << " harmonics in " << timer.wall_time() << " s" << std::endl;
    CoupledSoilSolver solver(*harmonic_set, parameters);
    const std::string directory = parameters.output.directory;
    try
      {
        solver.run(log);
      }
    catch (const std::exception &e)
      {
        // Keep the converged steps, marked as such by the file name.
        if (writes_csv() && !solver.get_steps().empty())
          solver.write_csv(directory + "/load-displacement-incomplete.csv");
        throw;
      }
    log << "coupled solve: " << solver.get_steps().size() << " steps in "
        << timer.wall_time() << " s" << std::endl;
    add_step_rows(solver, results);
    if (!writes_csv())
      return;
    const std::string curve = directory + "/load-displacement.csv";
    written.push_back(curve);
    solver.write_csv(curve);
    log << "load-displacement curve written to " << curve << std::endl;
    const std::string name = directory + "/" + parameters.output.results_file;
    written.push_back(name);
    results.write_csv(name);
    log << "results written to " << name << std::endl;
  }
} // namespace FourierSSI
