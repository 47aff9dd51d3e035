#include <cmath>
#include <deal.II/base/data_out_base.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/postprocess/plastic_field_output.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    /** The fields of both files, in the order of fill_row's rows. */
    const std::vector<VtuField> &
    plastic_fields()
    {
      static const std::vector<VtuField> fields = {{"displacement", 3},
                                                   {"u_r", 1},
                                                   {"u_theta", 1},
                                                   {"u_z", 1},
                                                   {"plastic_strain", 1},
                                                   {"plastic_strain_increment",
                                                    1},
                                                   {"plastic_points", 1},
                                                   {"yielded_points", 1},
                                                   {"yield_value", 1},
                                                   {"sigma_r", 1},
                                                   {"sigma_z", 1},
                                                   {"sigma_theta", 1},
                                                   {"tau_rz", 1},
                                                   {"tau_ztheta", 1},
                                                   {"tau_rtheta", 1}};
      return fields;
    }

    constexpr unsigned int n_rows = 17;

    /** (u_r, u_z, u_theta) at vertex v of a cell at angle theta [rad]. */
    std::array<double, 3>
    displacement_at(const PlasticFieldSnapshot &snapshot,
                    const PlasticFieldCell     &cell,
                    const unsigned int          v,
                    const double                theta)
    {
      std::array<double, 3> u = {{0., 0., 0.}};
      for (unsigned int h = 0; h < snapshot.harmonics.size(); ++h)
        {
          const double in_plane =
            theta_factor(snapshot.harmonics[h], ThetaFactor::in_plane, theta);
          const double around            = theta_factor(snapshot.harmonics[h],
                                             ThetaFactor::circumferential,
                                             theta);
          const std::array<double, 3> &a = cell.amplitudes[v][h];
          u[0] += a[0] * in_plane;
          u[1] += a[1] * in_plane;
          u[2] += a[2] * around;
        }
      return u;
    }

    /** The rows of one patch vertex: displacement, then the cell values. */
    template <int dim>
    void
    fill_vertex(DataOutBase::Patch<dim, 3>  &patch,
                const unsigned int           vertex,
                const std::array<double, 3> &u,
                const double                 theta,
                const PlasticCellValues     &values)
    {
      const double ct = std::cos(theta), st = std::sin(theta);
      const std::array<double, n_rows> rows = {{u[0] * ct - u[2] * st,
                                                u[0] * st + u[2] * ct,
                                                u[1],
                                                u[0],
                                                u[2],
                                                u[1],
                                                values.plastic_strain,
                                                values.plastic_strain_increment,
                                                values.plastic_points,
                                                values.yielded_points,
                                                values.yield_value,
                                                values.stress[0],
                                                values.stress[1],
                                                values.stress[2],
                                                values.stress[3],
                                                values.stress[4],
                                                values.stress[5]}};
      for (unsigned int r = 0; r < n_rows; ++r)
        patch.data(r, vertex) = rows[r];
    }

    /** The angle's text in a file name: as given (0, 90, 22.5). */
    std::string
    degrees_text(const double degrees)
    {
      std::ostringstream text;
      text << degrees;
      return text.str();
    }
  } // namespace

  unsigned int
  nearest_theta_sample(const unsigned int n_samples, const double degrees)
  {
    const double spacing = 360. / n_samples;
    return static_cast<unsigned int>(std::lround(degrees / spacing)) %
           n_samples;
  }

  double
  theta_sample_degrees(const unsigned int n_samples, const unsigned int j)
  {
    return 360. * j / n_samples;
  }

  std::string
  plastic_field_plane_name(const double degrees, const unsigned int step)
  {
    return "plastic-field-theta" + degrees_text(degrees) + "-step" +
           std::to_string(step) + ".vtu";
  }

  std::string
  plastic_field_plane_series(const double degrees)
  {
    return "plastic-field-theta" + degrees_text(degrees) + ".pvd";
  }

  std::string
  plastic_field_3d_name(const unsigned int step)
  {
    return "plastic-field-3d-step" + std::to_string(step) + ".vtu";
  }

  std::string
  plastic_field_3d_series()
  {
    return "plastic-field-3d.pvd";
  }

  void
  write_plastic_field_plane(const PlasticFieldSnapshot &snapshot,
                            const double                degrees,
                            const std::string          &filename)
  {
    const double       theta = degrees * numbers::PI / 180.;
    const unsigned int j = nearest_theta_sample(snapshot.n_samples, degrees);
    std::vector<DataOutBase::Patch<2, 3>> patches;
    for (unsigned int c = 0; c < snapshot.cells.size(); ++c)
      {
        const PlasticFieldCell  &cell = snapshot.cells[c];
        DataOutBase::Patch<2, 3> patch;
        patch.patch_index    = patches.size();
        patch.reference_cell = ReferenceCells::Quadrilateral;
        patch.data.reinit(n_rows, 4);
        for (unsigned int v = 0; v < 4; ++v)
          {
            const Point<2> &x = cell.vertices[v];
            patch.vertices[v] = revolved_point(x, theta);
            fill_vertex(patch,
                        v,
                        displacement_at(snapshot, cell, v, theta),
                        theta,
                        snapshot.values[c * snapshot.n_samples + j]);
          }
        patches.push_back(std::move(patch));
      }
    write_patches_vtu(patches, plastic_fields(), filename);
  }

  void
  write_plastic_field_revolved(const PlasticFieldSnapshot &snapshot,
                               const unsigned int          divisions,
                               const std::string          &filename)
  {
    const double                          sector = 2. * numbers::PI / divisions;
    std::vector<DataOutBase::Patch<3, 3>> patches;
    for (unsigned int k = 0; k < divisions; ++k)
      {
        const unsigned int j =
          nearest_theta_sample(snapshot.n_samples, 360. * k / divisions);
        // Patch vertices 0-3: the cell at the sector's first angle, 4-7 at
        // its second (deal.II's lexicographic order of a hexahedron).
        const double angles[2] = {(k - 0.5) * sector, (k + 0.5) * sector};
        for (unsigned int c = 0; c < snapshot.cells.size(); ++c)
          {
            const PlasticFieldCell  &cell = snapshot.cells[c];
            DataOutBase::Patch<3, 3> patch;
            patch.patch_index    = patches.size();
            patch.reference_cell = ReferenceCells::Hexahedron;
            patch.data.reinit(n_rows, 8);
            for (unsigned int v = 0; v < 8; ++v)
              {
                const double theta = angles[v / 4];
                patch.vertices[v] = revolved_point(cell.vertices[v % 4], theta);
                fill_vertex(patch,
                            v,
                            displacement_at(snapshot, cell, v % 4, theta),
                            theta,
                            snapshot.values[c * snapshot.n_samples + j]);
              }
            patches.push_back(std::move(patch));
          }
      }
    write_patches_vtu(patches, plastic_fields(), filename);
  }
} // namespace FourierSSI
