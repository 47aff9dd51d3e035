/**
 * The strain operator B of one Fourier harmonic (thesis eq. 3.3 with the
 * trigonometric factors of eq. 3.2 divided out), see doc/theory.md.
 *
 * With s = +1 (symmetric) or -1 (antisymmetric) and m = s n, the strain
 * amplitudes of (U, V, W) at radius r are
 *   e_r  = dU/dr,            e_z  = dV/dz,          e_t = (U + m W) / r,
 *   g_rz = dU/dz + dV/dr,    g_zt = -m V / r + dW/dz,
 *   g_rt = -m U / r + dW/dr - W / r.
 * e_r, e_z, e_t, g_rz carry the trig factor of (U, V); g_zt, g_rt that of W.
 */
#ifndef fourier_ssi_harmonic_operator_h
#define fourier_ssi_harmonic_operator_h

#include <array>
#include <deal.II/base/tensor.h>
#include <fourier_ssi/input/harmonic.h>

namespace FourierSSI
{
  using namespace dealii;

  /** Strain or stress amplitudes in the order (r, z, theta, rz, ztheta,
   * rtheta). */
  using StrainVector = std::array<double, 6>;

  namespace StrainIndex
  {
    constexpr unsigned int rr = 0, zz = 1, tt = 2, rz = 3, zt = 4, rt = 5;
  }

  /** Displacement component indices in the FESystem. */
  namespace Component
  {
    constexpr unsigned int radial = 0, axial = 1, circumferential = 2;
  }

  class HarmonicOperator
  {
  public:
    explicit HarmonicOperator(const Harmonic &harmonic);

    /**
     * Strain amplitudes of a field whose only non-zero component is
     * `component`, with value `value` and (d/dr, d/dz) gradient `gradient`,
     * at radius r >= 0 (r = 0: axis limit, see the .cc).
     */
    StrainVector
    strain_of_component(const unsigned int  component,
                        const double        value,
                        const Tensor<1, 2> &gradient,
                        const double        r) const;

    /** Strain amplitudes of the full field (U, V, W) at radius r > 0. */
    StrainVector
    strain(const std::array<double, 3>       &values,
           const std::array<Tensor<1, 2>, 3> &gradients,
           const double                       r) const;

    /** Weight of strain component k in the theta integral (pi, 2 pi or 0). */
    double
    weight(const unsigned int k) const
    {
      return weights[k];
    }

    const Harmonic &
    get_harmonic() const
    {
      return harmonic;
    }

  private:
    Harmonic              harmonic;
    double                m; // signed harmonic number s n
    std::array<double, 6> weights;
  };
} // namespace FourierSSI

#endif
