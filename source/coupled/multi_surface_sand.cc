#include <fourier_ssi/coupled/multi_surface_sand.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>

namespace FourierSSI
{
  namespace
  {
    /** The law's Mohr-Coulomb surface with its cohesion scaled by w. */
    SoilLaw
    element_law(const SoilLaw &law, const double w)
    {
      SoilLaw element  = law;
      element.kind     = SoilLaw::Kind::mohr_coulomb;
      element.cohesion = w * law.cohesion;
      return element;
    }
  } // namespace

  MultiSurfaceSand::MultiSurfaceSand(const SoilLaw &law)
    // (S3): G0 = q_f = 1 and gamma_ref = 1 / R_f in MultiSurfaceBackbone's
    // (B1) give x / (1 + R_f x) capped at 1.
    : backbone(1., 1., 1. / law.failure_ratio, law.n_surfaces)
    , failure(element_law(law, 1.))
  {
    Assert(law.kind == SoilLaw::Kind::iwan_sand, ExcInternalError());
    for (unsigned int i = 0; i < backbone.n_surfaces(); ++i)
      {
        stiffness_fraction.push_back(backbone.shear_modulus(i));
        strength_fraction.push_back(backbone.strength(i));
        elements.emplace_back(element_law(law, strength_fraction.back()));
      }
  }

  double
  MultiSurfaceSand::yield_function(const StrainVector &stress,
                                   const double        depth) const
  {
    return failure.yield_function(stress, depth);
  }

  MultiSurfaceStress
  MultiSurfaceSand::return_map(const StrainVector &strain,
                               const StrainVector &initial_stress,
                               const double        shear_modulus,
                               const double        bulk_modulus,
                               const double        depth,
                               const StrainVector *committed,
                               StrainVector       *updated,
                               StressTangent      *tangent) const
  {
    // sigma = sigma_0 + sum_i (D_i (eps - eps^p_i) + the return's
    // correction): summed as changes from sigma_0, so that an elastic step
    // of any size gives sigma_0 + D eps to the round-off of D eps, not of
    // sigma_0 (the s_p of a step of 1e-7 m would otherwise be 1e-14 kPa of
    // noise against 1e-4 kPa of stress).
    MultiSurfaceStress result;
    result.stress = initial_stress;
    if (tangent != nullptr)
      tangent->fill(0.);
    StressTangent element_tangent;
    for (unsigned int i = 0; i < n_surfaces(); ++i)
      {
        const double G      = stiffness_fraction[i] * shear_modulus,
                     K      = strength_fraction[i] * bulk_modulus,
                     lambda = K - 2. * G / 3.;
        // (S1): the trial w_i sigma_0 + D_i (eps - eps^p_i,n).
        StrainVector elastic_strain;
        for (unsigned int c = 0; c < 6; ++c)
          elastic_strain[c] = strain[c] - committed[i][c];
        const StrainVector change = hooke_stress(elastic_strain, lambda, G);
        StrainVector       trial  = change;
        for (unsigned int c = 0; c < 6; ++c)
          trial[c] += strength_fraction[i] * initial_stress[c];
        const SoilReturn r = tangent == nullptr ?
                               elements[i].return_map(trial, G, K, depth) :
                               elements[i].return_map_with_tangent(
                                 trial, G, K, depth, element_tangent);
        if (r.state != SoilState::elastic)
          ++result.n_yielding;
        for (unsigned int c = 0; c < 6; ++c)
          result.stress[c] += change[c] + (r.stress[c] - trial[c]);
        if (tangent != nullptr)
          for (unsigned int a = 0; a < 36; ++a)
            (*tangent)[a] += element_tangent[a];
        if (updated == nullptr)
          continue;
        // eps^p_i,n+1 = eps^p_i,n + D_i^-1 (trial - sigma_i).
        StrainVector correction;
        for (unsigned int c = 0; c < 6; ++c)
          correction[c] = trial[c] - r.stress[c];
        const StrainVector plastic = compliance_strain(correction, lambda, G);
        for (unsigned int c = 0; c < 6; ++c)
          updated[i][c] = committed[i][c] + plastic[c];
      }
    return result;
  }
} // namespace FourierSSI
