// Helpers of the multi-surface clay element tests
// (coupled/multi_surface_clay.h, doc/derivations/multi_surface_clay.md): the
// law as Soil plasticity/Laws gives it, the strain of simple shear and of
// undrained triaxial compression, and a strain path driven through the return
// map with the state committed after every step.
#ifndef fourier_ssi_tests_multi_surface_clay_test_support_h
#define fourier_ssi_tests_multi_surface_clay_test_support_h

#include "multi_surface_test_support.h"

#include <cmath>
#include <fourier_ssi/coupled/multi_surface_clay.h>
#include <string>
#include <vector>

namespace clay_test
{
  using namespace FourierSSI;

  /**
   * The clay of the tests: G0 = 11000 kPa, gamma_ref = 1e-3, s_u = 10 kPa,
   * so G0 gamma_ref = 11 kPa and the hyperbola reaches s_u at
   * u_f = s_u / (G0 gamma_ref - s_u) = 10 (eq. B2): the backbone is the pure
   * hyperbola up to 10 gamma_ref, the range the acceptance asks for.
   * K from nu = 0.49 (undrained).
   */
  constexpr double g0 = 11000., gamma_ref = 1e-3, su = 10., nu = 0.49;
  const double     bulk = 2. * g0 * (1. + nu) / (3. * (1. - 2. * nu));

  /** The 'iwan' law with N surfaces, parsed as the .prm gives it. */
  inline SoilLaw
  iwan_law(const unsigned int n_surfaces, const std::string &extra = "")
  {
    SoilPlasticityParameters p;
    p.parse_law_list("0: iwan, su=10, gref=0.001, surfaces=" +
                     std::to_string(n_surfaces) + extra);
    return p.laws.at(0);
  }

  inline MultiSurfaceClay
  clay(const unsigned int n_surfaces)
  {
    return MultiSurfaceClay(iwan_law(n_surfaces), g0, bulk, 0.);
  }

  using multi_surface_test::simple_shear;

  /**
   * Undrained (isochoric) triaxial compression along z of axial strain
   * eps_a > 0 (tension positive: eps_z = -eps_a, eps_r = eps_theta =
   * eps_a / 2). Its deviatoric strain has norm sqrt(3/2) eps_a, that of
   * simple shear gamma / sqrt(2): the same element state at
   * gamma = sqrt(3) eps_a.
   */
  inline StrainVector
  triaxial_compression(const double eps_a)
  {
    return {{0.5 * eps_a, -eps_a, 0.5 * eps_a, 0., 0., 0.}};
  }

  /** Drives `law` through the strains, committing after each; the returns. */
  inline std::vector<MultiSurfaceReturn>
  drive(const MultiSurfaceClay &law, const std::vector<StrainVector> &path)
  {
    std::vector<MultiSurfaceReturn> returns;
    MultiSurfaceState               state = law.initial_state();
    for (const StrainVector &strain : path)
      {
        returns.push_back(law.return_map(strain, state));
        state = returns.back().plastic_strains;
      }
    return returns;
  }

  /** n equally spaced strains after a, up to b (a excluded, b included). */
  inline std::vector<double>
  strains_between(const double a, const double b, const unsigned int n)
  {
    std::vector<double> g(n);
    for (unsigned int k = 1; k <= n; ++k)
      g[k - 1] = a + (b - a) * k / n;
    return g;
  }

  /** The error estimate dpsi^2 / 4 of the fit (derivation section 3). */
  inline double
  estimated_fit_error(const unsigned int n_surfaces, const double u_fail)
  {
    const double dpsi = 2. * std::atan(std::sqrt(u_fail)) / (n_surfaces - 1.);
    return dpsi * dpsi / 4.;
  }
} // namespace clay_test

#endif
