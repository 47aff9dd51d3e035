// Helpers of the multi-surface sand element tests
// (coupled/multi_surface_sand.h, doc/derivations/multi_surface_sand.md): the
// law as Soil plasticity/Laws gives it, a point's moduli and isotropic
// geostatic stress, and a strain path driven through the return map with
// the elements' plastic strains committed after every step.
#ifndef fourier_ssi_tests_multi_surface_sand_test_support_h
#define fourier_ssi_tests_multi_surface_sand_test_support_h

#include "multi_surface_test_support.h"

#include <cmath>
#include <fourier_ssi/coupled/multi_surface_sand.h>
#include <string>
#include <vector>

namespace sand_test
{
  using namespace FourierSSI;

  /**
   * The sand of the tests: G0 = 30 MPa, nu = 0.25, p'0 = 100 kPa isotropic
   * (tension positive: sigma_0 = -100 1), c' = 2 kPa, phi' = 35 degrees.
   */
  constexpr double g0 = 30000., nu = 0.25, p0 = 100., cohesion = 2.;
  const double     bulk = 2. * g0 * (1. + nu) / (3. * (1. - 2. * nu));
  const double     phi  = 35. * M_PI / 180.;

  inline StrainVector
  isotropic_stress()
  {
    return {{-p0, -p0, -p0, 0., 0., 0.}};
  }

  /** The 'iwan-sand' law, parsed as the .prm gives it. */
  inline SoilLaw
  sand_law(const std::string &keys)
  {
    SoilPlasticityParameters p;
    p.parse_law_list("0: iwan-sand, c=2, phi=35, " + keys);
    return p.laws.at(0);
  }

  using multi_surface_test::simple_shear;

  /**
   * Isochoric triaxial strain along z, eps_q = |eps| (tension positive):
   * compression for eps > 0 (eps_z = -eps, eps_r = eps_theta = eps / 2).
   */
  inline StrainVector
  isochoric_triaxial(const double eps)
  {
    return {{0.5 * eps, -eps, 0.5 * eps, 0., 0., 0.}};
  }

  /** One sample: its elements' plastic strains, committed per step. */
  struct SandPoint
  {
    const MultiSurfaceSand   &law;
    StrainVector              initial_stress = isotropic_stress();
    std::vector<StrainVector> plastic =
      std::vector<StrainVector>(law.n_surfaces(),
                                StrainVector{{0., 0., 0., 0., 0., 0.}});

    /** The stress at `strain` from the committed state; commits. */
    MultiSurfaceStress
    step(const StrainVector &strain, StressTangent *tangent = nullptr)
    {
      std::vector<StrainVector> updated(plastic.size());
      const MultiSurfaceStress  r = law.return_map(strain,
                                                  initial_stress,
                                                  g0,
                                                  bulk,
                                                  0.,
                                                  plastic.data(),
                                                  updated.data(),
                                                  tangent);
      plastic                     = updated;
      return r;
    }

    /** The stress at `strain` from the committed state, not committed. */
    MultiSurfaceStress
    trial(const StrainVector &strain, StressTangent *tangent = nullptr) const
    {
      return law.return_map(
        strain, initial_stress, g0, bulk, 0., plastic.data(), nullptr, tangent);
    }
  };
} // namespace sand_test

#endif
