// Output of CoupledInterfaceSolver: the load-displacement curve and the
// interface state around the circumference (doc/nonlinear-interfaces.md
// section 9). The solve itself is in coupled_interface_solver.cc.
#include <cmath>
#include <fourier_ssi/coupled/coupled_interface_solver.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <fstream>
#include <iomanip>

namespace FourierSSI
{
  namespace
  {
    const std::string entry_name = "Load path";

  } // namespace

  void
  CoupledInterfaceSolver::write_csv(const std::string &filename) const
  {
    // The loads that hold the held motions, or a direction probe's H and M.
    write_load_step_csv(
      filename,
      steps,
      parameters.rigid_foundation,
      "stick,slip,open,time_s,harmonics,held_fraction" +
        (steps.empty() ? std::string() :
                         held_reaction_columns(parameters.rigid_foundation,
                                               steps.back().held_reactions)),
      [](std::ostream &out, const LoadStepResult &r) {
        out << r.states[0] << ',' << r.states[1] << ',' << r.states[2] << ','
            << r.time << ',' << r.n_harmonics << ',' << r.held_fraction;
        for (const auto &reaction : r.held_reactions)
          out << ',' << reaction.second;
      });
  }

  void
  CoupledInterfaceSolver::write_interface_state_csv(
    const std::string &filename) const
  {
    interface.write_state_csv(filename, snapshots, sampling);
  }

  void
  CoupledInterfaceSolver::write_interface_state_vtu(
    const std::string &filename) const
  {
    AssertThrow(!snapshots.empty(),
                ExcMessage(entry_name + ": no converged step to write"));
    const InterfaceSnapshot &last = snapshots.back();
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
