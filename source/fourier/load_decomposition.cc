#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/fourier/load_decomposition.h>
#include <iostream>
#include <mutex>
#include <sstream>

namespace FourierSSI
{
  PointSpectrum
  compute_spectrum(const Function<3> &load,
                   const Point<2>    &point,
                   const unsigned int n_max,
                   const unsigned int n_samples)
  {
    const unsigned int                 K = n_samples;
    std::vector<std::array<double, 3>> f(K);
    std::vector<double>                cos_table(K), sin_table(K);
    PointSpectrum                      spectrum;
    Vector<double>                     values(3);
    for (unsigned int k = 0; k < K; ++k)
      {
        const double theta = 2. * numbers::PI * k / K;
        cos_table[k]       = std::cos(theta);
        sin_table[k]       = std::sin(theta);
        load.vector_value(Point<3>(point[0], point[1], theta), values);
        for (unsigned int c = 0; c < 3; ++c)
          {
            f[k][c]          = values(c);
            spectrum.max_abs = std::max(spectrum.max_abs, std::abs(values(c)));
          }
      }
    for (auto &family : spectrum.coefficient)
      family.assign(n_max + 1, {{0., 0., 0.}});
    for (unsigned int n = 0; n <= n_max; ++n)
      {
        // Trapezoidal rule: (1/pi) int g dt = (2/K) sum g_k (n >= 1), and
        // (1/2 pi) int g dt = (1/K) sum g_k for n = 0.
        std::array<double, 3> c_sum = {{0., 0., 0.}}, s_sum = {{0., 0., 0.}};
        for (unsigned int k = 0; k < K; ++k)
          {
            const unsigned int j = (static_cast<unsigned long>(k) * n) % K;
            for (unsigned int c = 0; c < 3; ++c)
              {
                c_sum[c] += f[k][c] * cos_table[j];
                s_sum[c] += f[k][c] * sin_table[j];
              }
          }
        const double scale = (n == 0 ? 1. : 2.) / K;
        auto        &sym   = spectrum.coefficient[0][n];
        auto        &anti  = spectrum.coefficient[1][n];
        // In-plane components (r, z): cos (symmetric), sin (antisymmetric);
        // circumferential: sin (symmetric), cos (antisymmetric).
        for (unsigned int c = 0; c < 2; ++c)
          {
            sym[c]  = scale * c_sum[c];
            anti[c] = scale * s_sum[c];
          }
        sym[2]  = scale * s_sum[2];
        anti[2] = scale * c_sum[2];
      }
    return spectrum;
  }

  ThetaLoad::ThetaLoad(const ComponentExpressions &expressions,
                       const std::string          &entry,
                       const unsigned int          n_max)
    : entry(entry)
    , function(make_theta_function(expressions, entry))
    , n_max(n_max)
  {
    samples = 64;
    while (samples < 4 * (n_max + 1))
      samples *= 2;
  }

  namespace
  {
    /** A coordinate in a message, 4 significant digits. */
    std::string
    short_number(const double value)
    {
      std::ostringstream s;
      s.precision(4);
      s << value;
      return s.str();
    }
  } // namespace

  double
  ThetaLoad::choose_samples(const std::vector<Point<2>> &points,
                            const double                 tolerance)
  {
    // A NaN or infinity would vanish from the amplitudes (std::max ignores
    // NaN) and the scene would report "no load": name it instead.
    {
      const std::array<std::string, 3> components =
        entry.find("displacement") != std::string::npos ?
          std::array<std::string, 3>{{"u", "v", "w"}} :
          std::array<std::string, 3>{{"r", "z", "theta"}};
      Vector<double> values(3);
      for (const Point<2> &p : points)
        for (unsigned int k = 0; k < 36; ++k)
          {
            const double theta = 2. * numbers::PI * k / 36.;
            function->vector_value(Point<3>(p[0], p[1], theta), values);
            for (unsigned int c = 0; c < 3; ++c)
              AssertThrow(std::isfinite(values(c)),
                          ExcMessage(
                            entry + ": component " + components[c] + " is " +
                            (std::isnan(values(c)) ? "NaN" : "infinite") +
                            " at (r, z) = (" + short_number(p[0]) + ", " +
                            short_number(p[1]) +
                            "), theta = " + std::to_string(k * 10) + " deg"));
          }
    }
    constexpr unsigned int max_samples = 1u << 16;
    double                 largest = 0., change = 0.;
    for (; samples <= max_samples; samples *= 2)
      {
        largest = 0.;
        change  = 0.;
        for (const Point<2> &p : points)
          {
            const PointSpectrum a =
              compute_spectrum(*function, p, n_max, samples);
            const PointSpectrum b =
              compute_spectrum(*function, p, n_max, 2 * samples);
            largest = std::max(largest, b.max_abs);
            for (unsigned int f = 0; f < 2; ++f)
              for (unsigned int n = 0; n <= n_max; ++n)
                for (unsigned int c = 0; c < 3; ++c)
                  change = std::max(change,
                                    std::abs(a.coefficient[f][n][c] -
                                             b.coefficient[f][n][c]));
          }
        if (change <= tolerance * largest)
          break;
      }
    AssertThrow(samples <= max_samples,
                ExcMessage(entry + ": the Fourier coefficients up to n = " +
                           std::to_string(n_max) + " still change by " +
                           Utilities::to_string(change / largest, 3) +
                           " (relative) with 65536 samples in theta; raise "
                           "Loads/Harmonic tolerance"));
    std::lock_guard<std::mutex> lock(cache_mutex);
    cache.clear();
    return largest;
  }

  const PointSpectrum &
  ThetaLoad::spectrum(const Point<2> &point) const
  {
    const std::pair<double, double> key(point[0], point[1]);
    {
      std::lock_guard<std::mutex> lock(cache_mutex);
      const auto                  it = cache.find(key);
      if (it != cache.end())
        return it->second;
    }
    // Computed outside the lock: another thread may do the same point, and
    // the first insertion wins (std::map keeps references valid).
    PointSpectrum s = compute_spectrum(*function, point, n_max, samples);
    std::lock_guard<std::mutex> lock(cache_mutex);
    return cache.emplace(key, std::move(s)).first->second;
  }

  namespace
  {
    /** The amplitudes of one harmonic, read from the load's spectra. */
    class HarmonicAmplitude : public Function<2>
    {
    public:
      HarmonicAmplitude(const ThetaLoad &load, const Harmonic &harmonic)
        : Function<2>(3)
        , load(load)
        , harmonic(harmonic)
      {}

      double
      value(const Point<2> &p, const unsigned int component) const override
      {
        return load.spectrum(p).get(harmonic)[component];
      }

      void
      vector_value(const Point<2> &p, Vector<double> &values) const override
      {
        const auto &a = load.spectrum(p).get(harmonic);
        for (unsigned int c = 0; c < 3; ++c)
          values(c) = a[c];
      }

    private:
      const ThetaLoad &load;
      const Harmonic   harmonic;
    };
  } // namespace

  std::unique_ptr<Function<2>>
  ThetaLoad::amplitude_function(const Harmonic &harmonic) const
  {
    AssertThrow(harmonic.n <= n_max,
                ExcMessage(entry + ": harmonic " + std::to_string(harmonic.n) +
                           " is above Loads/Maximum harmonic"));
    return std::make_unique<HarmonicAmplitude>(*this, harmonic);
  }
} // namespace FourierSSI
