/**
 * The theta integrals that couple the harmonics in a tangent stiffness
 * (doc/soil-plasticity.md section 3b): for a matrix C(theta) of m x m
 * entries known at the samples theta_j of a ThetaSampling,
 *   S_ab,hg = int_0^{2 pi} factor_h,a(theta) C_ab(theta) factor_g,b(theta)
 *             dtheta     (trapezoidal rule, weight 2 pi / N),
 * with factor_h,a the factor of harmonic h for component a (in-plane for
 * a < n_in_plane, circumferential above). Every factor is cos(n theta) or
 * sin(n theta), so factor_h factor_g = (1/2)[trig((n_h - n_g) theta) +-
 * trig((n_h + n_g) theta)]: S follows from the cosine and sine transforms
 * of C at the frequencies 0..2 n_max, O(n_max) work per sample instead of
 * O(H^2). The soil (m = 6, strains) and the nonlinear interfaces (m = 3,
 * relative displacements) share it.
 */
#ifndef fourier_ssi_harmonic_pair_integral_h
#define fourier_ssi_harmonic_pair_integral_h

#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/input/harmonic.h>
#include <vector>

namespace FourierSSI
{
  class HarmonicPairIntegral
  {
  public:
    HarmonicPairIntegral(const std::vector<Harmonic> &harmonics,
                         const ThetaSampling         &sampling,
                         const unsigned int           size,
                         const unsigned int           n_in_plane);

    /** Start a new point: every transform to zero. */
    void
    clear();

    /** Add C(theta_j) (row-major size x size); zero entries cost nothing. */
    void
    add_sample(const unsigned int j, const double *c);

    /**
     * S[(a * size + b) * H^2 + h * H + g] (the harmonic pair innermost:
     * contiguous in the assembly), resized to size^2 H^2.
     */
    void
    integrals(std::vector<double> &S) const;

  private:
    std::vector<unsigned int> n;
    /** is_cosine[2 h + kind]: kind 0 in-plane, 1 circumferential. */
    std::vector<char>   is_cosine;
    unsigned int        size, n_in_plane, n_frequencies, n_samples;
    double              weight;
    std::vector<double> cosine, sine;
    /** [ab * M + m]: sum_j w C_ab(theta_j) cos(m theta_j), resp. sin. */
    std::vector<double> c_cos, c_sin;
  };
} // namespace FourierSSI

#endif
