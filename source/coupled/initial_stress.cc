#include <fourier_ssi/coupled/initial_stress.h>

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

  LocalVector
  InitialStressParameters::interface_traction(const Tensor<1, 2> &tangent,
                                              const Tensor<1, 2> &normal,
                                              const double        depth) const
  {
    const double vertical   = vertical_stress(depth);
    const double horizontal = earth_pressure_coefficient * vertical;
    const double t_s        = -(tangent[0] * normal[0] * horizontal +
                         tangent[1] * normal[1] * vertical);
    const double t_n =
      -(normal[0] * normal[0] * horizontal + normal[1] * normal[1] * vertical);
    return {{t_s, t_n, 0.}};
  }

  double
  InitialStressParameters::vertical_stress(const double depth) const
  {
    return depth < 0. ? 0. : surcharge + unit_weight * depth;
  }

  StrainVector
  InitialStressParameters::soil_stress(const double depth) const
  {
    const double vertical   = vertical_stress(depth);
    const double horizontal = earth_pressure_coefficient * vertical;
    return {{-horizontal, -vertical, -horizontal, 0., 0., 0.}};
  }
} // namespace FourierSSI
