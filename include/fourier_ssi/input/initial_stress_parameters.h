/**
 * Subsection "Initial stress" of the .prm file: the geostatic effective
 * stress of dry or submerged soil under a surcharge, sigma'_v = q + gamma'
 * depth and sigma'_h = K0 sigma'_v (coupled/initial_stress.h says how the
 * interfaces and the plastic soil take it).
 */
#ifndef fourier_ssi_initial_stress_parameters_h
#define fourier_ssi_initial_stress_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace FourierSSI
{
  using namespace dealii;

  /** Subsection "Initial stress" of the .prm file. */
  struct InitialStressParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** gamma' [kN/m^3]. */
    double unit_weight = 0.;
    /** q [kPa]: sigma'_v at the ground surface. */
    double surcharge = 0.;
    /** K0 [-]: sigma'_h / sigma'_v. */
    double earth_pressure_coefficient = 0.5;

    /** False (gamma' = q = 0): no initial stress. */
    bool
    enabled() const
    {
      return unit_weight > 0. || surcharge > 0.;
    }

    /** sigma'_v [kPa] (compression positive) at a depth; 0 above ground. */
    double
    vertical_stress(const double depth) const;
  };
} // namespace FourierSSI

#endif
