/**
 * The plastic field of one converged load step of plastic soil, and its VTU
 * files (doc/output-files.md, "The plastic field"): a meridian plane at an
 * angle theta (plastic-field-theta<deg>-step<s>.vtu), the soil revolved
 * about the axis (plastic-field-3d-step<s>.vtu), and a .pvd series of each
 * so that ParaView steps through the load path.
 *
 * The soil's state lives at its quadrature points and theta samples
 * (doc/soil-plasticity.md section 3). Here it is one value per soil cell and
 * theta sample: the r-weighted mean over the cell's points (plastic strain,
 * stress), the fraction of its points that yielded, the largest f. A plane
 * at theta shows the sample nearest to theta; a sector of the revolved mesh
 * the sample nearest to its middle. The displacement is the sum of the
 * harmonics at each vertex and angle (thesis eq. 3.1), exact at the
 * vertices (the vertex DoFs of FE_Q).
 *
 * Filled in by PlasticFieldRecorder (coupled layer); written here through
 * write_patches_vtu (vtu_output.h), cell values constant over each cell's
 * own vertices; the .pvd series by write_pvd_series (vtu_output.h).
 */
#ifndef fourier_ssi_plastic_field_output_h
#define fourier_ssi_plastic_field_output_h

#include <array>
#include <deal.II/base/point.h>
#include <fourier_ssi/input/harmonic.h>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** One soil cell's state at one theta sample. */
  struct PlasticCellValues
  {
    /** Mean equivalent plastic strain (plastic_field_recorder.h) [-]. */
    double plastic_strain = 0.;
    /** Mean equivalent plastic strain of the step's increment [-]. */
    double plastic_strain_increment = 0.;
    /** Fraction of the points whose return mapping yielded in the step. */
    double plastic_points = 0.;
    /** Fraction of the points with a plastic strain (eps_p != 0). */
    double yielded_points = 0.;
    /** The largest f(sigma) of the cell's points [kPa], <= 0 admissible. */
    double yield_value = 0.;
    /** Mean stress (r, z, theta, rz, ztheta, rtheta) [kPa], tension > 0. */
    std::array<double, 6> stress = {{0., 0., 0., 0., 0., 0.}};
  };

  /** A soil cell: its vertices and the harmonics' amplitudes there. */
  struct PlasticFieldCell
  {
    /** The cell's vertices (r, z), deal.II's lexicographic order. */
    std::array<Point<2>, 4> vertices;
    /** [v][h]: (u_r, u_z, u_theta) amplitude of harmonic h at vertex v. */
    std::array<std::vector<std::array<double, 3>>, 4> amplitudes;
  };

  struct PlasticFieldSnapshot
  {
    /** The load step (as in load-displacement.csv, from 1). */
    unsigned int step = 0;
    /** The harmonics of the amplitudes, in order. */
    std::vector<Harmonic> harmonics;
    /** N: the soil's theta samples are theta_j = 2 pi j / N. */
    unsigned int n_samples = 1;
    /** Plastic (point, theta) samples of the step, and all of them. */
    unsigned int                  n_plastic = 0, n_total = 0;
    std::vector<PlasticFieldCell> cells;
    /** [cell * n_samples + j]. */
    std::vector<PlasticCellValues> values;
  };

  /** The theta sample j nearest to the angle `degrees`. */
  unsigned int
  nearest_theta_sample(const unsigned int n_samples, const double degrees);

  /** The angle of the theta sample j [degrees]. */
  double
  theta_sample_degrees(const unsigned int n_samples, const unsigned int j);

  /** plastic-field-theta<deg>-step<s>.vtu (deg as Plastic field planes). */
  std::string
  plastic_field_plane_name(const double degrees, const unsigned int step);

  /** plastic-field-theta<deg>.pvd. */
  std::string
  plastic_field_plane_series(const double degrees);

  /** plastic-field-3d-step<s>.vtu. */
  std::string
  plastic_field_3d_name(const unsigned int step);

  /** plastic-field-3d.pvd. */
  std::string
  plastic_field_3d_series();

  /**
   * The meridian plane at `degrees` as quadrilaterals in 3D, (r cos theta,
   * r sin theta, z), with the values of the nearest theta sample and the
   * displacement at theta itself.
   */
  void
  write_plastic_field_plane(const PlasticFieldSnapshot &snapshot,
                            const double                degrees,
                            const std::string          &filename);

  /**
   * The soil cells revolved about the axis in `divisions` sectors centred
   * on theta_k = 360 k / divisions degrees (hexahedra, degenerate on the
   * axis), each with the values of the theta sample nearest to theta_k.
   */
  void
  write_plastic_field_revolved(const PlasticFieldSnapshot &snapshot,
                               const unsigned int          divisions,
                               const std::string          &filename);
} // namespace FourierSSI

#endif
