/**
 * Multi-surface sand, drained and in effective stress (Soil plasticity/Laws
 * 'iwan-sand'; doc/soil-plasticity.md section 11, derivation in
 * doc/derivations/multi_surface_sand.md).
 *
 * An overlay of N Mohr-Coulomb elements (the overlay models of Zienkiewicz,
 * Nayak & Owen 1972 and Pande, Owen & Zienkiewicz 1977; Iwan 1967's
 * parallel elements with a friction law). All share the strain; element i
 * has the elastic moduli g_i G0 and w_i K, starts from w_i sigma_0, and
 * carries the law's phi', psi with the cohesion w_i c':
 *   sigma   = sum_i sigma_i,                                          (S1)
 *   sigma_i = w_i sigma_0 + D_i (eps - eps^p_i),  f(sigma_i; w_i c) <= 0,
 * each returned by the closed-form Mohr-Coulomb mapping of soil_law.h in
 * its own energy norm, with its own consistent tangent; the law's tangent
 * is their sum.                                                       (S2)
 * sum g_i = sum w_i = 1, so the elastic law is the material's (G0, K).
 *
 * Why it is Mohr-Coulomb at failure: the Mohr-Coulomb set C is a convex
 * cone about the apex (c cot phi), and scaling c by w_i scales it, w_i C.
 * Every sigma_i in w_i C puts sigma in sum w_i C = C: the law never leaves
 * Mohr-Coulomb. When every element is on its surface with the same
 * principal directions and face (monotonic loading), sigma is on the face
 * of C itself: the failure stress of the Mohr-Coulomb law of the same c',
 * phi' in compression, extension and shear alike (derivation section 2).
 *
 * The staggering: along any path with a fixed mean stress and a fixed Lode
 * angle, element i yields at x_i = w_i / g_i, x = the elastic stress over
 * the Mohr-Coulomb strength on that path, so the stress-strain curve is
 * q_f sum_i min(g_i x, w_i): the polygon of MultiSurfaceBackbone fitted to
 * the Duncan-Chang hyperbola in these units,
 *   q / q_f = min(x / (1 + R_f x), 1),  x = 3 G0 eps_q / q_f,         (S3)
 * with R_f the failure ratio (Duncan & Chang 1970): G/G0 = 1/2 at
 * x = 1 / R_f, failure at x = 1 / (1 - R_f). So the reference strain
 * scales with q_f / G0, as (p')^(1 - m) for Hardin's G0 ~ (p')^m.
 * g_i, w_i are the moduli and strengths of that backbone with G0 = s_u = 1
 * and gamma_ref = 1 / R_f; they do not depend on the point.
 * The cyclic loops follow Masing's rules while the elements' directions
 * stay fixed (derivation section 3).
 */
#ifndef fourier_ssi_multi_surface_sand_h
#define fourier_ssi_multi_surface_sand_h

#include <fourier_ssi/coupled/multi_surface_clay.h>
#include <fourier_ssi/coupled/soil_law.h>
#include <vector>

namespace FourierSSI
{
  /** The return mapping (S1)-(S2) of the sand of one law. */
  class MultiSurfaceSand
  {
  public:
    /** The elements of an 'iwan-sand' law (its R_f and N). */
    explicit MultiSurfaceSand(const SoilLaw &law);

    unsigned int
    n_surfaces() const
    {
      return stiffness_fraction.size();
    }

    /** g_i: element i's share of G0. */
    double
    stiffness_share(const unsigned int i) const
    {
      return stiffness_fraction[i];
    }

    /** w_i: element i's share of K, sigma_0 and c'. */
    double
    strength_share(const unsigned int i) const
    {
      return strength_fraction[i];
    }

    /**
     * The normalised backbone (S3): its polygon is q / q_f against
     * x = 3 G0 eps_q / q_f (MultiSurfaceBackbone with G0 = s_u = 1).
     */
    const MultiSurfaceBackbone &
    normalised_backbone() const
    {
      return backbone;
    }

    /** f of the law's own Mohr-Coulomb surface [kPa] (<= 0 admissible). */
    double
    yield_function(const StrainVector &stress, const double depth) const;

    /**
     * The stress (S1) at the total strain `strain` (engineering shears) of
     * a point with G0, K [kPa] and geostatic stress sigma_0, from the
     * elements' committed plastic strains `committed` (n_surfaces(),
     * engineering shears). `updated` (may be null) receives the new ones;
     * `tangent` (may be null) the consistent tangent (S2).
     */
    MultiSurfaceStress
    return_map(const StrainVector &strain,
               const StrainVector &initial_stress,
               const double        shear_modulus,
               const double        bulk_modulus,
               const double        depth,
               const StrainVector *committed,
               StrainVector       *updated,
               StressTangent      *tangent) const;

  private:
    MultiSurfaceBackbone           backbone;
    std::vector<double>            stiffness_fraction, strength_fraction;
    std::vector<SoilReturnMapping> elements;
    SoilReturnMapping              failure;
  };
} // namespace FourierSSI

#endif
