// Output of CoupledInterfaceSolver: the interface state around the
// circumference (doc/nonlinear-interfaces.md section 9). The solve itself is in
// coupled_interface_solver.cc.
#include <cmath>
#include <fourier_ssi/coupled/coupled_interface_solver.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <fstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry_name = "Load path";

  } // namespace

  void
  CoupledInterfaceSolver::write_interface_state_csv(
    const std::string &filename) const
  {
    interface.write_state_csv(filename, interface_states(steps), sampling);
  }

  void
  CoupledInterfaceSolver::write_interface_state_vtu(
    const std::string &filename) const
  {
    AssertThrow(!steps.empty(),
                ExcMessage(entry_name + ": no converged step to write"));
    const InterfaceSnapshot &last = steps.back().interface_state;
    const unsigned int       N    = sampling.n_samples();
    // One point per (Gauss point, theta) sample, in the snapshot's order.
    std::vector<Point<3>>            positions;
    std::vector<std::vector<double>> values(3);
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int j = 0; j < N; ++j)
        positions.emplace_back(points[i].position[0] *
                                 std::cos(sampling.angle(j)),
                               points[i].position[0] *
                                 std::sin(sampling.angle(j)),
                               points[i].position[1]);
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
} // namespace FourierSSI
