/**
 * Sampling in theta of quantities given by their Fourier amplitudes, and the
 * projection of theta-sampled quantities back onto the harmonics
 * (doc/nonlinear-interfaces.md, section 3). This is how a law that is
 * nonlinear in the 3D field (the interface law) couples the harmonics.
 *
 * Samples at N equally spaced angles theta_j = 2 pi j / N, j = 0..N-1. The
 * projection integrates with the trapezoidal rule, which on a periodic
 * function is the discrete Fourier transform: it integrates cos(k theta) and
 * sin(k theta) exactly for every k that is not a non-zero multiple of N.
 *
 * The rule for N: a field band-limited to n_max (harmonics 0..n_max) times
 * the factor of a harmonic n <= n_max contains frequencies up to 2 n_max, so
 * the projection of every band-limited field onto every harmonic is exact
 * iff N > 2 n_max (N >= 2 n_max + 1). A nonlinear function of the field is
 * not band-limited: its frequencies k >= N - n alias onto harmonic n, and a
 * larger N pushes the aliasing to higher (smaller) content of the spectrum.
 */
#ifndef fourier_ssi_theta_sampling_h
#define fourier_ssi_theta_sampling_h

#include <fourier_ssi/input/harmonic.h>
#include <vector>

namespace FourierSSI
{
  /**
   * Which trigonometric factor a quantity carries (doc/theory.md section 2):
   * in-plane quantities (u, v, the tractions t_s, t_n) cos n theta in the
   * symmetric family and sin n theta in the antisymmetric one;
   * circumferential ones (w, t_theta) sin n theta resp. cos n theta.
   */
  enum class ThetaFactor
  {
    in_plane,
    circumferential
  };

  /** The factor of `harmonic` for a quantity of the given kind at theta. */
  double
  theta_factor(const Harmonic   &harmonic,
               const ThetaFactor kind,
               const double      theta);

  /** Smallest N that projects every field band-limited to n_max exactly. */
  inline unsigned int
  minimum_theta_samples(const unsigned int n_max)
  {
    return 2 * n_max + 1;
  }

  /** The highest n of a list of harmonics. */
  unsigned int
  highest_harmonic(const std::vector<Harmonic> &harmonics);

  /**
   * The number of theta samples of a coupled iteration whose fields reach
   * n_max: automatic (requested = 0) N = 4 (n_max + 1), else the requested
   * N, which must exceed 2 n_max (else the harmonics alias; one-line error
   * naming Load path/Theta samples).
   */
  unsigned int
  theta_samples_for(const unsigned int n_max, const unsigned int requested);

  /**
   * theta_samples_for() where a condition must hold at every sample of a
   * band-limited field (exact contact, Newton on a stiff penalty): the
   * automatic N is 2 n_max + 1, one sample per value. More samples ask a
   * band-limited gap to vanish at more samples than it has values
   * (doc/nonlinear-interfaces.md sections 5b, 5d): the contact edge then has
   * no consistent active set and the iteration wanders.
   */
  inline unsigned int
  constrained_theta_samples(const unsigned int n_max,
                            const unsigned int requested)
  {
    return theta_samples_for(n_max,
                             requested == 0 ? minimum_theta_samples(n_max) :
                                              requested);
  }

  class ThetaSampling
  {
  public:
    /** Tables of the factors of `harmonics` at n_samples angles. */
    ThetaSampling(const std::vector<Harmonic> &harmonics,
                  const unsigned int           n_samples);

    unsigned int
    n_samples() const
    {
      return n_angles;
    }

    double
    angle(const unsigned int j) const;

    /** True if N > 2 n_max: band-limited fields project exactly. */
    bool
    is_alias_free() const;

    /**
     * samples[j] = sum_h amplitudes[h] factor_h(theta_j), h over the
     * harmonics (one amplitude each, in the order given to the constructor).
     */
    void
    evaluate(const std::vector<double> &amplitudes,
             const ThetaFactor          kind,
             std::vector<double>       &samples) const;

    /**
     * coefficients[h] = (2 pi / N) sum_j factor_h(theta_j) samples[j], the
     * trapezoidal value of int_0^{2 pi} factor_h f dtheta: the theta part of
     * a virtual-work (load) coefficient.
     */
    void
    integrate(const std::vector<double> &samples,
              const ThetaFactor          kind,
              std::vector<double>       &coefficients) const;

    /**
     * The Fourier amplitudes: integrate() divided by int factor_h^2 (pi for
     * n >= 1, 2 pi or 0 for n = 0; 0 where the factor vanishes, e.g. the
     * circumferential part of n = 0 symmetric).
     */
    void
    project(const std::vector<double> &samples,
            const ThetaFactor          kind,
            std::vector<double>       &amplitudes) const;

  private:
    std::vector<Harmonic> harmonics;
    unsigned int          n_angles;
    /** factors[kind][h * N + j]. */
    std::vector<double> factors[2];
  };
} // namespace FourierSSI

#endif
