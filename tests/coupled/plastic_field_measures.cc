// The measures of the plastic field (include/fourier_ssi/coupled/
// plastic_field_recorder.h, doc/output-files.md "The plastic field")
// against values worked out by hand:
//  * eps_eq = sqrt(2/3 e_p : e_p) of an isochoric uniaxial plastic strain
//    (e, -e/2, -e/2) is |e|; of a pure engineering shear gamma (one
//    component) it is gamma / sqrt(3) (e_p : e_p = 2 (gamma/2)^2); a
//    volumetric strain (e, e, e) has none;
//  * compliance_strain (stress_postprocessor.h) undoes hooke_stress: the
//    strain comes back to 1e-15 (round-off of two 3 x 3 maps);
//  * a uniaxial stress s gives the strain s/E and -nu s/E across, E and nu
//    from lambda and mu (Timoshenko's isotropic relations).
#include "check.h"

#include <cmath>
#include <fourier_ssi/coupled/plastic_field_recorder.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>

using namespace FourierSSI;

int
main()
{
  const double e = 3e-3, gamma = 2e-3;
  check::relative("uniaxial isochoric: eps_eq = |e|",
                  equivalent_plastic_strain({{e, -e / 2, -e / 2, 0., 0., 0.}}),
                  e,
                  1e-14);
  check::relative("pure shear: eps_eq = gamma / sqrt(3)",
                  equivalent_plastic_strain({{0., 0., 0., 0., gamma, 0.}}),
                  gamma / std::sqrt(3.),
                  1e-14);
  check::small("volumetric strain: eps_eq = 0",
               equivalent_plastic_strain({{e, e, e, 0., 0., 0.}}),
               1e-15 * e);

  const double       lambda = 1500., mu = 1000.;
  const StrainVector strain = {{1e-3, -2e-3, 5e-4, 3e-3, -1e-3, 2e-4}};
  const StrainVector back =
    compliance_strain(hooke_stress(strain, lambda, mu), lambda, mu);
  double error = 0.;
  for (unsigned int k = 0; k < 6; ++k)
    error = std::max(error, std::abs(back[k] - strain[k]));
  check::small("compliance_strain(hooke_stress(eps)) - eps", error, 1e-15);

  const double       young = mu * (3. * lambda + 2. * mu) / (lambda + mu);
  const double       nu    = lambda / (2. * (lambda + mu));
  const double       s     = 12.;
  const StrainVector uniaxial =
    compliance_strain({{s, 0., 0., 0., 0., 0.}}, lambda, mu);
  check::relative("uniaxial stress: eps_r = s / E",
                  uniaxial[0],
                  s / young,
                  1e-14);
  check::relative("uniaxial stress: eps_z = -nu s / E",
                  uniaxial[1],
                  -nu * s / young,
                  1e-14);
  return check::summary();
}
