// Output of CoupledInterfaceSolver: the load-displacement curve and the
// interface state around the circumference (doc/nonlinear-interfaces.md
// section 9). The solve itself is in coupled_interface_solver.cc.
#include <cmath>
#include <fourier_ssi/coupled/coupled_interface_solver.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/input/atomic_file.h>
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
    write_load_step_csv(filename,
                        steps,
                        parameters.rigid_foundation,
                        "stick,slip,open,time_s,harmonics,held_fraction",
                        [](std::ostream &out, const LoadStepResult &r) {
                          out << r.states[0] << ',' << r.states[1] << ','
                              << r.states[2] << ',' << r.time << ','
                              << r.n_harmonics << ',' << r.held_fraction;
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
    AtomicFile               file(filename);
    std::ostream            &out  = file.stream();
    const InterfaceSnapshot &last = snapshots.back();
    const unsigned int       N = sampling.n_samples(), P = points.size() * N;
    // One VTK_VERTEX (type 1) per (point, theta) sample.
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>"
           "\n<Piece NumberOfPoints=\""
        << P << "\" NumberOfCells=\"" << P << "\">\n"
        << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n"
        << std::setprecision(10);
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int j = 0; j < N; ++j)
        out << points[i].position[0] * std::cos(sampling.angle(j)) << ' '
            << points[i].position[0] * std::sin(sampling.angle(j)) << ' '
            << points[i].position[1] << '\n';
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int32\" "
           "Name=\"connectivity\" format=\"ascii\">\n";
    for (unsigned int k = 0; k < P; ++k)
      out << k << '\n';
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 0; k < P; ++k)
      out << k + 1 << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 0; k < P; ++k)
      out << "1\n";
    out << "</DataArray>\n</Cells>\n<PointData Scalars=\"state\">\n"
           "<DataArray type=\"Int32\" Name=\"state\" format=\"ascii\">\n";
    for (unsigned int k = 0; k < P; ++k)
      out << static_cast<int>(last.state[k]) << '\n';
    out << "</DataArray>\n";
    const auto vectors = [&](const std::string              &name,
                             const std::vector<LocalVector> &values) {
      out << "<DataArray type=\"Float64\" Name=\"" << name
          << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const LocalVector &v : values)
        out << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
      out << "</DataArray>\n";
    };
    vectors("traction_s_n_theta_kPa", last.traction);
    vectors("relative_displacement_s_n_theta_m", last.relative);
    out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    file.commit();
  }
} // namespace FourierSSI
