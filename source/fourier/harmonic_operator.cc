#include <fourier_ssi/fourier/harmonic_operator.h>

namespace FourierSSI
{
  HarmonicOperator::HarmonicOperator(const Harmonic &harmonic)
    : harmonic(harmonic)
    , m(family_sign(harmonic.family) * harmonic.n)
  {
    const double in_plane  = harmonic.in_plane_weight();
    const double out_plane = harmonic.out_of_plane_weight();
    weights = {{in_plane, in_plane, in_plane, in_plane, out_plane, out_plane}};
  }

  StrainVector
  HarmonicOperator::strain_of_component(const unsigned int  component,
                                        const double        value,
                                        const Tensor<1, 2> &gradient,
                                        const double        r) const
  {
    StrainVector e{};
    // On the axis (only output points lie there, never quadrature points)
    // value/r is replaced by its limit d(value)/dr, valid for fields that
    // satisfy the axis conditions (doc/theory.md).
    const double value_over_r = (r > 0.) ? value / r : gradient[0];
    switch (component)
      {
        case Component::radial: // U
          e[StrainIndex::rr] = gradient[0];
          e[StrainIndex::tt] = value_over_r;
          e[StrainIndex::rz] = gradient[1];
          e[StrainIndex::rt] = -m * value_over_r;
          break;
        case Component::axial: // V
          e[StrainIndex::zz] = gradient[1];
          e[StrainIndex::rz] = gradient[0];
          e[StrainIndex::zt] = -m * value_over_r;
          break;
        case Component::circumferential: // W
          e[StrainIndex::tt] = m * value_over_r;
          e[StrainIndex::zt] = gradient[1];
          e[StrainIndex::rt] = gradient[0] - value_over_r;
          break;
        default:
          Assert(false, ExcIndexRange(component, 0, 3));
      }
    return e;
  }

  StrainVector
  HarmonicOperator::strain(const std::array<double, 3>       &values,
                           const std::array<Tensor<1, 2>, 3> &gradients,
                           const double                       r) const
  {
    StrainVector e{};
    for (unsigned int c = 0; c < 3; ++c)
      {
        const StrainVector ec =
          strain_of_component(c, values[c], gradients[c], r);
        for (unsigned int k = 0; k < 6; ++k)
          e[k] += ec[k];
      }
    return e;
  }
} // namespace FourierSSI
