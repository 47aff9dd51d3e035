#include <fourier_ssi/coupled/initial_stress.h>

namespace FourierSSI
{
  LocalVector
  initial_interface_traction(const InitialStressParameters &initial_stress,
                             const Tensor<1, 2>            &tangent,
                             const Tensor<1, 2>            &normal,
                             const double                   depth)
  {
    const double vertical = initial_stress.vertical_stress(depth);
    const double horizontal =
      initial_stress.earth_pressure_coefficient * vertical;
    const double t_s = -(tangent[0] * normal[0] * horizontal +
                         tangent[1] * normal[1] * vertical);
    const double t_n =
      -(normal[0] * normal[0] * horizontal + normal[1] * normal[1] * vertical);
    return {{t_s, t_n, 0.}};
  }

  StrainVector
  initial_soil_stress(const InitialStressParameters &initial_stress,
                      const double                   depth)
  {
    const double vertical = initial_stress.vertical_stress(depth);
    const double horizontal =
      initial_stress.earth_pressure_coefficient * vertical;
    return {{-horizontal, -vertical, -horizontal, 0., 0., 0.}};
  }
} // namespace FourierSSI
