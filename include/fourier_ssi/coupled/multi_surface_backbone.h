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
 */
#ifndef fourier_ssi_multi_surface_backbone_h
#define fourier_ssi_multi_surface_backbone_h

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

    /** The engineering shear strains gamma_ref t_j of the nodes (B3). */
    const std::vector<double> &
    node_strains() const
    {
      return nodes;
    }

    /** tau_b(gamma) of (B1) [kPa], the closed form the model fits. */
    double
    backbone_stress(const double gamma) const;

    /** The model's monotonic simple-shear stress sum_i min(G_i g, tau_i). */
    double
    model_stress(const double gamma) const;

    /** gamma_f of (B2): where the backbone reaches s_u. */
    double
    failure_strain() const;

  private:
    void
    fit_tangents(const unsigned int n_surfaces);

    double              g0, su, gamma_ref;
    std::vector<double> moduli, strengths, nodes;
  };
} // namespace FourierSSI

#endif
