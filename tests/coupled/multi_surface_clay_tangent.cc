// The consistent tangent (C3) of the multi-surface clay
// (MultiSurfaceClay::return_map_with_tangent; doc/derivations/
// multi_surface_clay.md section 1) against central differences of the
// return map itself, along random 3D strain paths (all six components,
// N = 10 elements, K from nu = 0.49) that load, unload and turn, so that
// the committed states have plastic strains in every direction and every
// count of yielding elements is met: none, some, all.
//
// Difference step h = 1e-8 on strains of order gamma_ref = 1e-3. Within
// one yield pattern the return is smooth; central differences err by
// O((h / |e - e^p_i|)^2) G_i, and |e - e^p_i| of a yielding element is at
// least its yield strain over sqrt(2) (>= 7e-6 here, that element's G_i is
// 0.04 G0): <= 1e-7 G0. Round-off: 1e-16 x 5000 kPa (K tr eps) / 1e-8 =
// 5e-5 kPa, 5e-9 of G0 = 11000 kPa. Measured: <= 6e-8 of G0. Tolerance:
// 1e-6 of G0 on every entry, above both and far below what one missing
// element term costs (its G_i >= 1e-3 G0). A sample is used only if every
// element keeps its state (elastic or yielding) at both differenced points.
// Also: the tangent is symmetric (associated flow, 1e-12 of G0).
#include "check.h"
#include "multi_surface_clay_test_support.h"
#include "multi_surface_test_support.h"

#include <random>

using namespace clay_test;

namespace
{
  constexpr double h = 1e-8;

  /** Which elements yield in a return (the plastic strain moved). */
  std::vector<bool>
  yield_pattern(const MultiSurfaceReturn &r, const MultiSurfaceState &committed)
  {
    std::vector<bool> yielding(committed.size());
    for (unsigned int i = 0; i < committed.size(); ++i)
      yielding[i] = r.plastic_strains[i] != committed[i];
    return yielding;
  }

  /**
   * Largest |D - central difference| / G0 at (strain, committed), or a
   * negative number if a differenced point changes the yield pattern.
   */
  double
  tangent_error(const MultiSurfaceClay  &law,
                const StrainVector      &strain,
                const MultiSurfaceState &committed,
                double                  &asymmetry)
  {
    StressTangent            d;
    const MultiSurfaceReturn at =
      law.return_map_with_tangent(strain, committed, d);
    const std::vector<bool> pattern = yield_pattern(at, committed);
    double                  error   = 0.;
    for (unsigned int b = 0; b < 6; ++b)
      {
        StrainVector plus = strain, minus = strain;
        plus[b] += h;
        minus[b] -= h;
        const MultiSurfaceReturn up   = law.return_map(plus, committed),
                                 down = law.return_map(minus, committed);
        if (yield_pattern(up, committed) != pattern ||
            yield_pattern(down, committed) != pattern)
          return -1.;
        for (unsigned int a = 0; a < 6; ++a)
          error =
            std::max(error,
                     std::abs(d[a * 6 + b] -
                              (up.stress[a] - down.stress[a]) / (2. * h)));
      }
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < a; ++b)
        asymmetry = std::max(asymmetry, std::abs(d[a * 6 + b] - d[b * 6 + a]));
    return error / g0;
  }

  /** Random paths; the worst error per class of yielding count. */
  void
  check_random_paths()
  {
    const MultiSurfaceClay            law = clay(10);
    const unsigned int                n   = law.n_surfaces();
    std::mt19937                      rng(7);
    std::normal_distribution<double>  step(0., 2. * gamma_ref);
    double                            asymmetry = 0.;
    multi_surface_test::TangentErrors errors;
    for (unsigned int path = 0; path < 40; ++path)
      {
        MultiSurfaceState state = law.initial_state();
        StrainVector      strain{};
        for (unsigned int k = 0; k < 25; ++k)
          {
            // Steps of random size and direction: from inside the smallest
            // surface to beyond the largest.
            const double size = std::pow(10., -3. + 3. * (k % 5) / 4.);
            for (unsigned int a = 0; a < 6; ++a)
              strain[a] += size * step(rng);
            const double error = tangent_error(law, strain, state, asymmetry);
            const MultiSurfaceReturn r = law.return_map(strain, state);
            errors.add(error, r.n_yielding, n);
            state = r.plastic_strains;
          }
      }
    errors.check(1e-6);
    check::small("asymmetry of D / G0", asymmetry / g0, 1e-12);
  }
} // namespace

int
main()
{
  check_random_paths();
  return check::summary();
}
