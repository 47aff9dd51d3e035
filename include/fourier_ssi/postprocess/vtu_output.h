/**
 * The one way fourier-ssi writes a VTU file: deal.II's DataOutBase::write_vtu
 * (the writer behind DataOut::write_vtu, which the per-harmonic output uses),
 * fed with patches built here for the outputs that are not a finite-element
 * field on the 2D mesh: the mesh revolved about the axis
 * (FieldReconstruction) and the interface samples as 3D points
 * (CoupledSolver). The file is written through AtomicFile.
 */
#ifndef fourier_ssi_vtu_output_h
#define fourier_ssi_vtu_output_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/point.h>
#include <string>
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
} // namespace FourierSSI

#endif
