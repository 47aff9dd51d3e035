// The closed-form return mapping of the Mohr-Coulomb interface with a tension
// cut-off (include/fourier_ssi/interfaces/interface_law.h,
// doc/nonlinear-interfaces.md section 2) against hand-computed cases, its
// consistency (returned tractions on the slip surface), the .prm syntax of the
// laws (the linear presets unchanged) and the rejected inputs.
//
// Hand cases: kn = 1000 kPa/m, ks = 500 kPa/m, c = 10 kPa, phi = 30 deg,
// initial traction t0 = (0, -100, 0) kPa (compression).
//  stick: d = (0.01, 0.02, 0.01) m -> t = (5, -80, 5), f < 0.
//  slip:  d = (0.2, 0, 0.1) -> trial (100, -100, 50), tau_tr = 111.8034,
//         f_tr = 111.8034 - 100 tan 30 - 10 = 44.06837; psi = 0: dl = f/ks,
//         tau = c + 100 tan 30 = 67.73503 in the trial direction
//         -> t = (60.58404986, -100, 30.29202493).
//  slip with psi = 10 deg: dl = f / (ks + kn tan30 tan10) = 0.07322731,
//         tau = 111.8034 - ks dl = 75.18974, t_n = -100 - kn tan10 dl
//         = -112.91195; check c + 112.91195 tan 30 = 75.18974.
//  open:  d = (0.1, 0.15, 0) -> t_n,tr = +50 > sigma_t = 0 -> t = 0,
//         d_p = d + t0 / k = (0.1, 0.05, 0).
// Tolerances: 1e-12 relative for the closed forms (a few roundings of
// numbers of order 100); the hand values are printed to 7 digits, so they
// are compared at 1e-9.
#include "check.h"

#include <cmath>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/interfaces/interface_law.h>
#include <random>

using namespace FourierSSI;

namespace
{
  InterfaceLaw
  law_of(const std::string &text)
  {
    return InterfaceParameters::parse_list("5: " + text).at(5);
  }

  void
  check_traction(const std::string         &what,
                 const ReturnMappingResult &result,
                 const LocalVector         &expected,
                 const double               tolerance)
  {
    const char *name[3] = {"t_s", "t_n", "t_theta"};
    for (unsigned int c = 0; c < 3; ++c)
      check::relative(
        what + " " + name[c], result.traction[c], expected[c], tolerance, 1.);
  }

  std::string
  error_of(const std::string &text)
  {
    try
      {
        InterfaceParameters::parse_list(text);
      }
    catch (const std::exception &e)
      {
        return one_line_message(e);
      }
    return "";
  }

  void
  hand_cases()
  {
    std::cout << "hand-computed cases" << std::endl;
    const MohrCoulombInterface law(
      law_of("coulomb, kn=1000, ks=500, c=10, phi=30"));
    const LocalVector t0   = {{0., -100., 0.}};
    const LocalVector zero = {{0., 0., 0.}};

    const auto stick = law.return_map({{0.01, 0.02, 0.01}}, t0, zero);
    check::that("stick state", stick.state == ContactState::stick);
    check_traction("stick", stick, {{5., -80., 5.}}, 1e-12);

    const auto slip = law.return_map({{0.2, 0., 0.1}}, t0, zero);
    check::that("slip state", slip.state == ContactState::slip);
    check_traction("slip", slip, {{60.58404986, -100., 30.29202493}}, 1e-9);
    check::relative("slip plastic d_s",
                    slip.plastic[0],
                    0.08813674 * 100. / 111.8033989,
                    1e-7);

    const MohrCoulombInterface dilatant(
      law_of("coulomb, kn=1000, ks=500, c=10, phi=30, psi=10"));
    const auto dilated = dilatant.return_map({{0.2, 0., 0.1}}, t0, zero);
    check::relative("dilatant slip tau",
                    std::hypot(dilated.traction[0], dilated.traction[2]),
                    75.18974,
                    1e-7);
    check::relative("dilatant slip t_n", dilated.traction[1], -112.91195, 1e-7);
    check::relative("dilatant slip opening d_p,n",
                    dilated.plastic[1],
                    0.07322731 * std::tan(10. * M_PI / 180.),
                    1e-6);

    const auto open = law.return_map({{0.1, 0.15, 0.}}, t0, zero);
    check::that("open state", open.state == ContactState::open);
    check_traction("open", open, {{0., 0., 0.}}, 0.);
    check::relative("open gap d_p,n", open.plastic[1], 0.05, 1e-12);
    check::relative("open d_p,s", open.plastic[0], 0.1, 1e-12);

    // Unloading after slip: back to zero relative displacement, the
    // plastic slip stays, the reversed shear -ks d_p is inside the cone.
    const auto back = law.return_map({{0., 0., 0.}}, t0, slip.plastic);
    check::that("unloading after slip sticks",
                back.state == ContactState::stick);
    check::relative("unloading t_s = -ks d_p,s",
                    back.traction[0],
                    -500. * slip.plastic[0],
                    1e-12);

    // Re-closing a gap: contact comes back where it was lost (d_n = 0.15,
    // t = t0 + kn (d_n - d_p,n) = 0 there), so at d_n = 0.14 the normal
    // traction is -100 + 1000 (0.14 - 0.05) = -10 kPa.
    const auto closed = law.return_map({{0.1, 0.14, 0.}}, t0, open.plastic);
    check::relative("re-closing t_n", closed.traction[1], -10., 1e-12);
  }

  // Where the slip cone meets the cut-off. Cohesionless and tensionless:
  // the cone's apex is t = 0 and the traction is continuous across the
  // slip/open boundary. Cohesive with sigma_t = 5 kPa (apex c/tan30 =
  // 17.3 kPa): below the cut-off the shear is limited to c - t_n tan(phi),
  // above it the interface is open.
  void
  corner_cases()
  {
    std::cout << "the corner (slip cone meets the tension cut-off)"
              << std::endl;
    const MohrCoulombInterface apex(law_of("coulomb, kn=1000, ks=500, phi=30"));
    const LocalVector          zero  = {{0., 0., 0.}};
    const double               small = 1e-9;
    const auto below = apex.return_map({{0.3, -small / 1000., 0.}}, zero, zero);
    const auto above = apex.return_map({{0.3, small / 1000., 0.}}, zero, zero);
    check::that("just below the apex: slip", below.state == ContactState::slip);
    check::that("just above the apex: open", above.state == ContactState::open);
    check::small("traction jump across the apex [kPa]",
                 std::hypot(below.traction[0] - above.traction[0],
                            below.traction[1] - above.traction[1]),
                 2. * small);

    const MohrCoulombInterface cohesive(
      law_of("coulomb, kn=1000, ks=500, c=10, phi=30, sigma_t=5"));
    const auto slip = cohesive.return_map({{0.04, 0.004, 0.}}, zero, zero);
    check::that("t_n = 4 < sigma_t: slip", slip.state == ContactState::slip);
    check::relative("shear at t_n = 4: c - 4 tan30",
                    slip.traction[0],
                    10. - 4. * std::tan(M_PI / 6.),
                    1e-12);
    const auto open = cohesive.return_map({{0.04, 0.006, 0.}}, zero, zero);
    check::that("t_n = 6 > sigma_t: open", open.state == ContactState::open);
  }

  // Random trials over all cases: t = t0 + D (d - d_p) always; slip ends on
  // f = 0 (|f| <= 1e-12 of the traction scale); stick has f <= 0; the
  // returned shear is parallel to the trial shear.
  void
  consistency()
  {
    std::cout << "consistency of 20000 random returns" << std::endl;
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> u(-1., 1.);
    double       worst_f = 0., worst_identity = 0., worst_direction = 0.;
    unsigned int counts[3] = {0, 0, 0};
    for (unsigned int trial = 0; trial < 20000; ++trial)
      {
        const double phi     = 45. * (1. + u(random)) / 2.;
        const double psi     = phi * (1. + u(random)) / 2.;
        const double c       = 20. * (1. + u(random)) / 2.;
        const double sigma_t = 0.5 * c /
                               std::tan(std::max(phi, 1.) * M_PI / 180.) *
                               (1. + u(random)) / 2.;
        InterfaceLaw law;
        law.kind           = InterfaceLaw::Kind::coulomb;
        law.normal         = 2000.;
        law.shear          = 700.;
        law.cohesion       = c;
        law.friction_angle = std::max(phi, 1.);
        law.dilation_angle = std::min(psi, law.friction_angle);
        law.tension_cutoff = sigma_t;
        const MohrCoulombInterface mc(law);
        const LocalVector          d = {
                   {0.2 * u(random), 0.05 * u(random), 0.2 * u(random)}};
        const LocalVector t0 = {
          {10. * u(random), -100. * (1. + u(random)), 0.}};
        const LocalVector dp = {{0.02 * u(random), 0., 0.02 * u(random)}};
        const auto        r  = mc.return_map(d, t0, dp);
        ++counts[static_cast<int>(r.state)];
        const double scale = 100.;
        if (r.state == ContactState::open)
          continue;
        const LocalVector k = {{700., 2000., 700.}};
        for (unsigned int i = 0; i < 3; ++i)
          worst_identity = std::max(worst_identity,
                                    std::abs(r.traction[i] - t0[i] -
                                             k[i] * (d[i] - r.plastic[i])) /
                                      scale);
        const double f = mc.yield_function(r.traction);
        if (r.state == ContactState::slip)
          {
            worst_f         = std::max(worst_f, std::abs(f) / scale);
            const double ts = t0[0] + k[0] * (d[0] - dp[0]),
                         tt = t0[2] + k[2] * (d[2] - dp[2]);
            worst_direction =
              std::max(worst_direction,
                       std::abs(ts * r.traction[2] - tt * r.traction[0]) /
                         (scale * scale));
          }
        else
          worst_f = std::max(worst_f, std::max(f, 0.) / scale);
      }
    std::cout << "  cases: " << counts[0] << " stick, " << counts[1]
              << " slip, " << counts[2] << " open" << std::endl;
    check::that("every case occurs",
                counts[0] > 100 && counts[1] > 100 && counts[2] > 100);
    check::small("max |f| on slip, f+ on stick / 100 kPa", worst_f, 1e-12);
    check::small("max |t - t0 - D (d - d_p)| / 100 kPa", worst_identity, 1e-12);
    check::small("max shear direction change", worst_direction, 1e-12);
  }

  void
  syntax()
  {
    std::cout << "syntax: linear presets unchanged, coulomb entries"
              << std::endl;
    const auto laws = InterfaceParameters::parse_list(
      "1: rough; 2: smooth; 3: kn=1e8, ks=0; 4: vermeer, mu=50; 6: tied; "
      "7: tied-normal; 8: coulomb, kn=1e6, ks=2e6, c=5, phi=25, psi=5, "
      "sigma_t=1; 9: coulomb, kn=1e6, ks=1e6, phi=0, sigma_t=none");
    check::that("rough", laws.at(1).normal == 1e10 && laws.at(1).shear == 1e10);
    check::that("smooth", laws.at(2).normal == 1e10 && laws.at(2).shear == 0.);
    check::that("kn, ks", laws.at(3).normal == 1e8 && laws.at(3).shear == 0.);
    check::that("vermeer",
                laws.at(4).kind == InterfaceLaw::Kind::vermeer &&
                  laws.at(4).mu == 50.);
    check::that("tied",
                laws.at(6).kind == InterfaceLaw::Kind::tied &&
                  laws.at(7).kind == InterfaceLaw::Kind::tied_normal);
    check::that("linear laws are linear",
                !laws.at(1).is_nonlinear() && !laws.at(3).is_nonlinear());
    const InterfaceLaw &c = laws.at(8);
    check::that("coulomb entries",
                c.kind == InterfaceLaw::Kind::coulomb && c.normal == 1e6 &&
                  c.shear == 2e6 && c.cohesion == 5. &&
                  c.friction_angle == 25. && c.dilation_angle == 5. &&
                  c.tension_cutoff == 1.);
    check::that("sigma_t default 0 (tensionless)",
                law_of("coulomb, kn=1, ks=1, phi=20").tension_cutoff == 0.);
    check::that("sigma_t=none", std::isinf(laws.at(9).tension_cutoff));
    const InterfaceLaw contact = law_of("contact, c=2, phi=20");
    check::that("contact: tensionless, no dilation, no springs given",
                contact.kind == InterfaceLaw::Kind::contact &&
                  contact.is_nonlinear() && contact.cohesion == 2. &&
                  contact.friction_angle == 20. &&
                  contact.tension_cutoff == 0. &&
                  contact.dilation_angle == 0. && contact.normal == 0.);
    const InterfaceLaw automatic = law_of("coulomb, kn=auto, ks=auto, phi=20");
    check::that("kn=auto, ks=auto",
                automatic.automatic_normal && automatic.automatic_shear);

    const std::pair<std::string, std::string> bad[] = {
      {"5: coulomb, kn=1e6, ks=1e6, phi=90", "phi must be below 90"},
      {"5: coulomb, kn=1e6, ks=1e6, phi=-5", "phi must be >= 0"},
      {"5: coulomb, kn=1e6, ks=1e6, phi=20, c=-1", "c must be >= 0"},
      {"5: coulomb, kn=1e6, ks=1e6, phi=20, sigma_t=-1",
       "sigma_t must be >= 0"},
      {"5: coulomb, kn=0, ks=1e6, phi=20", "kn > 0 and ks > 0"},
      {"5: coulomb, kn=1e6, ks=1e6, phi=20, psi=30", "psi must not exceed phi"},
      {"5: coulomb, kn=1e6, ks=1e6, phi=30, c=1, sigma_t=5", "apex"},
      {"5: coulomb, kn=1e6, ks=1e6", "needs kn, ks and phi"},
      {"5: rough, phi=30", "belong to the coulomb and contact laws"},
      {"5: contact, kn=1e6, phi=20", "contact takes no kn or ks"},
      {"5: contact, ks=auto, phi=20", "contact takes no kn or ks"},
      {"5: contact, phi=90", "contact phi must be below 90"},
      {"5: contact, c=1", "contact needs phi"},
      {"5: contact, phi=20, sigma_t=0", "contact takes no psi or sigma_t"},
      {"5: kn=auto, ks=1e6", "kn=auto, ks=auto belong to the coulomb law"}};
    for (const auto &[text, expected] : bad)
      {
        const std::string message = error_of(text);
        check::that("'" + text + "' rejected: " + message,
                    message.find(expected) != std::string::npos &&
                      message.find("Interfaces/Interfaces") !=
                        std::string::npos);
      }
  }
} // namespace

int
main()
{
  hand_cases();
  corner_cases();
  consistency();
  syntax();
  return check::summary();
}
