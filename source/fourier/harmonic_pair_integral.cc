#include <algorithm>
#include <cmath>
#include <deal.II/base/numbers.h>
#include <fourier_ssi/fourier/harmonic_pair_integral.h>

namespace FourierSSI
{
  HarmonicPairIntegral::HarmonicPairIntegral(
    const std::vector<Harmonic> &harmonics,
    const ThetaSampling         &sampling,
    const unsigned int           size,
    const unsigned int           n_in_plane)
    : size(size)
    , n_in_plane(n_in_plane)
    , n_samples(sampling.n_samples())
    , weight(2. * dealii::numbers::PI / sampling.n_samples())
  {
    unsigned int n_max = 0;
    for (const Harmonic &harmonic : harmonics)
      {
        n.push_back(harmonic.n);
        n_max = std::max(n_max, harmonic.n);
        // In-plane factors are cosines in the symmetric family, the
        // circumferential ones in the antisymmetric family.
        for (unsigned int kind = 0; kind < 2; ++kind)
          is_cosine.push_back((kind == 0) ==
                              (harmonic.family == Family::symmetric));
      }
    n_frequencies        = 2 * n_max + 1;
    const unsigned int M = n_frequencies, N = n_samples;
    cosine.resize(M * N);
    sine.resize(M * N);
    for (unsigned int m = 0; m < M; ++m)
      for (unsigned int j = 0; j < N; ++j)
        {
          cosine[m * N + j] = std::cos(m * sampling.angle(j));
          sine[m * N + j]   = std::sin(m * sampling.angle(j));
        }
    c_cos.resize(size * size * M);
    c_sin.resize(size * size * M);
  }

  void
  HarmonicPairIntegral::clear()
  {
    std::fill(c_cos.begin(), c_cos.end(), 0.);
    std::fill(c_sin.begin(), c_sin.end(), 0.);
  }

  void
  HarmonicPairIntegral::add_sample(const unsigned int j, const double *c)
  {
    const unsigned int M = n_frequencies, N = n_samples;
    for (unsigned int ab = 0; ab < size * size; ++ab)
      {
        if (c[ab] == 0.)
          continue;
        const double x = weight * c[ab];
        for (unsigned int m = 0; m < M; ++m)
          {
            c_cos[ab * M + m] += x * cosine[m * N + j];
            c_sin[ab * M + m] += x * sine[m * N + j];
          }
      }
  }

  void
  HarmonicPairIntegral::integrals(std::vector<double> &S) const
  {
    const unsigned int H = n.size(), HH = H * H, M = n_frequencies;
    S.resize(size * size * HH);
    const auto kind_of = [&](const unsigned int a) {
      return a < n_in_plane ? 0u : 1u;
    };
    for (unsigned int a = 0; a < size; ++a)
      for (unsigned int b = 0; b < size; ++b)
        {
          const double *cc = &c_cos[(a * size + b) * M];
          const double *cs = &c_sin[(a * size + b) * M];
          double       *s  = &S[(a * size + b) * HH];
          for (unsigned int h = 0; h < H; ++h)
            for (unsigned int g = 0; g < H; ++g)
              {
                const int          n_h = n[h], n_g = n[g];
                const unsigned int sum        = n_h + n_g,
                                   difference = std::abs(n_h - n_g);
                const double sign             = n_h >= n_g ? 1. : -1.;
                const bool   cos_h            = is_cosine[2 * h + kind_of(a)],
                           cos_g              = is_cosine[2 * g + kind_of(b)];
                double value;
                if (cos_h && cos_g) // cos a cos b
                  value = cc[difference] + cc[sum];
                else if (!cos_h && !cos_g) // sin a sin b
                  value = cc[difference] - cc[sum];
                else if (cos_h) // cos a sin b
                  value = cs[sum] - sign * cs[difference];
                else // sin a cos b
                  value = cs[sum] + sign * cs[difference];
                s[h * H + g] = 0.5 * value;
              }
        }
  }
} // namespace FourierSSI
