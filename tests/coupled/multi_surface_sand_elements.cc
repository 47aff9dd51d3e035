// Element tests of the multi-surface sand (coupled/multi_surface_sand.h;
// doc/derivations/multi_surface_sand.md), p'0 = 100 kPa isotropic, c' = 2
// kPa, phi' = 35 degrees, psi = 0 unless stated, R_f = 0.9:
//  - one element is today's Mohr-Coulomb: the same stresses along a path
//    that loads, unloads and turns in all six components, to 1e-12 of p'0
//    (round-off: the two keep their plastic state differently);
//  - the backbone (S3) at a fixed mean stress and Lode angle, in simple
//    shear (tau_f = p'0 sin phi + c cos phi), isochoric triaxial
//    compression and extension (q_f = 6 (p'0 sin phi + c cos phi) /
//    (3 -+ sin phi)): the stress is q_f times the normalised polygon to
//    1e-12 (1e-10 in simple shear, whose principal axes the Jacobi
//    eigenvectors find at 1e-15 per return; the elements yield one by one,
//    as derived in section 1), and
//    against the hyperbola within 0.5 % for N = 20 at every strain up to
//    12 x_ref (the polygon's error, dpsi^2 / 4 = 0.38 % by (B3));
//  - failure is Mohr-Coulomb's: at 40 x_ref, beyond the last element's
//    yield, the three paths carry their Mohr-Coulomb strengths to 1e-12,
//    extension 22 % below compression as Mohr-Coulomb's Lode dependence
//    gives it (the same round-off bounds); and a drained triaxial compression
//    at constant sigma'_r with dilation (psi = 10 degrees) ends on sigma'_a =
//    sigma'_r N_phi + 2 c sqrt(N_phi) to 1e-9 (the lateral stress held by
//    Newton on the law's own tangent to 1e-10 kPa);
//  - Masing's rules in simple shear cycles +-gamma_a: the loop closes after
//    one cycle (1e-10 of tau_a, 10000 returns), and its damping ratio matches
//    the closed form of the hyperbola xi(x) = (4/pi)(1 + 1/x)(1 - ln(1 + x)/x)
//    - 2/pi, x = gamma_a / gamma_ref, within 2 % at x = 1, 3 and 9 (N = 20) and
//    at x = 0.1, 0.3 (N = 40): the clay's polygon, the same error
//    (multi_surface_clay_masing).
#include "check.h"
#include "multi_surface_sand_test_support.h"
#include "multi_surface_test_support.h"

#include <deal.II/base/numbers.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>

using namespace sand_test;

namespace
{
  const double     tau_f  = p0 * std::sin(phi) + cohesion * std::cos(phi);
  const double     q_f_tc = 6. * tau_f / (3. - std::sin(phi));
  const double     q_f_te = 6. * tau_f / (3. + std::sin(phi));
  constexpr double rf     = 0.9;
  /** x_ref: G / G0 = 1/2 on (S3). */
  constexpr double x_ref = 1. / rf;

  double
  hyperbola(const double x)
  {
    return std::min(x / (1. + rf * x), 1.);
  }

  void
  check_one_element_is_mohr_coulomb()
  {
    const SoilLaw          law = sand_law("psi=10, surfaces=1");
    const MultiSurfaceSand sand(law);
    SoilLaw                mc = law;
    mc.kind                   = SoilLaw::Kind::mohr_coulomb;
    const SoilReturnMapping mohr_coulomb(mc);
    SandPoint               point{sand};
    const double            lambda = bulk - 2. * g0 / 3.;
    StrainVector            strain{}, s_p{};
    double                  worst   = 0.;
    unsigned int            plastic = 0;
    for (unsigned int k = 0; k < 60; ++k)
      {
        // A path through every component and both signs, to 5 times the
        // elastic strain at failure.
        const double t = 0.3 * k;
        for (unsigned int c = 0; c < 6; ++c)
          strain[c] += 4e-4 * std::sin(t * (c + 1) + c);
        StrainVector trial = hooke_stress(strain, lambda, g0);
        for (unsigned int c = 0; c < 6; ++c)
          trial[c] += isotropic_stress()[c] - s_p[c];
        const SoilReturn   r = mohr_coulomb.return_map(trial, g0, bulk, 0.);
        const StrainVector elastic = hooke_stress(strain, lambda, g0);
        for (unsigned int c = 0; c < 6; ++c)
          s_p[c] = isotropic_stress()[c] + elastic[c] - r.stress[c];
        const MultiSurfaceStress s = point.step(strain);
        plastic += s.n_yielding;
        for (unsigned int c = 0; c < 6; ++c)
          worst = std::max(worst, std::abs(s.stress[c] - r.stress[c]));
      }
    check::that("one element: the path yields at 20 steps or more",
                plastic >= 20);
    check::small("one element - mohr-coulomb, largest |d sigma| / p'0",
                 worst / p0,
                 1e-12);
  }

  /** The stress measure of a path: tau_rz, or q = sigma_r - sigma_z. */
  double
  measure(const StrainVector &stress, const bool shear)
  {
    return shear ? stress[3] : stress[0] - stress[1];
  }

  void
  check_backbone(const std::string &name,
                 const bool         shear,
                 const double       sign,
                 const double       strength)
  {
    const MultiSurfaceSand      sand(sand_law("surfaces=20"));
    const MultiSurfaceBackbone &b = sand.normalised_backbone();
    // Simple shear turns each element's principal axes by 45 degrees: its
    // Jacobi eigenvectors round at 1e-15 per return, and 2400 committed
    // steps sum them (measured 3.5e-13); the triaxial paths stay on the
    // axes (1e-15).
    const double round_off = shear ? 1e-10 : 1e-12;
    SandPoint    point{sand};
    // x = G0 gamma / tau_f (shear), 3 G0 eps_q / q_f (triaxial).
    const double       unit = shear ? strength / g0 : strength / (3. * g0);
    double             own = 0., fit = 0.;
    const unsigned int n = 2400;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const double       x = 12. * x_ref * k / n;
        const StrainVector strain =
          shear ? simple_shear(x * unit) : isochoric_triaxial(sign * x * unit);
        const double value =
          sign * measure(point.step(strain).stress, shear) / strength;
        own = std::max(own, std::abs(value - b.model_stress(x)));
        fit = std::max(fit, std::abs(value - hyperbola(x)) / hyperbola(x));
      }
    check::small(name + ": stress / strength - the normalised polygon",
                 own,
                 round_off);
    check::small(name + ": |stress - hyperbola| / hyperbola up to 12 x_ref",
                 fit,
                 5e-3);
    const StrainVector far = shear ?
                               simple_shear(40. * x_ref * unit) :
                               isochoric_triaxial(sign * 40. * x_ref * unit);
    check::relative(name + ": the stress at 40 x_ref vs Mohr-Coulomb's",
                    sign * measure(point.step(far).stress, shear),
                    strength,
                    round_off);
  }

  /**
   * Drained triaxial compression at constant sigma_r = -p'0: the axial
   * strain driven, the lateral strain found by Newton on the tangent.
   */
  void
  check_drained_compression()
  {
    const MultiSurfaceSand sand(sand_law("psi=10, surfaces=20"));
    SandPoint              point{sand};
    double                 lateral = 0., worst_residual = 0., axial = 0.;
    const double           strain_to_failure = q_f_tc / (3. * g0);
    for (unsigned int k = 1; k <= 400; ++k)
      {
        const double eps_a = 100. * strain_to_failure * k / 400.;
        const auto   at    = [&](const double e, StressTangent *t) {
          return point.trial({{e, -eps_a, e, 0., 0., 0.}}, t);
        };
        for (unsigned int it = 0; it < 30; ++it)
          {
            StressTangent            d;
            const MultiSurfaceStress s        = at(lateral, &d);
            const double             residual = s.stress[0] + p0;
            if (std::abs(residual) < 1e-10)
              break;
            lateral -= residual / (d[0 * 6 + 0] + d[0 * 6 + 2]);
          }
        const MultiSurfaceStress s =
          point.step({{lateral, -eps_a, lateral, 0., 0., 0.}});
        worst_residual = std::max(worst_residual, std::abs(s.stress[0] + p0));
        axial          = -s.stress[1];
      }
    const double n_phi = (1. + std::sin(phi)) / (1. - std::sin(phi));
    check::small("drained: |sigma_r - sigma_r0| held by Newton [kPa]",
                 worst_residual,
                 1e-10);
    check::relative("drained, psi = 10: sigma'_a at 100 eps_f vs sigma'_r "
                    "N_phi + 2 c sqrt(N_phi)",
                    axial,
                    p0 * n_phi + 2. * cohesion * std::sqrt(n_phi),
                    1e-9);
  }


  /** Simple shear cycles at x = gamma_a / gamma_ref: closure and damping. */
  void
  check_cycles(const unsigned int n_surfaces, const double x)
  {
    const MultiSurfaceSand sand(
      sand_law("surfaces=" + std::to_string(n_surfaces)));
    SandPoint           point{sand};
    const double        gamma_ref = x_ref * tau_f / g0;
    const double        gamma_a   = x * gamma_ref;
    const unsigned int  steps     = 4000;
    std::vector<double> gamma, tau;
    const auto          go_to = [&](const double target, const unsigned int n) {
      const double from = gamma.empty() ? 0. : gamma.back();
      for (unsigned int k = 1; k <= n; ++k)
        {
          gamma.push_back(from + (target - from) * k / n);
          tau.push_back(point.step(simple_shear(gamma.back())).stress[3]);
        }
    };
    go_to(gamma_a, steps / 2);
    const unsigned int first = gamma.size() - 1;
    go_to(-gamma_a, steps);
    go_to(gamma_a, steps);
    const unsigned int end_1 = gamma.size() - 1;
    double             area  = 0.;
    for (unsigned int k = first + 1; k <= end_1; ++k)
      area += 0.5 * (tau[k] + tau[k - 1]) * (gamma[k] - gamma[k - 1]);
    const std::string at = "N = " + std::to_string(n_surfaces) +
                           ", x = " + std::to_string(x).substr(0, 4);
    // 10000 committed steps, each returned through Jacobi eigenvectors at
    // 1e-15 (measured <= 1e-12).
    check::small(at + ": tau after one cycle - first tau_a, / tau_a",
                 (tau[end_1] - tau[first]) / tau[first],
                 1e-10);
    const double xi = area / (4. * numbers::PI * 0.5 * tau[first] * gamma_a);
    check::relative(at + ": damping ratio vs the Masing hyperbola",
                    xi,
                    multi_surface_test::hyperbola_damping(x),
                    0.02);
  }
} // namespace

int
main()
{
  check_one_element_is_mohr_coulomb();
  check_backbone("simple shear", true, 1., tau_f);
  check_backbone("triaxial compression", false, 1., q_f_tc);
  check_backbone("triaxial extension", false, -1., q_f_te);
  check_drained_compression();
  for (const double x : {1., 3., 9.})
    check_cycles(20, x);
  for (const double x : {0.1, 0.3})
    check_cycles(40, x);
  return check::summary();
}
