/**
 * How stiff the coulomb interfaces of a mesh are against the soil beside
 * them: the dimensionless penalty max(kn, ks) l / G that decides the
 * interface-only linearisation and theta samples
 * (InterfaceParameters::is_stiff, doc/nonlinear-interfaces.md section 5b).
 */
#ifndef fourier_ssi_interface_penalty_ratio_h
#define fourier_ssi_interface_penalty_ratio_h

#include <deal.II/grid/tria.h>
#include <fourier_ssi/input/interface_parameters.h>
#include <fourier_ssi/input/material.h>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * The largest max(kn, ks) l / G over the faces of the coulomb interfaces
   * of `triangulation`: l the interface's mean face length and G the shear
   * modulus, at the face centre's depth, of the face's own cell (or of the
   * law's `material`), so that over both twins of a pair the softer side
   * counts, as in InterfaceIntegrator. kn = auto counts as
   * automatic_interface_stiffness. 0 without coulomb interfaces.
   */
  double
  coulomb_penalty_ratio(const InterfaceParameters &interfaces,
                        const MaterialLibrary     &materials,
                        const Triangulation<2>    &triangulation);
} // namespace FourierSSI

#endif
