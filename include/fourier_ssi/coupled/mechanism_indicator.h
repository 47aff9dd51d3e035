/**
 * Where a coupled run's mesh is refined next (Adaptivity/Strategy = kelly
 * with plastic soil or coulomb interfaces, doc/accuracy-vs-time.md section
 * "Coupled scenes"): the Kelly indicator of the mechanism, the displacement
 * increment of the last converged step, taken over the whole body of
 * revolution. A harmonic's field varies as cos(n theta) or sin(n theta),
 * so the theta integral of a squared 3D gradient jump is
 *   int_0^2pi |[grad du]|^2 dtheta = sum_h w_n |[grad du_h]|^2,
 *   w_0 = 2 pi, w_n = pi (n >= 1),
 * and a cell's indicator is eta_K = (sum_h w_n eta_K,h^2)^(1/2), eta_K,h
 * Kelly's indicator of harmonic h's increment (KellyErrorEstimator). Unlike
 * the linear cycles' indicator (each harmonic normalised alone, adaptivity.h)
 * the harmonics keep their own magnitudes: a harmonic that carries little of
 * the mechanism steers the mesh little.
 */
#ifndef fourier_ssi_mechanism_indicator_h
#define fourier_ssi_mechanism_indicator_h

#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/harmonic/harmonic_set.h>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * eta_K per active cell of the set's mesh from the solver's last step
   * (a collective under MPI: every rank gets the same indicators).
   */
  Vector<float>
  mechanism_indicators(const HarmonicSet &set, const CoupledSolver &solver);
} // namespace FourierSSI

#endif
