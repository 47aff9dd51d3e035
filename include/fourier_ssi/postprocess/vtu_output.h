/**
 * The one way fourier-ssi writes a VTU file: deal.II's DataOutBase::write_vtu
 * (the writer behind DataOut::write_vtu, which the per-harmonic output uses),
 * fed with patches built here for the outputs that are not a finite-element
 * field on the 2D mesh: the mesh revolved about the axis
 * (FieldReconstruction) and the interface samples as 3D points
 * (CoupledSolver). The file is written through AtomicFile.
 *
 * DataOutBase writes Float32 (7 digits): enough to look at, not to compare
 * with the CSV a run also writes. The interface state as a revolved surface
 * (interface_state_surface.h) is such a comparison, so its quads are written
 * by write_quad_surface_vtu in Float64, with true cell data.
 */
#ifndef fourier_ssi_vtu_output_h
#define fourier_ssi_vtu_output_h

#include <array>
#include <cmath>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/point.h>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** A point field of a VTU file: a scalar (1) or a vector (3 components). */
  struct VtuField
  {
    std::string  name;
    unsigned int n_components;
  };

  /**
   * Write the patches, whose data rows are the fields' components in order
   * (one row per scalar, three rows per vector), to filename.
   */
  template <int dim>
  void
  write_patches_vtu(const std::vector<DataOutBase::Patch<dim, 3>> &patches,
                    const std::vector<VtuField>                   &fields,
                    const std::string                             &filename);

  /**
   * One VTK_VERTEX cell per point; values[f] holds field f's components
   * point after point (n_points x n_components numbers).
   */
  void
  write_point_samples_vtu(const std::vector<Point<3>>            &points,
                          const std::vector<VtuField>            &fields,
                          const std::vector<std::vector<double>> &values,
                          const std::string                      &filename);

  /**
   * The point (r, z) of the meridian plane at the angle theta [rad] in 3D:
   * (r cos theta, r sin theta, z), the one map of every revolved output.
   */
  inline Point<3>
  revolved_point(const Point<2> &x, const double theta)
  {
    return Point<3>(x[0] * std::cos(theta), x[0] * std::sin(theta), x[1]);
  }

  /**
   * A surface of quadrilaterals in 3D (VTK_QUAD, vertices in the order
   * around the quad), every number in Float64 (base64, uncompressed) and
   * the fields as cell data: values[f] holds field f's components quad
   * after quad (n_quads x n_components numbers).
   */
  void
  write_quad_surface_vtu(const std::vector<std::array<Point<3>, 4>> &quads,
                         const std::vector<VtuField>                &fields,
                         const std::vector<std::vector<double>>     &values,
                         const std::string                          &filename);

  /** A .pvd series: (step, file name in the same folder) in order. */
  void
  write_pvd_series(const std::vector<std::pair<double, std::string>> &steps,
                   const std::string                                 &filename);
} // namespace FourierSSI

#endif
