#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <fourier_ssi/interfaces/interface_law.h>

namespace FourierSSI
{
  MohrCoulombInterface::MohrCoulombInterface(const InterfaceLaw &law)
    : MohrCoulombInterface(law, law.normal, law.shear)
  {}

  MohrCoulombInterface::MohrCoulombInterface(const InterfaceLaw &law,
                                             const double        kn,
                                             const double        ks)
    : kn(kn)
    , ks(ks)
    , cohesion(law.cohesion)
    , tan_phi(std::tan(law.friction_angle * numbers::PI / 180.))
    , tan_psi(std::tan(law.dilation_angle * numbers::PI / 180.))
    , tension_cutoff(law.tension_cutoff)
  {}

  double
  MohrCoulombInterface::yield_function(const LocalVector &t) const
  {
    return std::hypot(t[0], t[2]) + t[1] * tan_phi - cohesion;
  }

  ReturnMappingResult
  MohrCoulombInterface::return_map(const LocalVector &d,
                                   const LocalVector &t0,
                                   const LocalVector &old_plastic) const
  {
    const LocalVector   stiffness = {{ks, kn, ks}};
    ReturnMappingResult result;
    result.plastic = old_plastic;
    for (unsigned int c = 0; c < 3; ++c)
      result.traction[c] = t0[c] + stiffness[c] * (d[c] - old_plastic[c]);
    const LocalVector trial = result.traction;

    // Open (decollement): no force across the gap; the plastic part takes
    // the whole relative displacement beyond the unloaded state, so that
    // re-closing starts from t = 0. The tangent is zero.
    if (trial[1] > tension_cutoff)
      {
        result.state    = ContactState::open;
        result.traction = {{0., 0., 0.}};
        for (unsigned int c = 0; c < 3; ++c)
          result.plastic[c] = d[c] + t0[c] / stiffness[c];
        return result;
      }

    const double f_trial = yield_function(trial);
    if (f_trial <= 0.)
      {
        for (unsigned int c = 0; c < 3; ++c)
          result.tangent[c * 3 + c] = stiffness[c];
        return result; // stick
      }

    // Slip: one multiplier dl on the plastic potential
    // g = tau + t_n tan(psi): d_p += dl (tau-direction, tan(psi), ...).
    // On this branch tau_tr >= f_trial > 0: t_n,tr <= sigma_t <= c/tan(phi)
    // (the apex), so the direction m is defined.
    result.state           = ContactState::slip;
    const double tau_tr    = std::hypot(trial[0], trial[2]);
    const double hardening = ks + kn * tan_phi * tan_psi;
    const double dl        = f_trial / hardening;
    const double tau       = tau_tr - ks * dl;
    const double scale     = tau / tau_tr;
    result.traction[0]     = scale * trial[0];
    result.traction[2]     = scale * trial[2];
    result.traction[1]     = trial[1] - kn * tan_psi * dl;
    result.plastic[0] += dl * trial[0] / tau_tr;
    result.plastic[2] += dl * trial[2] / tau_tr;
    result.plastic[1] += dl * tan_psi;
    result.tangent = slip_tangent(trial, scale);
    return result;
  }

  LocalTangent
  MohrCoulombInterface::slip_tangent(const LocalVector &trial,
                                     const double       scale) const
  {
    // d(dl)/dd = (ks m_s, kn tan(phi), ks m_theta) / H; the shear
    // t_a = tau m_a turns with m (radial part ks rho (I - m m^T)) and
    // shrinks by ks d(dl) along m; t_n = t_n,tr - kn tan(psi) dl.
    const double tau_tr    = std::hypot(trial[0], trial[2]);
    const double hardening = ks + kn * tan_phi * tan_psi;
    const double m[3]      = {trial[0] / tau_tr, 0., trial[2] / tau_tr};
    LocalTangent tangent   = {{0., 0., 0., 0., 0., 0., 0., 0., 0.}};
    for (const unsigned int a : {0u, 2u})
      {
        for (const unsigned int b : {0u, 2u})
          tangent[a * 3 + b] =
            ks * scale * ((a == b ? 1. : 0.) - m[a] * m[b]) +
            ks * kn * tan_phi * tan_psi / hardening * m[a] * m[b];
        tangent[a * 3 + 1] = -ks * kn * tan_phi / hardening * m[a];
        tangent[1 * 3 + a] = -ks * kn * tan_psi / hardening * m[a];
      }
    tangent[1 * 3 + 1] = ks * kn / hardening;
    return tangent;
  }

  std::string
  to_string(const ContactState state)
  {
    switch (state)
      {
        case ContactState::stick:
          return "stick";
        case ContactState::slip:
          return "slip";
        case ContactState::open:
          return "open";
      }
    return "";
  }
} // namespace FourierSSI
