#include <fourier_ssi/input/initial_stress_parameters.h>

namespace FourierSSI
{
  void
  InitialStressParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial stress");
    prm.declare_entry("Effective unit weight",
                      "0",
                      Patterns::Double(0.),
                      "gamma' [kN/m^3] of the (dry or submerged) soil: "
                      "sigma'_v = Surcharge + gamma' depth below "
                      "Materials/Ground surface elevation, acting on the "
                      "coulomb interfaces as their initial normal stress and "
                      "in plastic soil as its initial stress (Mohr-Coulomb "
                      "strength). 0 with Surcharge 0: none. The state is in "
                      "equilibrium by construction and is not a load.");
    prm.declare_entry("Surcharge",
                      "0",
                      Patterns::Double(0.),
                      "q [kPa]: a uniform vertical effective stress at the "
                      "ground surface (a fill, or the confining stress of a "
                      "laboratory test): sigma'_v = q + gamma' depth.");
    prm.declare_entry("K0",
                      "0.5",
                      Patterns::Double(0.),
                      "Coefficient of earth pressure at rest [-]: "
                      "sigma'_h = K0 sigma'_v (vertical interface faces; "
                      "the radial and circumferential stress of the soil).");
    prm.leave_subsection();
  }

  void
  InitialStressParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial stress");
    unit_weight                = prm.get_double("Effective unit weight");
    surcharge                  = prm.get_double("Surcharge");
    earth_pressure_coefficient = prm.get_double("K0");
    prm.leave_subsection();
  }

  double
  InitialStressParameters::vertical_stress(const double depth) const
  {
    return depth < 0. ? 0. : surcharge + unit_weight * depth;
  }
} // namespace FourierSSI
