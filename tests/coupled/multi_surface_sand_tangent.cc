// The consistent tangent (S2) of the multi-surface sand
// (MultiSurfaceSand::return_map; doc/derivations/multi_surface_sand.md
// section 1) against central differences of the return map itself, along
// random 3D strain paths (all six components, N = 10 elements, psi = 10
// degrees: non-associated) from an anisotropic geostatic stress
// (sigma'_v = 100 kPa, K0 = 0.5), that load, unload and turn: elements
// elastic, on a plane, on an edge and at the apex are all met.
//
// Difference step h = 1e-9 on strains of order 1e-4. Within one return
// region of every element the return is smooth; the central difference
// errs by O(h^2) times the curvature, and round-off is 1e-16 x 1e5 kPa /
// 1e-9 = 1e-2 kPa, 3e-7 of G0 = 30 MPa. Tolerance: 1e-5 of G0 on every
// entry, above both and below what one element's missing term costs (its
// stiffness share >= 1e-3). A sample is used only if every element keeps
// its return region at both differenced points.
// Also: the law never leaves its Mohr-Coulomb surface (the overlay's sum
// is inside the cone, header): f(sigma) <= 1e-10 of p'0 at every step.
#include "check.h"
#include "multi_surface_sand_test_support.h"
#include "multi_surface_test_support.h"

#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <map>
#include <random>

using namespace sand_test;

namespace
{
  constexpr double h = 1e-9;

  /**
   * The return region of every element (elastic, plane, edge, apex), from
   * its own trial as (S1) makes it: two returns with the same key are in
   * one smooth piece of the law.
   */
  std::vector<SoilState>
  regions(const SandPoint &point, const StrainVector &strain)
  {
    std::vector<SoilState> key;
    for (unsigned int i = 0; i < point.law.n_surfaces(); ++i)
      {
        const double w = point.law.strength_share(i),
                     G = point.law.stiffness_share(i) * g0, K = w * bulk;
        SoilLaw element = sand_law("psi=10");
        element.kind    = SoilLaw::Kind::mohr_coulomb;
        element.cohesion *= w;
        StrainVector elastic;
        for (unsigned int c = 0; c < 6; ++c)
          elastic[c] = strain[c] - point.plastic[i][c];
        StrainVector trial = hooke_stress(elastic, K - 2. * G / 3., G);
        for (unsigned int c = 0; c < 6; ++c)
          trial[c] += w * point.initial_stress[c];
        key.push_back(
          SoilReturnMapping(element).return_map(trial, G, K, 0.).state);
      }
    return key;
  }

  /** Element returns met in the samples used, by region. */
  std::map<SoilState, unsigned int> element_regions;

  /** Largest |D - central difference| / G0, or < 0 if a region changes. */
  double
  tangent_error(const SandPoint &point, const StrainVector &strain)
  {
    StressTangent d;
    point.trial(strain, &d);
    const std::vector<SoilState> key   = regions(point, strain);
    double                       error = 0.;
    for (unsigned int b = 0; b < 6; ++b)
      {
        StrainVector plus = strain, minus = strain;
        plus[b] += h;
        minus[b] -= h;
        if (regions(point, plus) != key || regions(point, minus) != key)
          return -1.;
        const StrainVector up   = point.trial(plus).stress,
                           down = point.trial(minus).stress;
        for (unsigned int a = 0; a < 6; ++a)
          error =
            std::max(error,
                     std::abs(d[a * 6 + b] - (up[a] - down[a]) / (2. * h)));
      }
    for (const SoilState state : key)
      ++element_regions[state];
    return error / g0;
  }
} // namespace

int
main()
{
  const MultiSurfaceSand            sand(sand_law("psi=10, surfaces=10"));
  std::mt19937                      rng(11);
  std::normal_distribution<double>  step(0., 1.);
  double                            largest_f = -1e300;
  multi_surface_test::TangentErrors errors;
  for (unsigned int path = 0; path < 30; ++path)
    {
      SandPoint point{sand};
      point.initial_stress = {{-50., -100., -50., 0., 0., 0.}};
      StrainVector strain{};
      for (unsigned int k = 0; k < 25; ++k)
        {
          // From inside the first element's surface to far beyond the last.
          const double size = std::pow(10., -6. + 3. * (k % 5) / 4.);
          for (unsigned int a = 0; a < 6; ++a)
            strain[a] += size * step(rng);
          const double             error = tangent_error(point, strain);
          const MultiSurfaceStress r     = point.step(strain);
          largest_f =
            std::max(largest_f, sand.yield_function(r.stress, 0.) / p0);
          errors.add(error, r.n_yielding, sand.n_surfaces());
        }
    }
  errors.check(1e-5);
  const char *region[4] = {"elastic",
                           "on a plane",
                           "on an edge",
                           "at the apex"};
  for (const SoilState state :
       {SoilState::elastic, SoilState::plane, SoilState::edge, SoilState::apex})
    check::that(std::string("element returns ") +
                  region[static_cast<int>(state)] + ": at least 20 (" +
                  std::to_string(element_regions[state]) + ")",
                element_regions[state] >= 20);
  check::small("largest f(sigma) / p'0 along the paths (<= 0: admissible)",
               std::max(largest_f, 0.),
               1e-10);
  return check::summary();
}
