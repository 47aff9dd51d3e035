#include <cmath>
#include <deal.II/base/exceptions.h>
#include <fourier_ssi/postprocess/pile_head_formulas.h>

namespace FourierSSI
{
  namespace
  {
    /** The mean of f over (0, L), composite Simpson rule (G is smooth). */
    double
    mean_over(const std::function<double(double)> &f, const double L)
    {
      const unsigned int n   = 256; // even
      const double       h   = L / n;
      double             sum = f(0.) + f(L);
      for (unsigned int i = 1; i < n; ++i)
        sum += (i % 2 == 1 ? 4. : 2.) * f(i * h);
      return sum * h / 3. / L;
    }
  } // namespace

  PileHeadStiffness
  randolph_flexible_pile(const double                         D,
                         const double                         E_p,
                         const double                         nu,
                         const std::function<double(double)> &G)
  {
    const auto G_star = [&](const double depth) {
      return G(depth) * (1. + 0.75 * nu);
    };
    // l_c = D (E_p / G_c(l_c))^(2/7) by fixed-point iteration: a
    // contraction, since G_c grows at most linearly with l_c (factor 2/7).
    double l_c = D * std::pow(E_p / G_star(D), 2. / 7.);
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double next = D * std::pow(E_p / mean_over(G_star, l_c), 2. / 7.);
        const bool   done = std::abs(next - l_c) <= 1e-14 * l_c;
        l_c               = next;
        if (done)
          break;
      }
    const double G_c   = mean_over(G_star, l_c);
    const double rho_c = G_star(l_c / 4.) / G_star(l_c / 2.);
    AssertThrow(std::isfinite(l_c) && G_c > 0. && rho_c > 0.,
                dealii::ExcMessage("Randolph (1981): no critical length for "
                                   "this soil (G = 0 near the surface?)"));
    // The flexibility [u, theta] = F [H, M] (header), then K = F^-1.
    const double      s    = std::pow(E_p / G_c, 1. / 7.) / (rho_c * G_c);
    const double      l    = l_c / 2.;
    const double      F_HH = s * 0.27 / l;
    const double      F_HM = s * 0.3 / (l * l);
    const double      F_MM = s * 0.8 / std::sqrt(rho_c) / (l * l * l);
    const double      det  = F_HH * F_MM - F_HM * F_HM;
    PileHeadStiffness k;
    k.K_H                = F_MM / det;
    k.K_M                = F_HH / det;
    k.K_MH               = -F_HM / det;
    k.critical_length    = l_c;
    k.homogeneity_factor = rho_c;
    return k;
  }
} // namespace FourierSSI
