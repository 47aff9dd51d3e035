/**
 * Loads given as functions of theta and their Fourier decomposition
 * (thesis eqs 3.1-3.2): a surface traction or a prescribed displacement
 * f(r, z, theta) with components (r, z, theta) becomes, per harmonic
 * (n, family), the amplitude the harmonic problem expects:
 *   symmetric:     F_r, F_z = c_n int f_{r,z} cos(n t) dt,
 *                  F_theta  = c_n int f_theta sin(n t) dt,
 *   antisymmetric: F_r, F_z = c_n int f_{r,z} sin(n t) dt,
 *                  F_theta  = c_n int f_theta cos(n t) dt,
 * c_0 = 1/(2 pi), c_n = 1/pi (n >= 1). The integrals are evaluated by the
 * trapezoidal rule on K equally spaced angles, which is exact for every
 * harmonic below K/2; K is doubled until the coefficients up to the largest
 * harmonic of interest stop changing (aliasing below the tolerance).
 */
#ifndef fourier_ssi_load_decomposition_h
#define fourier_ssi_load_decomposition_h

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/input/harmonic.h>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * Fourier coefficients of a 3-component load at one (r, z) point for
   * n = 0 .. n_max, both families, as defined in the file comment:
   * coefficient[family][n][component].
   */
  struct PointSpectrum
  {
    std::array<std::vector<std::array<double, 3>>, 2> coefficient;
    /** max over the samples and components of |f| */
    double max_abs = 0.;

    const std::array<double, 3> &
    get(const Harmonic &h) const
    {
      return coefficient[h.family == Family::symmetric ? 0 : 1][h.n];
    }
  };

  PointSpectrum
  compute_spectrum(const Function<3> &load,
                   const Point<2>    &point,
                   const unsigned int n_max,
                   const unsigned int n_samples);

  /**
   * One load f(r, z, theta) of the scene with its sampling; evaluates the
   * amplitudes of any harmonic, caching each point's spectrum so that the
   * harmonics (possibly solved concurrently) share the work.
   */
  class ThetaLoad
  {
  public:
    ThetaLoad(const ComponentExpressions &expressions,
              const std::string          &entry,
              const unsigned int          n_max);

    /**
     * Choose the number of samples: start at 4 n_max (at least 64), double
     * until the coefficients at the given points change by less than
     * `tolerance` times the largest |f|; throws if 2^16 samples do not reach
     * it. Returns the largest |f| seen.
     */
    double
    choose_samples(const std::vector<Point<2>> &points, const double tolerance);

    /** The spectrum at a point (cached). */
    const PointSpectrum &
    spectrum(const Point<2> &point) const;

    /** Amplitudes of one harmonic as a deal.II function of (r, z). */
    std::unique_ptr<Function<2>>
    amplitude_function(const Harmonic &harmonic) const;

    unsigned int
    n_samples() const
    {
      return samples;
    }

    const std::string &
    name() const
    {
      return entry;
    }

  private:
    std::string                                                entry;
    std::shared_ptr<FunctionParser<3>>                         function;
    unsigned int                                               n_max;
    unsigned int                                               samples = 64;
    mutable std::mutex                                         cache_mutex;
    mutable std::map<std::pair<double, double>, PointSpectrum> cache;
  };

  /** All theta-dependent loads of a scene, by kind and boundary id. */
  struct LoadDecomposition
  {
    std::map<types::boundary_id, std::shared_ptr<ThetaLoad>> traction;
    std::map<types::boundary_id, std::shared_ptr<ThetaLoad>> displacement;
    /** Which displacement components each id prescribes. */
    std::map<types::boundary_id, std::array<bool, 3>> displacement_components;
  };
} // namespace FourierSSI

#endif
