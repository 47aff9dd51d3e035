// The closed-form consistent tangent D_t = dt/dd of the Mohr-Coulomb
// interface return mapping (include/fourier_ssi/interfaces/interface_law.h,
// derived in doc/derivations/interface_consistent_tangent.py) against
// central differences of the return mapping, at random states built in
// each regime: stick, slip, open, and both sides of the corner where the
// slip cone meets the tension cut-off (t_n,tr = sigma_t with the trial shear
// above the cone). Each state is built from a chosen trial traction
// (d = d_p + D^-1 (t_tr - t0)), so its regime is known before the return
// mapping is called; the state label must name it.
//
// Difference step and tolerance: h = 1e-6 T / k_max with T = 100 kPa the
// traction scale. Central differences err by the truncation
// h^2 |t'''| / 6 <= k (h k / tau_tr)^2 / 6 (the radial return turns the
// shear direction over a relative displacement tau_tr / ks; the states keep
// tau_tr >= 1 kPa, so <= 2e-9 k) plus the round-off eps |t| / h
// <= 2.2e-16 * 400 kPa / h = 9e-10 k_max. The tolerance 1e-6 k_max is 500
// times both; a wrong term of the tangent (e.g. the dilation coupling
// kn tan(psi) / H, or the radial factor rho) is 1e-3 to 1 of k. The corner
// states sit 50 steps from the boundary so that no difference crosses it.
#include "check.h"

#include <algorithm>
#include <cmath>
#include <fourier_ssi/interfaces/interface_law.h>
#include <random>

using namespace FourierSSI;

namespace
{
  const double traction_scale = 100.; // T [kPa]

  /** A random coulomb law: kn, ks over three decades, phi, psi, c. */
  InterfaceLaw
  random_law(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> u(0., 1.);
    InterfaceLaw                           law;
    law.kind           = InterfaceLaw::Kind::coulomb;
    law.normal         = std::pow(10., 3. + 3. * u(random));
    law.shear          = std::pow(10., 3. + 3. * u(random));
    law.friction_angle = 1. + 44. * u(random);
    law.dilation_angle = law.friction_angle * u(random);
    law.cohesion       = 20. * u(random);
    const double apex =
      law.cohesion / std::tan(law.friction_angle * M_PI / 180.);
    law.tension_cutoff = apex * u(random);
    return law;
  }

  enum class Regime
  {
    stick,
    slip,
    open,
    corner_slip,
    corner_open
  };

  /**
   * A trial traction in the regime asked for; `offset` [kPa] is the
   * distance of t_n,tr from sigma_t in the corner regimes.
   */
  LocalVector
  trial_in(const Regime        regime,
           const InterfaceLaw &law,
           const double        offset,
           std::mt19937       &random)
  {
    std::uniform_real_distribution<double> u(0., 1.);
    const double tan_phi = std::tan(law.friction_angle * M_PI / 180.);
    double       t_n     = law.tension_cutoff - 200. * u(random) - 1.;
    if (regime == Regime::open)
      t_n = law.tension_cutoff + 1. + 100. * u(random);
    if (regime == Regime::corner_slip)
      t_n = law.tension_cutoff - offset;
    if (regime == Regime::corner_open)
      t_n = law.tension_cutoff + offset;
    // The shear capacity at this t_n (the cone), and a trial shear inside
    // it (stick) or above it (the others).
    const double capacity = law.cohesion - t_n * tan_phi;
    const double tau      = regime == Regime::stick ?
                              std::max(capacity, 0.) * (0.05 + 0.9 * u(random)) :
                              std::max(capacity, 0.) + 1. + 100. * u(random);
    const double angle    = 2. * M_PI * u(random);
    return {{tau * std::cos(angle), t_n, tau * std::sin(angle)}};
  }

  ContactState
  label_of(const Regime regime)
  {
    switch (regime)
      {
        case Regime::stick:
          return ContactState::stick;
        case Regime::slip:
        case Regime::corner_slip:
          return ContactState::slip;
        default:
          return ContactState::open;
      }
  }

  /**
   * The largest |D_t - central difference| over the nine entries, divided
   * by k_max.
   */
  double
  difference_error(const MohrCoulombInterface &law,
                   const LocalVector          &d,
                   const LocalVector          &t0,
                   const LocalVector          &plastic,
                   const double                h,
                   const double                k_max)
  {
    const ReturnMappingResult at    = law.return_map(d, t0, plastic);
    double                    worst = 0.;
    for (unsigned int b = 0; b < 3; ++b)
      {
        LocalVector plus = d, minus = d;
        plus[b] += h;
        minus[b] -= h;
        const LocalVector t_plus  = law.return_map(plus, t0, plastic).traction;
        const LocalVector t_minus = law.return_map(minus, t0, plastic).traction;
        for (unsigned int a = 0; a < 3; ++a)
          worst = std::max(worst,
                           std::abs((t_plus[a] - t_minus[a]) / (2. * h) -
                                    at.tangent[a * 3 + b]) /
                             k_max);
      }
    return worst;
  }

  void
  regime(const Regime regime, const std::string &name, const unsigned int n)
  {
    std::mt19937                           random(11 + int(regime));
    std::uniform_real_distribution<double> u(-1., 1.);
    double                                 worst    = 0.;
    unsigned int                           mislabel = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const InterfaceLaw law   = random_law(random);
        const double       k_max = std::max(law.normal, law.shear);
        const double       h     = 1e-6 * traction_scale / k_max;
        // 50 steps in traction from the corner's boundary.
        const double      offset = 50. * h * law.normal;
        const LocalVector trial  = trial_in(regime, law, offset, random);
        const LocalVector t0 = {{10. * u(random), -50. + 50. * u(random), 0.}};
        const LocalVector plastic = {
          {0.1 * u(random) * traction_scale / law.shear,
           0.,
           0.1 * u(random) * traction_scale / law.shear}};
        const LocalVector k = {{law.shear, law.normal, law.shear}};
        LocalVector       d;
        for (unsigned int c = 0; c < 3; ++c)
          d[c] = plastic[c] + (trial[c] - t0[c]) / k[c];
        const MohrCoulombInterface mc(law);
        if (mc.return_map(d, t0, plastic).state != label_of(regime))
          ++mislabel;
        worst = std::max(worst, difference_error(mc, d, t0, plastic, h, k_max));
      }
    std::cout << name << ": " << n << " random states" << std::endl;
    check::that(name + ": every state labelled " + to_string(label_of(regime)),
                mislabel == 0);
    check::small(name + ": max |D_t - central difference| / k_max",
                 worst,
                 1e-6);
  }

  // Hand case of the slip tangent (kn = 1000, ks = 500, c = 10, phi = 30,
  // psi = 10, t0 = (0, -100, 0), d = (0.2, 0, 0)): trial (100, -100, 0),
  // m = (1, 0, 0), H = 500 + 1000 tan30 tan10 = 601.8024, so
  // dt_s/dd_s = ks kn tan30 tan10 / H = 84.5813, dt_s/dd_n = -ks kn tan30 / H
  // = -479.6842, dt_n/dd_s = -ks kn tan10 / H = -146.4991, dt_n/dd_n =
  // ks kn / H = 830.8375 kPa/m, dt_theta/dd_theta = ks rho = 365.9653 with
  // rho = tau / tau_tr = (100 - ks dl) / 100, dl = (100 - 100 tan30 - 10) / H.
  void
  hand_case()
  {
    std::cout << "hand case of the slip tangent" << std::endl;
    InterfaceLaw law;
    law.kind           = InterfaceLaw::Kind::coulomb;
    law.normal         = 1000.;
    law.shear          = 500.;
    law.cohesion       = 10.;
    law.friction_angle = 30.;
    law.dilation_angle = 10.;
    const MohrCoulombInterface mc(law);
    const auto   r   = mc.return_map({{0.2, 0., 0.}}, {{0., -100., 0.}}, {});
    const double t30 = std::tan(M_PI / 6.), t10 = std::tan(M_PI / 18.);
    const double H  = 500. + 1000. * t30 * t10;
    const double dl = (100. - 100. * t30 - 10.) / H;
    check::that("slip state", r.state == ContactState::slip);
    check::relative("dt_s/dd_s", r.tangent[0], 500e3 * t30 * t10 / H, 1e-12);
    check::relative("dt_s/dd_n", r.tangent[1], -500e3 * t30 / H, 1e-12);
    check::relative("dt_n/dd_s", r.tangent[3], -500e3 * t10 / H, 1e-12);
    check::relative("dt_n/dd_n", r.tangent[4], 500e3 / H, 1e-12);
    check::relative("dt_theta/dd_theta",
                    r.tangent[8],
                    500. * (100. - 500. * dl) / 100.,
                    1e-12);
    check::small("dt_s/dd_theta (m_theta = 0)", r.tangent[2], 1e-12);
  }
} // namespace

int
main()
{
  hand_case();
  regime(Regime::stick, "stick", 2000);
  regime(Regime::slip, "slip", 2000);
  regime(Regime::open, "open", 2000);
  regime(Regime::corner_slip, "corner, slip side", 2000);
  regime(Regime::corner_open, "corner, open side", 2000);
  return check::summary();
}
