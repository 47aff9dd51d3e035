/**
 * A published pile-head formula for a laterally loaded pile, printed beside
 * the computed K_H, K_M, K_MH of a pile scene so that the user sees where
 * the formula stands (doc/foundation-stiffness.md).
 *
 * Randolph (1981), "The response of flexible piles to lateral loading",
 * Geotechnique 31(2): a pile longer than its critical length l_c in an
 * elastic soil with shear modulus G(depth), loaded at the ground surface:
 *   G*    = G (1 + 3 nu / 4),
 *   G_c   = the mean of G* over 0 < depth < l_c,
 *   l_c   = D (E_p / G_c)^(2/7)   (an equation for l_c, since G_c depends
 *                                  on it; D (E_p / G*)^(2/7) in
 *                                  homogeneous soil),
 *   rho_c = G*(l_c / 4) / G*(l_c / 2),
 *   u     = (E_p / G_c)^(1/7) / (rho_c G_c)
 *             [0.27 H (l_c/2)^-1 + 0.3 M (l_c/2)^-2],
 *   theta = (E_p / G_c)^(1/7) / (rho_c G_c)
 *             [0.3 H (l_c/2)^-2 + 0.8 rho_c^(-1/2) M (l_c/2)^-3],
 * with E_p the Young's modulus of the solid circular pile of the same
 * bending stiffness (E I / (pi D^4 / 64)). Its stiffness is the inverse of
 * this flexibility; theta > 0 under H in the convention of
 * rigid_foundation.h, so the coupling term is negative as ours.
 */
#ifndef fourier_ssi_pile_head_formulas_h
#define fourier_ssi_pile_head_formulas_h

#include <functional>

namespace FourierSSI
{
  struct PileHeadStiffness
  {
    double K_H                = 0.; // H / u [kN/m]
    double K_M                = 0.; // M / theta [kN.m/rad]
    double K_MH               = 0.; // H / theta at u = 0 [kN/rad]
    double critical_length    = 0.; // l_c [m]
    double homogeneity_factor = 0.; // rho_c
  };

  /**
   * Randolph's (1981) flexible-pile head stiffness (header) for a pile of
   * diameter D [m] and equivalent Young's modulus E_p [kPa] in a soil of
   * Poisson's ratio nu and shear modulus G(depth) [kPa].
   */
  PileHeadStiffness
  randolph_flexible_pile(const double                         diameter,
                         const double                         pile_modulus,
                         const double                         poisson_ratio,
                         const std::function<double(double)> &shear_modulus);
} // namespace FourierSSI

#endif
