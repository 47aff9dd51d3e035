// Output of CoupledSolver: the interface state around the circumference
// (doc/nonlinear-interfaces.md section 9). The solve itself is in
// coupled_solver.cc.
#include <cmath>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/interface_state_surface.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <fstream>

namespace FourierSSI
{
  void
  CoupledSolver::write_interface_state_csv(const std::string &filename) const
  {
    const NonlinearInterfacePoints *interface = sources.interface_points();
    AssertThrow(interface != nullptr,
                ExcMessage(entry + ": the scene has no nonlinear interface"));
    interface->write_state_csv(filename,
                               interface_states(states.steps),
                               sources.interface_sampling());
  }

  void
  CoupledSolver::write_interface_state_vtu(const std::string &filename) const
  {
    const NonlinearInterfacePoints *interface = sources.interface_points();
    const ThetaSampling &interface_sampling   = sources.interface_sampling();
    AssertThrow(interface != nullptr && !states.steps.empty(),
                ExcMessage(entry + ": no converged interface state to write"));
    const InterfaceSnapshot &last = states.steps.back().interface_state;
    const std::vector<InterfacePoint> &points = interface->get_points();
    const unsigned int                 N      = interface_sampling.n_samples();
    // One point per (Gauss point, theta) sample, in the snapshot's order.
    std::vector<Point<3>>            positions;
    std::vector<std::vector<double>> values(3);
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int j = 0; j < N; ++j)
        positions.push_back(
          revolved_point(points[i].position, interface_sampling.angle(j)));
    for (unsigned int k = 0; k < positions.size(); ++k)
      {
        values[0].push_back(static_cast<int>(last.state[k]));
        for (unsigned int c = 0; c < 3; ++c)
          {
            values[1].push_back(last.traction[k][c]);
            values[2].push_back(last.relative[k][c]);
          }
      }
    write_point_samples_vtu(positions,
                            {{"state", 1},
                             {"traction_s_n_theta_kPa", 3},
                             {"relative_displacement_s_n_theta_m", 3}},
                            values,
                            filename);
  }

  ContactCounts
  CoupledSolver::write_interface_state_surface(
    const unsigned int step,
    const std::string &filename) const
  {
    const NonlinearInterfacePoints *interface = sources.interface_points();
    AssertThrow(interface != nullptr && step >= 1 &&
                  step <= states.steps.size(),
                ExcMessage("Output/Interface state steps: no converged "
                           "interface state of step " +
                           std::to_string(step)));
    return FourierSSI::write_interface_state_surface(
      *interface,
      states.steps[step - 1].interface_state,
      sources.interface_sampling(),
      filename);
  }
} // namespace FourierSSI
