/**
 * Linear isotropic elastic materials per material id, with the power-law
 * non-homogeneity of thesis eq. 4.3 (Booker et al. 1985):
 *   G(depth) = G_ref (depth / depth_ref)^alpha,  nu constant,
 * alpha = 0 homogeneous, alpha = 1 Gibson soil. depth = surface elevation - z.
 * Or Hardin's small-strain modulus from the geostatic mean effective stress
 * p'0 of Initial stress (Hardin & Black 1968):
 *   G(depth) = G_ref (p'0(depth) / p_ref)^m,
 *   p'0 = (1 + 2 K0) (q + gamma' depth) / 3.
 */
#ifndef fourier_ssi_material_h
#define fourier_ssi_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <fourier_ssi/input/initial_stress_parameters.h>
#include <map>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  struct ElasticMaterial
  {
    double shear_modulus_ref = 0.; // G at depth_ref (or everywhere if alpha=0)
    double poisson_ratio     = 0.;
    double alpha             = 0.; // non-homogeneity exponent
    double depth_ref         = 1.; // depth at which G = shear_modulus_ref
    /** Hardin: p_ref [kPa] (G = shear_modulus_ref at p'0 = p_ref); 0: off. */
    double hardin_reference_stress = 0.;
    /** Hardin's exponent m. */
    double hardin_exponent = 0.5;
    /** Hardin: p'0(depth) = mean_at_surface + mean_gradient depth [kPa]. */
    double mean_at_surface = 0., mean_gradient = 0.;

    bool
    hardin() const
    {
      return hardin_reference_stress > 0.;
    }

    /** G varies with depth (a power law or Hardin's). */
    bool
    graded() const
    {
      return alpha > 0. || hardin();
    }

    /** Shear modulus at depth d >= 0 (thesis eq. 4.3, or Hardin's). */
    double
    shear_modulus(const double depth) const;

    /** Lame's first parameter lambda = 2 G nu / (1 - 2 nu). */
    double
    lambda(const double depth) const;
  };

  class MaterialLibrary
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Parse a material list "id: key=value, ...; id: ...". Keys: E or G (one of
     * them, > 0), nu (-1 < nu < 0.5), alpha (>= 0, default 0), depth_ref (> 0,
     * default 1). Throws with a one-line message naming the offending text.
     */
    void
    parse_material_list(const std::string &text);

    /**
     * Hardin's materials take p'0(depth) from the geostatic stress; one
     * line if one is given without Initial stress.
     */
    void
    use_geostatic_stress(const InitialStressParameters &initial_stress);

    bool
    has(const types::material_id id) const
    {
      return materials.count(id) > 0;
    }

    const ElasticMaterial &
    get(const types::material_id id) const;

    /** Depth below the ground surface of a point at elevation z (>= 0). */
    double
    depth(const double z) const
    {
      const double d = surface_elevation - z;
      return d > 0. ? d : 0.;
    }

    void
    set(const types::material_id id, const ElasticMaterial &material)
    {
      materials[id] = material;
    }

    const std::map<types::material_id, ElasticMaterial> &
    all() const
    {
      return materials;
    }

    double surface_elevation = 0.;

  private:
    std::map<types::material_id, ElasticMaterial> materials;
  };

  /**
   * Poisson's ratio from which FE_Q(2) with the standard (fully integrated)
   * dilatation locks noticeably. On the bundled embedded footing (finer
   * cycle) locking adds 0.2 % to K_M at nu = 0.3, 0.9 % at 0.45 (more than
   * the discretization error, 0.7 %), 2.6 % at 0.49 and 5.0 % at 0.499
   * (doc/robustness.md).
   */
  constexpr double locking_poisson_ratio = 0.45;

  /** The largest Poisson's ratio defined in Materials/Materials. */
  double
  largest_poisson_ratio(const MaterialLibrary &materials);
} // namespace FourierSSI

#endif
