#include <cmath>
#include <fourier_ssi/coupled/interface_state_surface.h>
#include <fourier_ssi/postprocess/vtu_output.h>

namespace FourierSSI
{
  std::string
  interface_state_3d_name(const unsigned int step)
  {
    return "interface-state-3d-step" + std::to_string(step) + ".vtu";
  }

  std::string
  interface_state_3d_series()
  {
    return "interface-state-3d.pvd";
  }

  ContactCounts
  write_interface_state_surface(const NonlinearInterfacePoints &interface,
                                const InterfaceSnapshot        &state,
                                const ThetaSampling            &sampling,
                                const std::string              &filename)
  {
    const std::vector<InterfacePoint> &points = interface.get_points();
    const unsigned int                 N      = sampling.n_samples();
    AssertThrow(state.state.size() == points.size() * N,
                ExcMessage("Output/Interface state 3D: the snapshot has not "
                           "one value per point and theta sample"));
    const std::vector<VtuField>          fields = {{"state", 1},
                                                   {"t_n_kPa", 1},
                                                   {"t_s_kPa", 1},
                                                   {"t_theta_kPa", 1},
                                                   {"tau_kPa", 1},
                                                   {"d_n_m", 1},
                                                   {"d_s_m", 1},
                                                   {"d_theta_m", 1},
                                                   {"interface_id", 1},
                                                   {"point", 1},
                                                   {"theta_deg", 1}};
    std::vector<std::array<Point<3>, 4>> quads;
    std::vector<std::vector<double>>     values(fields.size());
    ContactCounts                        counts = {{0, 0, 0}};
    const double                         half   = numbers::PI / N;
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const std::array<Point<2>, 2> &share = points[i].share;
        const unsigned int id = interface.pair_of(points[i]).boundary_id;
        for (unsigned int j = 0; j < N; ++j)
          {
            const unsigned int k     = i * N + j;
            const double       theta = sampling.angle(j);
            // Around the quad: along the share at the sector's first angle,
            // back along it at the second.
            quads.push_back({{revolved_point(share[0], theta - half),
                              revolved_point(share[1], theta - half),
                              revolved_point(share[1], theta + half),
                              revolved_point(share[0], theta + half)}});
            const LocalVector &t = state.traction[k];
            const LocalVector &d = state.relative[k];
            const auto         s = static_cast<unsigned int>(state.state[k]);
            ++counts[s];
            // Local components (s, n, theta): t[1], d[1] are the normal.
            const double row[] = {static_cast<double>(s),
                                  t[1],
                                  t[0],
                                  t[2],
                                  std::hypot(t[0], t[2]),
                                  d[1],
                                  d[0],
                                  d[2],
                                  static_cast<double>(id),
                                  static_cast<double>(i),
                                  theta * 180. / numbers::PI};
            for (unsigned int f = 0; f < fields.size(); ++f)
              values[f].push_back(row[f]);
          }
      }
    write_quad_surface_vtu(quads, fields, values, filename);
    return counts;
  }
} // namespace FourierSSI
