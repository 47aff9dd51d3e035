// Theta sampling and projection (include/fourier_ssi/fourier/theta_sampling.h,
// doc/nonlinear-interfaces.md section 3): the trapezoidal rule on N equally
// spaced angles is the exact DFT, so (i) sampling harmonics 0..n_max of both
// families and projecting back returns the amplitudes to round-off iff
// N > 2 n_max; (ii) a product of two fields band-limited to n_max / 2
// (band-limited to n_max) projects exactly; (iii) with N = 2 n_max the
// highest harmonic aliases (cos 4 theta at N = 8: amplitude 2 instead of 1,
// sin 4 theta: 0 instead of 1); (iv) a non-band-limited function, |cos t|,
// has its harmonic-2 amplitude 4/(3 pi) polluted by aliasing that shrinks
// as N grows. Tolerance 1e-13: sums of ~20 terms of order 1.
#include "check.h"

#include <cmath>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <random>

using namespace FourierSSI;

namespace
{
  std::vector<Harmonic>
  harmonics_up_to(const unsigned int n_max)
  {
    std::vector<Harmonic> list;
    for (unsigned int n = 0; n <= n_max; ++n)
      for (const Family f : {Family::symmetric, Family::antisymmetric})
        list.push_back({n, f});
    return list;
  }

  /** Amplitudes with zeros where the factor vanishes (n = 0). */
  std::vector<double>
  random_amplitudes(const std::vector<Harmonic> &list,
                    const ThetaFactor            kind,
                    std::mt19937                &random)
  {
    std::uniform_real_distribution<double> u(-1., 1.);
    std::vector<double>                    a(list.size());
    for (unsigned int h = 0; h < list.size(); ++h)
      {
        const double norm = kind == ThetaFactor::in_plane ?
                              list[h].in_plane_weight() :
                              list[h].out_of_plane_weight();
        a[h]              = norm > 0. ? u(random) : 0.;
      }
    return a;
  }

  double
  max_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double d = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  }

  void
  round_trip()
  {
    std::cout << "sample and project back, n_max = 4" << std::endl;
    const auto   list = harmonics_up_to(4);
    std::mt19937 random(3);
    for (const ThetaFactor kind :
         {ThetaFactor::in_plane, ThetaFactor::circumferential})
      {
        const std::string name =
          kind == ThetaFactor::in_plane ? "in-plane" : "circumferential";
        const auto          a = random_amplitudes(list, kind, random);
        std::vector<double> samples, back;
        for (const unsigned int N : {9u, 10u, 33u})
          {
            const ThetaSampling sampling(list, N);
            check::that(name + " N = " + std::to_string(N) + " is alias-free",
                        sampling.is_alias_free());
            sampling.evaluate(a, kind, samples);
            sampling.project(samples, kind, back);
            check::small(name + " N = " + std::to_string(N) +
                           ": max amplitude error",
                         max_difference(a, back),
                         1e-13);
          }
        const ThetaSampling too_few(list, 8);
        check::that(name + " N = 8 = 2 n_max is not alias-free",
                    !too_few.is_alias_free());
        too_few.evaluate(a, kind, samples);
        too_few.project(samples, kind, back);
        check::in_range(name + " N = 8: the aliasing shows (max error)",
                        max_difference(a, back),
                        0.05,
                        10.);
      }
  }

  void
  product_of_band_limited_fields()
  {
    std::cout << "a product of two fields band-limited to 2 (band 4)"
              << std::endl;
    const auto   low = harmonics_up_to(2), high = harmonics_up_to(4);
    std::mt19937 random(5);
    const auto   a = random_amplitudes(low, ThetaFactor::in_plane, random);
    const auto   b = random_amplitudes(low, ThetaFactor::in_plane, random);
    const ThetaSampling reference_low(low, 256), reference_high(high, 256);
    std::vector<double> fa, fb, reference;
    reference_low.evaluate(a, ThetaFactor::in_plane, fa);
    reference_low.evaluate(b, ThetaFactor::in_plane, fb);
    for (unsigned int j = 0; j < fa.size(); ++j)
      fa[j] *= fb[j];
    reference_high.project(fa, ThetaFactor::in_plane, reference);
    for (const unsigned int N : {9u, 8u})
      {
        const ThetaSampling s_low(low, N), s_high(high, N);
        std::vector<double> ga, gb, projected;
        s_low.evaluate(a, ThetaFactor::in_plane, ga);
        s_low.evaluate(b, ThetaFactor::in_plane, gb);
        for (unsigned int j = 0; j < N; ++j)
          ga[j] *= gb[j];
        s_high.project(ga, ThetaFactor::in_plane, projected);
        const double error = max_difference(projected, reference);
        if (N == 9)
          check::small("N = 9: product projected exactly", error, 1e-13);
        else
          check::in_range("N = 8: product aliased", error, 1e-3, 10.);
      }
  }

  void
  exact_aliasing_values()
  {
    std::cout << "harmonic 4 at N = 8 (N = 2 n_max)" << std::endl;
    const std::vector<Harmonic> four = {{4, Family::symmetric},
                                        {4, Family::antisymmetric}};
    const ThetaSampling         sampling(four, 8);
    std::vector<double>         samples, back;
    sampling.evaluate({1., 1.}, ThetaFactor::in_plane, samples);
    sampling.project(samples, ThetaFactor::in_plane, back);
    check::relative("cos 4t comes back as 2 cos 4t", back[0], 2., 1e-13);
    check::small("sin 4t is invisible (0)", back[1], 1e-13);
  }

  void
  non_band_limited()
  {
    std::cout << "|cos t|: harmonic-2 amplitude 4/(3 pi) vs N" << std::endl;
    const std::vector<Harmonic> two      = {{2, Family::symmetric}};
    const double                exact    = 4. / (3. * M_PI);
    double                      previous = 1.;
    for (const unsigned int N : {8u, 32u, 128u})
      {
        const ThetaSampling sampling(two, N);
        std::vector<double> samples(N), back;
        for (unsigned int j = 0; j < N; ++j)
          samples[j] = std::abs(std::cos(sampling.angle(j)));
        sampling.project(samples, ThetaFactor::in_plane, back);
        const double error = std::abs(back[0] - exact);
        std::cout << "  N = " << N << ": amplitude " << back[0] << ", error "
                  << error << std::endl;
        check::that("aliasing error shrinks with N (N = " + std::to_string(N) +
                      ")",
                    error < previous && error > 0.);
        previous = error;
      }
  }
} // namespace

int
main()
{
  round_trip();
  product_of_band_limited_fields();
  exact_aliasing_values();
  non_band_limited();
  return check::summary();
}
