#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/grid/tria.h>
#include <filesystem>
#include <fourier_ssi/adaptivity.h>
#include <fourier_ssi/command_line.h>
#include <fourier_ssi/harmonic_problem.h>
#include <fourier_ssi/simulator.h>
#include <iomanip>

namespace FourierSSI
{
  Simulator::Simulator(const AllParameters &parameters,
                       const MPI_Comm       communicator)
    : parameters(parameters)
    , communicator(communicator)
  {}

  ResultsTable
  Simulator::run(std::ostream &log, const bool write_files)
  {
    ResultsTable             results;
    std::vector<std::string> written;
    const std::string       &directory = parameters.output.directory;
    // Rank 0 writes the CSV files (each rank writes its VTU piece).
    const bool write_csv =
      write_files && (!Utilities::MPI::job_supports_mpi() ||
                      Utilities::MPI::this_mpi_process(communicator) == 0);
    try
      {
        if (write_files)
          std::filesystem::create_directories(directory);
        Triangulation<2>                     triangulation;
        std::unique_ptr<RefinementIndicator> indicator;
        parameters.mesh.build(triangulation);
        for (const auto &cell : triangulation.active_cell_iterators())
          parameters.materials.get(cell->material_id()); // throws if missing

        for (unsigned int cycle = 0;
             cycle < parameters.discretization.refinement_cycles;
             ++cycle)
          {
            if (cycle > 0)
              {
                if (parameters.adaptivity.strategy == "kelly")
                  {
                    std::set<types::boundary_id> interface_ids;
                    for (const auto &[id, law] : parameters.interfaces.laws)
                      interface_ids.insert(id);
                    indicator->refine(triangulation,
                                      parameters.adaptivity.refine_fraction,
                                      interface_ids);
                  }
                else
                  triangulation.refine_global(1);
              }
            indicator = std::make_unique<RefinementIndicator>(triangulation);
            for (const Harmonic &harmonic : parameters.discretization.harmonics)
              {
                try
                  {
                    HarmonicProblem problem(parameters,
                                            harmonic,
                                            triangulation,
                                            communicator);
                    Timer           timer;
                    problem.setup_system();
                    const double t_setup = timer.wall_time();
                    timer.restart();
                    problem.assemble_system();
                    const double t_assembly = timer.wall_time();
                    timer.restart();
                    const SolverReport report = problem.solve();
                    if (parameters.adaptivity.strategy == "kelly")
                      indicator->add_kelly(problem.get_dof_handler(),
                                           problem.get_solution());
                    const double t_solve = timer.wall_time();

                    const auto add = [&](const std::string &q,
                                         const double       v,
                                         const std::string &unit) {
                      results.add(q, harmonic, cycle, v, unit);
                    };
                    const double n_dofs = problem.get_dof_handler().n_dofs();
                    add("n_cells", triangulation.n_active_cells(), "-");
                    add("n_dofs", n_dofs, "-");
                    add("n_axis_nodes", problem.n_axis_nodes, "-");
                    add("solver_iterations", report.iterations, "-");
                    add("solver_relative_residual",
                        report.relative_residual,
                        "-");
                    add("strain_energy",
                        problem.strain_energy(problem.get_solution()),
                        "kJ");
                    add("time_setup", t_setup, "s");
                    add("time_assembly", t_assembly, "s");
                    add("time_solve", t_solve, "s");

                    std::ostringstream line;
                    line << "cycle " << cycle << ", " << harmonic.name() << ": "
                         << n_dofs << " dofs, " << report.method;
                    if (report.iterations > 0)
                      line << " (" << report.iterations << " it.)";
                    line << ", residual " << std::setprecision(2)
                         << report.relative_residual;

                    if (!parameters.boundary_conditions.dirichlet.empty())
                      {
                        const Vector<double> reactions =
                          problem.nodal_reactions();
                        for (const auto &[id, e] :
                             parameters.boundary_conditions.dirichlet)
                          {
                            const BoundaryResultant R =
                              problem.boundary_resultant(id, reactions);
                            const std::string b =
                              "_boundary_" + std::to_string(id);
                            add("reaction_force" + b, R.force, "kN");
                            add("reaction_moment" + b, R.moment, "kN.m");
                            add("reaction_work" + b, R.work, "kJ");
                            if (R.force != 0. || R.moment != 0.)
                              line << "\n    reactions on boundary " << id
                                   << ": force " << std::setprecision(6)
                                   << R.force << " kN, moment " << R.moment
                                   << " kN.m";
                          }
                      }
                    if (const RigidFoundation *foundation =
                          problem.get_foundation())
                      {
                        const RigidMotion m =
                          foundation->motion(problem.get_solution());
                        add("foundation_horizontal_displacement",
                            m.horizontal_displacement,
                            "m");
                        add("foundation_rotation", m.rotation, "rad");
                        add("foundation_vertical_displacement",
                            m.vertical_displacement,
                            "m");
                        add("foundation_twist", m.twist, "rad");
                        if (parameters.rigid_foundation
                              .stiffness_coefficients &&
                            harmonic.n == 1 &&
                            harmonic.family == Family::symmetric)
                          {
                            std::vector<Vector<double>>  unit_solutions;
                            const FoundationCoefficients c =
                              problem.foundation_coefficients(&unit_solutions);
                            // The scene's own load may be zero: let the
                            // unit-H and unit-M fields steer the mesh.
                            if (parameters.adaptivity.strategy == "kelly")
                              for (const auto &field : unit_solutions)
                                indicator->add_kelly(problem.get_dof_handler(),
                                                     field);
                            add("I_H", c.I_H, "-");
                            add("I_M", c.I_M, "-");
                            add("I_MH_from_H", c.I_MH_from_H, "-");
                            add("I_MH_from_M", c.I_MH_from_M, "-");
                            add("K_H", c.K_H, "-");
                            add("K_M", c.K_M, "-");
                            add("K_MH", c.K_MH, "-");
                            line << "\n    stiffness: K_H "
                                 << std::setprecision(6) << c.K_H << ", K_M "
                                 << c.K_M << ", K_MH " << c.K_MH
                                 << " (I_MH from H " << c.I_MH_from_H
                                 << ", from M " << c.I_MH_from_M << ")";
                          }
                        line << "\n    foundation: U_h " << std::setprecision(6)
                             << m.horizontal_displacement << " m, Theta "
                             << m.rotation << " rad, W "
                             << m.vertical_displacement << " m, Phi " << m.twist
                             << " rad";
                      }
                    if (parameters.exact_solution.enabled)
                      {
                        const ErrorNorms e = problem.compute_errors();
                        add("error_l2", e.l2, "m.m^1.5");
                        add("error_h1_seminorm", e.h1_seminorm, "m.m^0.5");
                        add("relative_error_l2", e.l2 / e.l2_exact, "-");
                        add("relative_error_h1",
                            e.h1_seminorm / e.h1_exact,
                            "-");
                        line << ", L2 error " << std::setprecision(4) << e.l2
                             << ", H1 error " << e.h1_seminorm;
                        if (cycle > 0)
                          {
                            const double rate_l2 = std::log2(
                              results.get("error_l2", harmonic, cycle - 1) /
                              e.l2);
                            const double rate_h1 =
                              std::log2(results.get("error_h1_seminorm",
                                                    harmonic,
                                                    cycle - 1) /
                                        e.h1_seminorm);
                            add("rate_l2", rate_l2, "-");
                            add("rate_h1", rate_h1, "-");
                            line << " (rates " << std::setprecision(3)
                                 << rate_l2 << ", " << rate_h1 << ")";
                          }
                      }
                    log << line.str() << std::endl;

                    if (write_files && parameters.output.write_vtu)
                      {
                        const std::string name =
                          directory + "/solution-n" +
                          std::to_string(harmonic.n) + "-" +
                          to_string(harmonic.family) + "-cycle" +
                          std::to_string(cycle) + ".vtu";
                        written.push_back(name);
                        problem.write_vtu(name);
                      }
                    if (write_csv && problem.get_interfaces())
                      for (const types::boundary_id id :
                           problem.get_interfaces()->boundary_ids())
                        {
                          const std::string name =
                            directory + "/interface-" + std::to_string(id) +
                            "-n" + std::to_string(harmonic.n) + "-" +
                            to_string(harmonic.family) + "-cycle" +
                            std::to_string(cycle) + ".csv";
                          written.push_back(name);
                          problem.get_interfaces()->write_csv(
                            id, problem.get_solution(), name);
                        }
                  }
                catch (const std::exception &e)
                  {
                    // Say which harmonic and cycle failed.
                    AssertThrow(false,
                                ExcMessage("cycle " + std::to_string(cycle) +
                                           ", " + harmonic.name() + ": " +
                                           one_line_message(e)));
                  }
              }
          }
        if (write_csv)
          {
            const std::string name =
              directory + "/" + parameters.output.results_file;
            written.push_back(name);
            results.write_csv(name);
            log << "results written to " << name << std::endl;
          }
      }
    catch (...)
      {
        for (const std::string &file : written)
          std::filesystem::remove(file);
        throw;
      }
    return results;
  }
} // namespace FourierSSI
