#include <chrono>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/interface_state_surface.h>
#include <fourier_ssi/driver/interface_state_output.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <utility>
#include <vector>

namespace FourierSSI
{
  InterfaceStateCsv::InterfaceStateCsv(const std::string &description)
    : description(description)
  {}

  void
  InterfaceStateCsv::write_files(const CoupledSolver     &solver,
                                 const CoupledRunContext &context,
                                 std::ostream            &log)
  {
    if (!context.writes_csv || !solver.has_nonlinear_interfaces())
      return;
    const std::string state = context.result_files.claim("interface-state.csv");
    solver.write_interface_state_csv(state);
    log << description << " written to " << state << std::endl;
  }

  void
  InterfaceState3d::check(const CoupledSolver     &solver,
                          const CoupledRunContext &context) const
  {
    const OutputParameters          &output = context.parameters.output;
    const std::vector<unsigned int> &chosen = output.interface_state_steps;
    const auto n_steps = static_cast<unsigned int>(solver.get_steps().size());
    if (!output.interface_state_3d || chosen.empty())
      return;
    AssertThrow(chosen.back() <= n_steps,
                ExcMessage("Output/Interface state steps: step " +
                           std::to_string(chosen.back()) +
                           " lies beyond the load path, which has " +
                           std::to_string(n_steps) + " converged steps"));
  }

  void
  InterfaceState3d::write_files(const CoupledSolver     &solver,
                                const CoupledRunContext &context,
                                std::ostream            &log)
  {
    if (!context.writes_csv || !solver.has_nonlinear_interfaces())
      return;
    if (context.parameters.output.write_3d_vtu)
      {
        const std::string vtu =
          context.result_files.claim("interface-state-3d.vtu");
        solver.write_interface_state_vtu(vtu);
        log << "interface state of the last step (3D points) written to " << vtu
            << std::endl;
      }
    write_surfaces(solver, context, log);
  }

  void
  InterfaceState3d::write_surfaces(const CoupledSolver     &solver,
                                   const CoupledRunContext &context,
                                   std::ostream            &log) const
  {
    const OutputParameters &output = context.parameters.output;
    if (!output.interface_state_3d)
      return;
    const auto                start = std::chrono::steady_clock::now();
    std::vector<unsigned int> steps = output.interface_state_steps;
    if (steps.empty())
      steps = {static_cast<unsigned int>(solver.get_steps().size())};
    std::vector<std::pair<double, std::string>> series;
    log << "interface state in 3D (quads of point x theta sample) of";
    for (const unsigned int step : steps)
      {
        const std::string   name   = interface_state_3d_name(step);
        const ContactCounts counts = solver.write_interface_state_surface(
          step, context.result_files.claim(name));
        series.emplace_back(step, name);
        log << (step == steps.front() ? " step " : ", step ") << step << " ("
            << counts[0] << '/' << counts[1] << '/' << counts[2]
            << " stick/slip/open)";
      }
    write_pvd_series(series,
                     context.result_files.claim(interface_state_3d_series()));
    log << " written to " << output.directory
        << "/interface-state-3d-step*.vtu and interface-state-3d.pvd; "
        << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
             .count()
        << " s" << std::endl;
  }
} // namespace FourierSSI
