#include <fourier_ssi/initial_stress.h>

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
                      "sigma'_v = gamma' depth below Materials/Ground surface "
                      "elevation, acting on the interfaces as their initial "
                      "normal stress (Coulomb strength). 0: none. The state "
                      "is in equilibrium by construction and is not a load.");
    prm.declare_entry("K0",
                      "0.5",
                      Patterns::Double(0.),
                      "Coefficient of earth pressure at rest [-]: "
                      "sigma'_h = K0 sigma'_v (vertical interface faces).");
    prm.leave_subsection();
  }

  void
  InitialStressParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial stress");
    unit_weight                = prm.get_double("Effective unit weight");
    earth_pressure_coefficient = prm.get_double("K0");
    prm.leave_subsection();
  }

  LocalVector
  InitialStressParameters::interface_traction(const Tensor<1, 2> &tangent,
                                              const Tensor<1, 2> &normal,
                                              const double        depth) const
  {
    const double vertical   = unit_weight * std::max(depth, 0.);
    const double horizontal = earth_pressure_coefficient * vertical;
    const double t_s        = -(tangent[0] * normal[0] * horizontal +
                         tangent[1] * normal[1] * vertical);
    const double t_n =
      -(normal[0] * normal[0] * horizontal + normal[1] * normal[1] * vertical);
    return {{t_s, t_n, 0.}};
  }
} // namespace FourierSSI
