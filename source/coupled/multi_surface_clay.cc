#include <cmath>
#include <fourier_ssi/coupled/multi_surface_clay.h>

namespace FourierSSI
{
  MultiSurfaceClay::MultiSurfaceClay(const MultiSurfaceBackbone &backbone,
                                     const double                bulk_modulus)
    : backbone(backbone)
    , bulk_modulus(bulk_modulus)
  {}

  MultiSurfaceClay::MultiSurfaceClay(const SoilLaw &law,
                                     const double   shear_modulus,
                                     const double   bulk_modulus,
                                     const double   depth)
    : MultiSurfaceClay(law.degradation.empty() ?
                         MultiSurfaceBackbone(shear_modulus,
                                              law.undrained_strength(depth),
                                              law.reference_strain,
                                              law.n_surfaces) :
                         MultiSurfaceBackbone(shear_modulus,
                                              law.undrained_strength(depth),
                                              law.degradation),
                       bulk_modulus)
  {
    Assert(law.kind == SoilLaw::Kind::iwan, ExcInternalError());
  }

  MultiSurfaceState
  MultiSurfaceClay::initial_state() const
  {
    return MultiSurfaceState(n_surfaces(), StrainVector{});
  }

  MultiSurfaceReturn
  MultiSurfaceClay::return_map(const StrainVector      &strain,
                               const MultiSurfaceState &committed) const
  {
    return with_state(strain, committed, nullptr);
  }

  MultiSurfaceReturn
  MultiSurfaceClay::return_map_with_tangent(const StrainVector      &strain,
                                            const MultiSurfaceState &committed,
                                            StressTangent &tangent) const
  {
    return with_state(strain, committed, &tangent);
  }

  MultiSurfaceReturn
  MultiSurfaceClay::with_state(const StrainVector      &strain,
                               const MultiSurfaceState &committed,
                               StressTangent           *tangent) const
  {
    Assert(committed.size() == n_surfaces(),
           ExcDimensionMismatch(committed.size(), n_surfaces()));
    MultiSurfaceReturn result;
    result.plastic_strains.resize(n_surfaces());
    const MultiSurfaceStress r = return_map(strain,
                                            committed.data(),
                                            result.plastic_strains.data(),
                                            tangent);
    result.stress              = r.stress;
    result.n_yielding          = r.n_yielding;
    return result;
  }

  MultiSurfaceStress
  MultiSurfaceClay::return_map(const StrainVector &strain,
                               const StrainVector *committed,
                               StrainVector       *updated,
                               StressTangent      *tangent) const
  {
    // Flat 6-vectors of tensor components (shears halved from the
    // engineering strains; the stress vector holds the tensor's shears);
    // the Frobenius norm weighs the shears twice. The same (C1)-(C3) as
    // on deal.II tensors, without their fourth-order sums per element.
    constexpr double weight[6] = {1., 1., 1., 2., 2., 2.};
    const double     volume    = strain[0] + strain[1] + strain[2];
    double           e[6];
    for (unsigned int a = 0; a < 6; ++a)
      e[a] = a < 3 ? strain[a] - volume / 3. : 0.5 * strain[a];

    MultiSurfaceStress result;
    // (C1): the volumetric part is elastic.
    StrainVector stress{};
    for (unsigned int a = 0; a < 3; ++a)
      stress[a] = bulk_modulus * volume;
    // (C3): sum_i 2 G_i alpha_i I_dev - sum_yielding 2 G_i alpha_i n n,
    // alpha_i = 1 (elastic) or radius / |s_trial| (returned).
    double deviatoric_modulus = 0.;
    if (tangent)
      tangent->fill(0.);
    for (unsigned int i = 0; i < n_surfaces(); ++i)
      {
        const double g      = backbone.shear_modulus(i);
        const double radius = std::sqrt(2.) * backbone.strength(i);
        // (C2) with e^p_i frozen: the trial deviator of element i.
        double s[6], size_sqr = 0.;
        for (unsigned int a = 0; a < 6; ++a)
          {
            const double plastic =
              a < 3 ? committed[i][a] : 0.5 * committed[i][a];
            s[a] = 2. * g * (e[a] - plastic);
            size_sqr += weight[a] * s[a] * s[a];
          }
        const double size = std::sqrt(size_sqr);
        if (size <= radius)
          {
            if (updated)
              updated[i] = committed[i];
            deviatoric_modulus += 2. * g;
          }
        else
          {
            // The radial return onto |s_i| = sqrt(2) tau_i; the plastic
            // strain is what the elastic part 2 G_i (e - e^p) leaves.
            const double scale = radius / size;
            for (unsigned int a = 0; a < 6; ++a)
              s[a] *= scale;
            if (updated)
              for (unsigned int a = 0; a < 6; ++a)
                updated[i][a] = (a < 3 ? 1. : 2.) * (e[a] - s[a] / (2. * g));
            ++result.n_yielding;
            if (tangent)
              {
                // n = s / |s| of the returned (or trial) deviator.
                const double factor = 2. * g * scale / (radius * radius);
                deviatoric_modulus += 2. * g * scale;
                for (unsigned int a = 0; a < 6; ++a)
                  for (unsigned int b = 0; b < 6; ++b)
                    (*tangent)[a * 6 + b] -= factor * s[a] * s[b];
              }
          }
        for (unsigned int a = 0; a < 6; ++a)
          stress[a] += s[a];
      }
    result.stress = stress;
    if (tangent)
      {
        // K 1 x 1 + deviatoric_modulus I_dev as d sigma_a / d eps_b with
        // engineering shears: I_dev is delta_ab - 1/3 on the normal
        // block and 1/2 on the shear diagonal.
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            (*tangent)[a * 6 + b] +=
              bulk_modulus +
              deviatoric_modulus * ((a == b ? 1. : 0.) - 1. / 3.);
        for (unsigned int a = 3; a < 6; ++a)
          (*tangent)[a * 6 + a] += 0.5 * deviatoric_modulus;
      }
    return result;
  }
} // namespace FourierSSI
