/**
 * Regularity conditions on the symmetry axis r = 0 for harmonic n (proof in
 * doc/theory.md): a smooth 3D displacement field has Fourier amplitudes with
 *   n = 0: U = 0 (symmetric/axisymmetric), W = 0 (antisymmetric/torsion);
 *   n = 1: V = 0 and W = -U (symmetric) or W = +U (antisymmetric);
 *   n >= 2: U = V = W = 0.
 * Also for n = 0 the component that carries no stiffness (W in the
 * symmetric family, U and V in the antisymmetric one) is set to zero
 * everywhere, so the system is never singular.
 */
#ifndef fourier_ssi_axis_constraints_h
#define fourier_ssi_axis_constraints_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <fourier_ssi/input/harmonic.h>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * Add the axis and n = 0 conditions to `constraints`, skipping DoFs that
   * are already constrained (Dirichlet data or hanging nodes win). DoFs whose
   * support point has r <= axis_tolerance are on the axis.
   * Returns the number of axis nodes found.
   */
  unsigned int
  add_axis_constraints(const DoFHandler<2>       &dof_handler,
                       const Harmonic            &harmonic,
                       const double               axis_tolerance,
                       AffineConstraints<double> &constraints);
} // namespace FourierSSI

#endif
