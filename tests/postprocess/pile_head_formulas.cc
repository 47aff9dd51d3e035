// Randolph's (1981) flexible-pile formula as printed beside a pile scene's
// K_H, K_M, K_MH (pile_head_formulas.h): its critical length against the
// two closed forms Randolph gives (homogeneous soil: l_c = D (E_p /
// G*)^(2/7); G = m depth: l_c = D (2 E_p / (m* D))^(2/9), rho_c = 1/2), and
// the stiffness against the inverse of his flexibility written out by hand
// for homogeneous soil (the inversion and the sign of K_MH); and, on the
// flexible pile of prm/pile.prm made twice as long (L = 20 m, L/l_c = 2.2)
// in homogeneous soil (G = 1000 kPa, E_p = 2500 G), the printed formula
// against the computed K_H, K_M, K_MH: within 10 % (Randolph fitted his
// expressions to finite-element results for elastic continua; the ratios
// measured here are 1.045, 0.943, 0.990).
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/postprocess/pile_head_formulas.h>

using namespace FourierSSI;

namespace
{
  /** prm/pile.prm, homogeneous soil, L = 20 m, with the pile formula. */
  std::string
  long_pile_scene()
  {
    return test_support::bundled_prm("prm/pile.prm") +
           "subsection Mesh\n set Z breakpoints = -40, -20, 0\n"
           " set Z cells = 8, 24\n set Z growth = 0.8, 0.85\n"
           " set Material regions = 1: 0, 0.5, -20, 0\n"
           " set Interface lines = 5: r=0.5, z=-20..0; 5: z=-20, r=0..0.5\n"
           "end\n"
           "subsection Materials\n"
           " set Materials = 0: G=1000, nu=0.25; 1: G=1e6, nu=0.25\nend\n"
           "subsection Rigid foundation\n set Pile diameter = 1\n"
           " set Pile length = 20\n set Pile Young modulus = 2.5e6\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double D = 1., E_p = 2.5e6, nu = 0.25, G_star_factor = 1. + 0.75 * nu;

  // Homogeneous soil, G = 1000 kPa: G_c = G* at every l_c, so the
  // fixed point is explicit. The Simpson mean of a constant is exact:
  // round-off only (1e-12).
  const double            G = 1000., G_star = G * G_star_factor;
  const PileHeadStiffness h =
    randolph_flexible_pile(D, E_p, nu, [&](double) { return G; });
  const double l_c = D * std::pow(E_p / G_star, 2. / 7.);
  check::relative("homogeneous l_c = D (E_p/G*)^(2/7)",
                  h.critical_length,
                  l_c,
                  1e-12);
  check::relative("homogeneous rho_c = 1", h.homogeneity_factor, 1., 1e-12);
  // Randolph's flexibility with rho_c = 1, inverted by hand.
  const double s = std::pow(E_p / G_star, 1. / 7.) / G_star, l = l_c / 2.;
  const double u_H = s * 0.27 / l, u_M = s * 0.3 / (l * l),
               t_M = s * 0.8 / (l * l * l);
  const double det = u_H * t_M - u_M * u_M;
  check::relative("homogeneous K_H = inverse of the flexibility",
                  h.K_H,
                  t_M / det,
                  1e-12);
  check::relative("homogeneous K_M", h.K_M, u_H / det, 1e-12);
  check::relative("homogeneous K_MH (negative: theta > 0 under H)",
                  h.K_MH,
                  -u_M / det,
                  1e-12);

  // G = m depth (Gibson), m = 100 kPa/m: G_c = m* l_c / 2, so
  // l_c = D (2 E_p / (m* D))^(2/9). The Simpson mean of a linear G is
  // exact; the fixed point converges to round-off (1e-12).
  const double            m = 100., m_star = m * G_star_factor;
  const PileHeadStiffness g =
    randolph_flexible_pile(D, E_p, nu, [&](double z) { return m * z; });
  check::relative("Gibson l_c = D (2 E_p/(m* D))^(2/9)",
                  g.critical_length,
                  D * std::pow(2. * E_p / (m_star * D), 2. / 9.),
                  1e-12);
  check::relative("Gibson rho_c = 1/2", g.homogeneity_factor, 0.5, 1e-12);
  check::that("Gibson soil is softer near the surface: lower K_H",
              g.K_H < h.K_H);

  const ResultsTable r = test_support::run(long_pile_scene());
  const Harmonic     lateral{1, Family::symmetric};
  check::relative("long flexible pile: l_c printed",
                  r.get("randolph_critical_length", lateral, 0),
                  l_c,
                  1e-12);
  for (const std::string term : {"K_H", "K_M", "K_MH"})
    check::relative("long flexible pile: computed " + term +
                      " vs Randolph (1981)",
                    r.get(term, lateral, 0),
                    r.get("randolph_" + term, lateral, 0),
                    0.1);
  return check::summary();
}
