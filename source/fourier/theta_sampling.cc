#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <string>

namespace FourierSSI
{
  double
  theta_factor(const Harmonic   &harmonic,
               const ThetaFactor kind,
               const double      theta)
  {
    const double angle = harmonic.n * theta;
    const bool   cosine =
      (kind == ThetaFactor::in_plane) == (harmonic.family == Family::symmetric);
    return cosine ? std::cos(angle) : std::sin(angle);
  }

  ThetaSampling::ThetaSampling(const std::vector<Harmonic> &harmonics,
                               const unsigned int           n_samples)
    : harmonics(harmonics)
    , n_angles(n_samples)
  {
    AssertThrow(n_samples > 0, dealii::ExcMessage("theta samples must be > 0"));
    for (const ThetaFactor kind :
         {ThetaFactor::in_plane, ThetaFactor::circumferential})
      {
        std::vector<double> &table = factors[static_cast<int>(kind)];
        table.resize(harmonics.size() * n_angles);
        for (unsigned int h = 0; h < harmonics.size(); ++h)
          for (unsigned int j = 0; j < n_angles; ++j)
            table[h * n_angles + j] =
              theta_factor(harmonics[h], kind, angle(j));
      }
  }

  double
  ThetaSampling::angle(const unsigned int j) const
  {
    return 2. * dealii::numbers::PI * j / n_angles;
  }

  bool
  ThetaSampling::is_alias_free() const
  {
    unsigned int n_max = 0;
    for (const Harmonic &h : harmonics)
      n_max = std::max(n_max, h.n);
    return n_angles >= minimum_theta_samples(n_max);
  }

  unsigned int
  highest_harmonic(const std::vector<Harmonic> &harmonics)
  {
    unsigned int n_max = 0;
    for (const Harmonic &h : harmonics)
      n_max = std::max(n_max, h.n);
    return n_max;
  }

  unsigned int
  theta_samples_for(const unsigned int n_max, const unsigned int requested)
  {
    if (requested == 0)
      return 4 * (n_max + 1);
    AssertThrow(requested >= minimum_theta_samples(n_max),
                dealii::ExcMessage(
                  "Load path/Theta samples: " + std::to_string(requested) +
                  " must exceed 2 n_max = " + std::to_string(2 * n_max) +
                  " (else the harmonics alias)"));
    return requested;
  }

  void
  ThetaSampling::evaluate(const std::vector<double> &amplitudes,
                          const ThetaFactor          kind,
                          std::vector<double>       &samples) const
  {
    Assert(amplitudes.size() == harmonics.size(), dealii::ExcInternalError());
    const std::vector<double> &table = factors[static_cast<int>(kind)];
    samples.assign(n_angles, 0.);
    for (unsigned int h = 0; h < harmonics.size(); ++h)
      if (amplitudes[h] != 0.)
        for (unsigned int j = 0; j < n_angles; ++j)
          samples[j] += amplitudes[h] * table[h * n_angles + j];
  }

  void
  ThetaSampling::integrate(const std::vector<double> &samples,
                           const ThetaFactor          kind,
                           std::vector<double>       &coefficients) const
  {
    Assert(samples.size() == n_angles, dealii::ExcInternalError());
    const std::vector<double> &table  = factors[static_cast<int>(kind)];
    const double               weight = 2. * dealii::numbers::PI / n_angles;
    coefficients.assign(harmonics.size(), 0.);
    for (unsigned int h = 0; h < harmonics.size(); ++h)
      {
        double sum = 0.;
        for (unsigned int j = 0; j < n_angles; ++j)
          sum += table[h * n_angles + j] * samples[j];
        coefficients[h] = weight * sum;
      }
  }

  void
  ThetaSampling::project(const std::vector<double> &samples,
                         const ThetaFactor          kind,
                         std::vector<double>       &amplitudes) const
  {
    integrate(samples, kind, amplitudes);
    for (unsigned int h = 0; h < harmonics.size(); ++h)
      {
        const double norm = kind == ThetaFactor::in_plane ?
                              harmonics[h].in_plane_weight() :
                              harmonics[h].out_of_plane_weight();
        amplitudes[h]     = norm > 0. ? amplitudes[h] / norm : 0.;
      }
  }
} // namespace FourierSSI
