/**
 * Multi-surface kinematic hardening clay, undrained and in total stress
 * (Soil plasticity/Laws 'iwan'; doc/soil-plasticity.md section 10,
 * derivation in doc/derivations/multi_surface_clay.md).
 *
 * The overlay ("parallel") form of Iwan (1967): N von Mises elements,
 * elastic-perfectly plastic, all sharing the strain; their deviatoric
 * stresses add, the volume change is elastic:
 *   sigma = K tr(eps) 1 + sum_i s_i,                                  (C1)
 *   s_i   = 2 G_i (e - e^p_i),   |s_i| <= sqrt(2) tau_i,               (C2)
 * e = dev(eps), |.| the Frobenius norm. sqrt(2) tau_i makes tau_i the
 * strength of element i in simple shear (sqrt(J2) <= tau_i); the law's
 * strength is s_u in simple shear and q = sqrt(3) s_u in triaxial. The
 * G_i, tau_i come from MultiSurfaceBackbone. Together the elements behave
 * as Mroz's (1967) nested surfaces with kinematic hardening; Masing's
 * rules follow (derivation section 4).
 *
 * Each element returns radially (closed form, derivation section 1):
 *   s_i^tr = 2 G_i (e - e^p_i,n),  s_i = min(1, sqrt(2) tau_i / |s_i^tr|)
 *   s_i^tr, and its consistent tangent is 2 G_i I_dev when elastic and
 *   2 G_i (sqrt(2) tau_i / |s_i^tr|) (I_dev - n_i (x) n_i),
 *   n_i = s_i^tr / |s_i^tr|, when it yields; the law's tangent is
 *   K 1 (x) 1 plus their sum.                                         (C3)
 *
 * Stresses tension positive, in the order of StrainVector (r, z, theta,
 * rz, ztheta, rtheta); strains and plastic strains with engineering shears.
 */
#ifndef fourier_ssi_multi_surface_clay_h
#define fourier_ssi_multi_surface_clay_h

#include <fourier_ssi/coupled/multi_surface_backbone.h>
#include <fourier_ssi/coupled/soil_law.h>
#include <vector>

namespace FourierSSI
{
  /** The plastic state: the deviatoric plastic strain of each element. */
  using MultiSurfaceState = std::vector<StrainVector>;

  /**
   * The stress and the count of yielding elements of a return whose new
   * plastic strains were written in place (the coupled soil points keep
   * every sample's elements in one flat array).
   */
  struct MultiSurfaceStress
  {
    /** The stress (C1) [kPa]. */
    StrainVector stress     = {{0., 0., 0., 0., 0., 0.}};
    unsigned int n_yielding = 0;
  };

  struct MultiSurfaceReturn
  {
    /** The stress (C1) [kPa]. */
    StrainVector stress = {{0., 0., 0., 0., 0., 0.}};
    /** The new plastic strains e^p_i, n+1 (engineering shears). */
    MultiSurfaceState plastic_strains;
    /** How many elements are on their surface. */
    unsigned int n_yielding = 0;
  };

  /** The return mapping (C1)-(C3) of the clay at one point. */
  class MultiSurfaceClay
  {
  public:
    /** The elements of `backbone` and the bulk modulus K [kPa]. */
    MultiSurfaceClay(const MultiSurfaceBackbone &backbone,
                     const double                bulk_modulus);

    /**
     * An 'iwan' law at a point of depth `depth` [m] of a material with
     * small-strain shear modulus G0 and bulk modulus K [kPa].
     */
    MultiSurfaceClay(const SoilLaw &law,
                     const double   shear_modulus,
                     const double   bulk_modulus,
                     const double   depth);

    unsigned int
    n_surfaces() const
    {
      return backbone.n_surfaces();
    }

    const MultiSurfaceBackbone &
    elements() const
    {
      return backbone;
    }

    /** The virgin state: no plastic strain in any element. */
    MultiSurfaceState
    initial_state() const;

    /**
     * The stress and the new state at the total strain `strain`, from the
     * committed plastic strains (the strain increment of the step is
     * strain - strain_n; the elements need only the total).
     */
    MultiSurfaceReturn
    return_map(const StrainVector      &strain,
               const MultiSurfaceState &committed) const;

    /** As return_map, and the consistent tangent (C3). */
    MultiSurfaceReturn
    return_map_with_tangent(const StrainVector      &strain,
                            const MultiSurfaceState &committed,
                            StressTangent           &tangent) const;

    /**
     * The same return on raw arrays of n_surfaces() plastic strains:
     * `committed` read, `updated` written (it may be null: the stress only);
     * the tangent (C3) if `tangent` is not null.
     */
    MultiSurfaceStress
    return_map(const StrainVector &strain,
               const StrainVector *committed,
               StrainVector       *updated,
               StressTangent      *tangent) const;

  private:
    /** return_map on raw arrays, into a MultiSurfaceReturn. */
    MultiSurfaceReturn
    with_state(const StrainVector      &strain,
               const MultiSurfaceState &committed,
               StressTangent           *tangent) const;

    MultiSurfaceBackbone backbone;
    double               bulk_modulus;
  };
} // namespace FourierSSI

#endif
