#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <fourier_ssi/coupled/multi_surface_backbone.h>
#include <sstream>

namespace FourierSSI
{
  MultiSurfaceBackbone::MultiSurfaceBackbone(const double shear_modulus,
                                             const double undrained_strength,
                                             const double reference_strain,
                                             const unsigned int n_surfaces)
    : g0(shear_modulus)
    , su(undrained_strength)
    , gamma_ref(reference_strain)
  {
    Assert(g0 > 0. && su > 0. && gamma_ref > 0. && n_surfaces >= 1,
           dealii::ExcInternalError());
    if (n_surfaces == 1)
      {
        // One von Mises element: elastic G0 up to s_u (no backbone to fit).
        moduli    = {g0};
        strengths = {su};
        nodes     = {0.};
        return;
      }
    std::ostringstream text;
    text << "Soil plasticity/Laws: iwan: G0 gref = " << g0 * gamma_ref
         << " kPa does not exceed s_u = " << su
         << " kPa: the hyperbola never reaches s_u (give gref > s_u / G0 = "
         << su / g0 << ")";
    AssertThrow(g0 * gamma_ref > su, dealii::ExcMessage(text.str()));
    fit_tangents(n_surfaces);
  }

  MultiSurfaceBackbone::MultiSurfaceBackbone(
    const double                                  shear_modulus,
    const double                                  undrained_strength,
    const std::vector<std::pair<double, double>> &degradation)
    : g0(shear_modulus)
    , su(undrained_strength)
  {
    Assert(g0 > 0. && su > 0. && degradation.size() >= 2,
           dealii::ExcInternalError());
    // The polygon through tau_k = G0 gamma_k (G/G0)_k from the origin,
    // walked until it reaches s_u; past the last point the last slope goes
    // on (derivation section 7).
    polygon      = {{0., 0.}};
    double slope = g0;
    for (const auto &[gamma, ratio] : degradation)
      {
        const double tau                  = g0 * gamma * ratio;
        const auto [gamma_last, tau_last] = polygon.back();
        slope = (tau - tau_last) / (gamma - gamma_last);
        if (tau >= su)
          break;
        polygon.emplace_back(gamma, tau);
      }
    const auto [gamma_last, tau_last] = polygon.back();
    std::ostringstream text;
    text << "Soil plasticity/Laws: iwan: the table's last point gives tau = "
         << tau_last
         << " kPa on a flat last segment: it never reaches s_u = " << su
         << " kPa (end the table above s_u / G0 = " << su / g0
         << " with a rising tau = G0 gamma G/G0)";
    AssertThrow(slope > 0., dealii::ExcMessage(text.str()));
    polygon.emplace_back(gamma_last + (su - tau_last) / slope, su);
    fit_polygon(polygon);
  }

  void
  MultiSurfaceBackbone::fit_polygon(
    const std::vector<std::pair<double, double>> &vertices)
  {
    // Segment j has slope sum_{i >= j} G_i (eq. 2.4): G_i is the drop of
    // slope at kink i, and it yields there. Equal slopes (collinear
    // points) make no element.
    const unsigned int  n = vertices.size() - 1;
    std::vector<double> slope(n + 1, 0.);
    for (unsigned int j = 0; j < n; ++j)
      slope[j] = (vertices[j + 1].second - vertices[j].second) /
                 (vertices[j + 1].first - vertices[j].first);
    moduli.clear();
    strengths.clear();
    nodes.clear();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double modulus = slope[i] - slope[i + 1];
        nodes.push_back(vertices[i].first);
        if (modulus <= 0.)
          continue;
        moduli.push_back(modulus);
        strengths.push_back(modulus * vertices[i + 1].first);
      }
  }

  void
  MultiSurfaceBackbone::fit_tangents(const unsigned int n_surfaces)
  {
    const unsigned int N      = n_surfaces;
    const double       u_fail = failure_strain() / gamma_ref;
    // (B3): equal steps in psi(u) = 2 atan(sqrt(u)), the last node at u_f.
    const double        step = 2. * std::atan(std::sqrt(u_fail)) / (N - 1);
    std::vector<double> t(N);
    for (unsigned int j = 0; j < N; ++j)
      t[j] = std::pow(std::tan(0.5 * j * step), 2);
    t[N - 1] = u_fail;

    // The tangent of (B1) at t_j has slope G0 / (1 + t_j)^2 (derivation
    // eq. 2.2); two neighbouring tangents cross where 1 + u is the harmonic
    // mean of 1 + t_j and 1 + t_{j+1} (eq. 2.3); the last tangent meets
    // the cap at u_f itself.
    std::vector<double> slope(N + 1, 0.), kink(N);
    for (unsigned int j = 0; j < N; ++j)
      slope[j] = 1. / ((1. + t[j]) * (1. + t[j]));
    for (unsigned int j = 0; j + 1 < N; ++j)
      kink[j] =
        2. * (1. + t[j]) * (1. + t[j + 1]) / (2. + t[j] + t[j + 1]) - 1.;
    kink[N - 1] = u_fail;

    // Segment j of the polygon has slope sum_{i >= j} G_i (eq. 2.4).
    moduli.resize(N);
    strengths.resize(N);
    nodes.resize(N);
    for (unsigned int i = 0; i < N; ++i)
      {
        moduli[i]    = g0 * (slope[i] - slope[i + 1]);
        strengths[i] = moduli[i] * gamma_ref * kink[i];
        nodes[i]     = gamma_ref * t[i];
      }
  }

  double
  MultiSurfaceBackbone::backbone_stress(const double gamma) const
  {
    if (polygon.empty())
      return std::min(g0 * gamma / (1. + gamma / gamma_ref), su);
    for (unsigned int j = 0; j + 1 < polygon.size(); ++j)
      if (gamma <= polygon[j + 1].first)
        {
          const auto [g1, t1] = polygon[j];
          const auto [g2, t2] = polygon[j + 1];
          return t1 + (t2 - t1) * (gamma - g1) / (g2 - g1);
        }
    return su;
  }

  double
  MultiSurfaceBackbone::model_stress(const double gamma) const
  {
    double tau = 0.;
    for (unsigned int i = 0; i < moduli.size(); ++i)
      tau += std::min(moduli[i] * gamma, strengths[i]);
    return tau;
  }

  double
  MultiSurfaceBackbone::failure_strain() const
  {
    return polygon.empty() ? gamma_ref * su / (g0 * gamma_ref - su) :
                             polygon.back().first;
  }
} // namespace FourierSSI
