/**
 * The sub-elements of the multi-surface clay (multi_surface_clay.h) fitted
 * to its simple-shear backbone (doc/derivations/multi_surface_clay.md,
 * sections 2 and 3).
 *
 * The backbone is the hyperbola capped at the undrained strength,
 *   tau_b(gamma) = min(G0 gamma / (1 + gamma / gamma_ref), s_u),     (B1)
 * so G / G0 = 1/2 at gamma_ref; it reaches s_u at
 *   gamma_f = gamma_ref s_u / (G0 gamma_ref - s_u),                  (B2)
 * which needs G0 gamma_ref > s_u.
 *
 * N elastic-perfectly plastic sub-elements in parallel (Iwan 1967) give, in
 * monotonic simple shear, tau(gamma) = sum_i min(G_i gamma, tau_i): a
 * polygon. It is built from the tangents of (B1) at N nodes t_j (in
 * u = gamma / gamma_ref), the last node at u_f = gamma_f / gamma_ref and
 * the cap as the last line, so that
 *   - tau = G0 gamma below the first yield (sum G_i = G0),
 *   - tau = s_u beyond gamma_f (sum tau_i = s_u),
 *   - tau = tau_b at every node.
 * The nodes are
 *   t_j = tan^2(j dpsi / 2), dpsi = 2 atan(sqrt(u_f)) / (N - 1),     (B3)
 * which spreads the relative error between nodes evenly; it is about
 * dpsi^2 / 4 (derivation section 3).
 *
 * A measured degradation curve (gamma_k, G/G0_k), k = 1..K, G/G0 = 1 at the
 * first, is taken as the polygon through tau_k = G0 gamma_k (G/G0)_k
 * (derivation section 7): linear between the points, continued beyond the
 * last with the last segment's slope, capped at s_u. Its sub-elements are
 * the polygon's kinks below the cap, so the model is that polygon exactly.
 */
#ifndef fourier_ssi_multi_surface_backbone_h
#define fourier_ssi_multi_surface_backbone_h

#include <utility>
#include <vector>

namespace FourierSSI
{
  /** The moduli and strengths of the N sub-elements fitted to (B1). */
  class MultiSurfaceBackbone
  {
  public:
    /**
     * G0 [kPa], s_u [kPa], gamma_ref and N >= 1. Throws one line if
     * G0 gamma_ref <= s_u with N > 1: the hyperbola never reaches s_u.
     * N = 1 is one von Mises element of modulus G0 and strength s_u.
     */
    MultiSurfaceBackbone(const double       shear_modulus,
                         const double       undrained_strength,
                         const double       reference_strain,
                         const unsigned int n_surfaces);

    /**
     * G0 [kPa], s_u [kPa] and a degradation table (gamma, G/G0), checked by
     * the input (SoilLaw::degradation). Throws one line if the polygon
     * cannot reach s_u (it ends below s_u on a flat last segment).
     */
    MultiSurfaceBackbone(
      const double                                  shear_modulus,
      const double                                  undrained_strength,
      const std::vector<std::pair<double, double>> &degradation);

    unsigned int
    n_surfaces() const
    {
      return moduli.size();
    }

    /** G_i [kPa] of sub-element i (sum = G0). */
    double
    shear_modulus(const unsigned int i) const
    {
      return moduli[i];
    }

    /** The simple-shear strength tau_i [kPa] of sub-element i (sum = s_u). */
    double
    strength(const unsigned int i) const
    {
      return strengths[i];
    }

    /** s_u [kPa]: the strengths' sum, the law's simple-shear strength. */
    double
    undrained_strength() const
    {
      return su;
    }

    /** The strain gamma_i = tau_i / G_i at which sub-element i yields. */
    double
    yield_strain(const unsigned int i) const
    {
      return strengths[i] / moduli[i];
    }

    /**
     * The engineering shear strains where the model meets its backbone:
     * gamma_ref t_j of (B3), or the table's strains below the cap.
     */
    const std::vector<double> &
    node_strains() const
    {
      return nodes;
    }

    /**
     * tau_b(gamma) [kPa], the curve the model fits: (B1), or the table's
     * polygon capped at s_u.
     */
    double
    backbone_stress(const double gamma) const;

    /** The model's monotonic simple-shear stress sum_i min(G_i g, tau_i). */
    double
    model_stress(const double gamma) const;

    /** gamma_f: where the backbone reaches s_u ((B2), or the table's). */
    double
    failure_strain() const;

  private:
    void
    fit_tangents(const unsigned int n_surfaces);

    /** The sub-elements of the polygon through `vertices` (from 0, 0). */
    void
    fit_polygon(const std::vector<std::pair<double, double>> &vertices);

    double              g0, su, gamma_ref = 0.;
    std::vector<double> moduli, strengths, nodes;
    /** The table's polygon (gamma, tau), up to gamma_f; empty: (B1). */
    std::vector<std::pair<double, double>> polygon;
  };
} // namespace FourierSSI

#endif
