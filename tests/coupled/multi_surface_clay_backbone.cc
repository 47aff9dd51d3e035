// The multi-surface clay (coupled/multi_surface_clay.h) on its monotonic
// backbone, against the closed form tau_b = G0 gamma / (1 + gamma /
// gamma_ref) capped at s_u (doc/derivations/multi_surface_clay.md, B1),
// driven step by step through the return map up to 2 gamma_f = 20 gamma_ref:
//  - simple shear (tau_rz against gamma_rz) and undrained triaxial
//    compression (q = sigma_r - sigma_z against eps_a, closed form
//    q = sqrt(3) tau_b(sqrt(3) eps_a) for von Mises elements matched in
//    simple shear, derivation section 5);
//  - at the nodes of the fit the polygon touches the backbone: error at
//    round-off (tolerance 1e-10 relative; the nodes' stresses are sums of
//    N products);
//  - between nodes the error is about dpsi^2 / 4 (derivation section 3),
//    falling as (N - 1)^-2: measured for N = 5, 10, 20, 40, checked against
//    that estimate within 10 % (the estimate drops O(dpsi^4) terms), and
//    below 0.5 % for N >= 20;
//  - small strains: the tangent is the elastic G0, K (1e-12 relative);
//    large strains: the capacity s_u (simple shear) and sqrt(3) s_u
//    (triaxial) to round-off, with zero shear tangent;
//  - N = 1 is one von Mises element: min(G0 gamma, s_u) exactly;
//  - s_u = su + k depth; G0 gamma_ref <= s_u refused with one line (the
//    hyperbola never reaches s_u).
//  - a measured degradation table (derivation section 7): the model is the
//    polygon through tau_k = G0 gamma_k (G/G0)_k, continued with the last
//    slope to s_u: tau at every table point equals G0 gamma_k (G/G0)_k
//    computed here (1e-10 relative: sums of a few products), every
//    sampled strain equals the polygon (1e-10), in simple shear and in
//    triaxial (sqrt(3) times), the elements' moduli sum to G0 and their
//    strengths to s_u (1e-12), one element per kink below the cap (6 for
//    the table below with s_u = 10 kPa, 4 with s_u = 4 kPa where the cap
//    cuts its fourth segment), and a table whose tau ends flat below s_u
//    is refused in one line.
#include "check.h"
#include "multi_surface_clay_test_support.h"

#include <algorithm>
#include <fourier_ssi/input/messages.h>

using namespace clay_test;

namespace
{
  /**
   * Strains to sample for an N-surface fit: each node, each yield strain
   * (the kinks, where the error peaks) and 40 points inside every gap, up
   * to 2 gamma_f; sorted, so that the path loads monotonically.
   */
  std::vector<double>
  sample_strains(const MultiSurfaceBackbone &elements)
  {
    std::vector<double> g = elements.node_strains();
    for (unsigned int i = 0; i < elements.n_surfaces(); ++i)
      g.push_back(elements.yield_strain(i));
    g.push_back(2. * elements.failure_strain());
    std::sort(g.begin(), g.end());
    std::vector<double> all;
    for (unsigned int k = 0; k + 1 < g.size(); ++k)
      for (const double s : strains_between(g[k], g[k + 1], 40))
        all.push_back(s);
    return all;
  }

  /** The largest relative error of a monotonic curve against tau_b. */
  struct CurveErrors
  {
    double at_nodes = 0., between_nodes = 0., capacity = 0.;
  };

  /**
   * Simple shear (triaxial = false) or triaxial compression at the same
   * element strains gamma = sqrt(3) eps_a.
   */
  CurveErrors
  monotonic_errors(const MultiSurfaceClay &law, const bool triaxial)
  {
    const MultiSurfaceBackbone &elements = law.elements();
    const std::vector<double>   gammas   = sample_strains(elements);
    std::vector<StrainVector>   path;
    for (const double g : gammas)
      path.push_back(triaxial ? triaxial_compression(g / std::sqrt(3.)) :
                                simple_shear(g));
    const std::vector<MultiSurfaceReturn> returns = drive(law, path);
    const std::vector<double>            &nodes   = elements.node_strains();
    const double                          scale = triaxial ? std::sqrt(3.) : 1.;
    CurveErrors                           errors;
    for (unsigned int k = 0; k < gammas.size(); ++k)
      {
        const StrainVector &s     = returns[k].stress;
        const double        value = triaxial ? s[0] - s[1] : s[3];
        const double        exact = scale * elements.backbone_stress(gammas[k]);
        const double        error = std::abs(value / exact - 1.);
        const bool          is_node =
          std::find(nodes.begin(), nodes.end(), gammas[k]) != nodes.end();
        double &slot = is_node ? errors.at_nodes : errors.between_nodes;
        slot         = std::max(slot, error);
      }
    const StrainVector &last = returns.back().stress;
    errors.capacity =
      std::abs((triaxial ? last[0] - last[1] : last[3]) / (scale * su) - 1.);
    return errors;
  }

  void
  check_fit(const unsigned int n)
  {
    const MultiSurfaceClay law    = clay(n);
    const double           u_fail = law.elements().failure_strain() / gamma_ref;
    const double           estimate = estimated_fit_error(n, u_fail);
    for (const bool triaxial : {false, true})
      {
        const CurveErrors e = monotonic_errors(law, triaxial);
        const std::string what =
          "N = " + std::to_string(n) +
          (triaxial ? ", triaxial q(eps_a)" : ", simple shear tau(gamma)");
        std::cout << what << ": largest error between nodes " << e.between_nodes
                  << " (estimate dpsi^2/4 = " << estimate << ")" << std::endl;
        check::small(what + ": error at the nodes", e.at_nodes, 1e-10);
        check::relative(what + ": error between nodes against dpsi^2 / 4",
                        e.between_nodes,
                        estimate,
                        0.10);
        if (n >= 20)
          check::small(what + ": error between nodes", e.between_nodes, 5e-3);
        check::small(what + ": capacity at 2 gamma_f", e.capacity, 1e-12);
      }
  }

  /** d sigma / d eps at (strain, virgin state). */
  StressTangent
  tangent_at(const MultiSurfaceClay &law, const StrainVector &strain)
  {
    StressTangent d;
    law.return_map_with_tangent(strain, law.initial_state(), d);
    return d;
  }

  void
  check_limits()
  {
    const MultiSurfaceClay law         = clay(20);
    const double           gamma_small = 0.5 * law.elements().yield_strain(0);
    const StressTangent    d      = tangent_at(law, simple_shear(gamma_small));
    const double           lambda = bulk - 2. * g0 / 3.;
    check::relative("small strain: d tau_rz / d gamma_rz = G0",
                    d[3 * 6 + 3],
                    g0,
                    1e-12);
    check::relative("small strain: d sigma_r / d eps_r = lambda + 2 G0",
                    d[0],
                    lambda + 2. * g0,
                    1e-12);
    check::relative("small strain: d sigma_r / d eps_z = lambda",
                    d[1],
                    lambda,
                    1e-12);
    check::relative(
      "small strain: tau = G0 gamma",
      law.return_map(simple_shear(gamma_small), law.initial_state()).stress[3],
      g0 * gamma_small,
      1e-12);
    const double        gamma_large = 20. * law.elements().failure_strain();
    const StressTangent dl = tangent_at(law, simple_shear(gamma_large));
    check::small("large strain: d tau_rz / d gamma_rz / G0",
                 dl[3 * 6 + 3] / g0,
                 1e-12);
    check::relative("large strain: sum of the strengths = s_u",
                    law.elements().model_stress(gamma_large),
                    su,
                    1e-13);
  }

  void
  check_one_element()
  {
    const MultiSurfaceClay law = clay(1);
    for (const double g : {0.5 * su / g0, 2. * su / g0})
      check::relative(
        "N = 1: tau(" + std::to_string(g) + ") = min(G0 gamma, s_u)",
        law.return_map(simple_shear(g), law.initial_state()).stress[3],
        std::min(g0 * g, su),
        1e-14);
  }

  void
  check_depth_profile()
  {
    // s_u = 10 + 0.2 depth at depth 4 m: 10.8 kPa (< G0 gamma_ref = 11).
    const SoilLaw          law = iwan_law(20, ", k=0.2");
    const MultiSurfaceClay at_depth(law, g0, bulk, 4.);
    const double           gamma = 10. * at_depth.elements().failure_strain();
    check::relative("s_u = su + k depth: capacity at 4 m",
                    at_depth
                      .return_map(simple_shear(gamma), at_depth.initial_state())
                      .stress[3],
                    10.8,
                    1e-13);
    SoilPlasticityParameters p;
    p.parse_law_list("0: iwan, su=10, gref=0.001");
    check::equal("surfaces default to 20", p.laws.at(0).n_surfaces, 20);
  }

  void
  check_unreachable_strength()
  {
    std::string message;
    try
      {
        // G0 gamma_ref = 11 kPa < s_u = 12 kPa.
        MultiSurfaceBackbone(g0, 12., gamma_ref, 20);
      }
    catch (const std::exception &e)
      {
        message = one_line_message(e);
      }
    std::cout << "  message: " << message << std::endl;
    check::that("G0 gref <= s_u refused with one line naming the entry",
                message.find("Soil plasticity/Laws: iwan: G0 gref = 11 kPa "
                             "does not exceed s_u = 12 kPa") == 0 &&
                  message.find('\n') == std::string::npos);
  }
  /** A degradation curve of a soft clay (strain : G/G0), concave tau. */
  const std::string table =
    "1e-5:1 1e-4:0.9 3e-4:0.75 1e-3:0.5 3e-3:0.25 1e-2:0.085";

  MultiSurfaceClay
  table_clay(const std::string &strength)
  {
    SoilPlasticityParameters p;
    p.parse_law_list("0: iwan, su=" + strength + ", table=" + table);
    return MultiSurfaceClay(p.laws.at(0), g0, bulk, 0.);
  }

  void
  check_table()
  {
    const MultiSurfaceClay      law      = table_clay("10");
    const MultiSurfaceBackbone &elements = law.elements();
    // Kinks at the first five points and at the cap; the last point is
    // none (its slope goes on past it).
    check::equal("table: one element per kink below s_u",
                 elements.n_surfaces(),
                 6);
    // The points themselves, from the table's numbers.
    const std::vector<std::pair<double, double>> points = {{1e-5, 1.},
                                                           {1e-4, 0.9},
                                                           {3e-4, 0.75},
                                                           {1e-3, 0.5},
                                                           {3e-3, 0.25},
                                                           {1e-2, 0.085}};
    std::vector<StrainVector>                    path;
    for (const auto &[gamma, ratio] : points)
      path.push_back(simple_shear(gamma));
    const std::vector<MultiSurfaceReturn> returns = drive(law, path);
    double                                worst   = 0.;
    for (unsigned int k = 0; k < points.size(); ++k)
      worst = std::max(worst,
                       std::abs(returns[k].stress[3] /
                                  (g0 * points[k].first * points[k].second) -
                                1.));
    check::small("table: tau at its points = G0 gamma G/G0", worst, 1e-10);
    for (const bool triaxial : {false, true})
      {
        const CurveErrors e = monotonic_errors(law, triaxial);
        const std::string what =
          triaxial ? "table, triaxial q(eps_a)" : "table, simple shear";
        check::small(what + ": error at the nodes", e.at_nodes, 1e-10);
        check::small(what + ": error between the nodes",
                     e.between_nodes,
                     1e-10);
        check::small(what + ": capacity at 2 gamma_f", e.capacity, 1e-12);
      }
    double moduli = 0., strengths = 0.;
    for (unsigned int i = 0; i < elements.n_surfaces(); ++i)
      {
        moduli += elements.shear_modulus(i);
        strengths += elements.strength(i);
      }
    check::relative("table: the moduli sum to G0", moduli, g0, 1e-12);
    check::relative("table: the strengths sum to s_u", strengths, su, 1e-12);
    // Past the last point the last slope goes on: s_u at gamma_f.
    const double slope = g0 * (1e-2 * 0.085 - 3e-3 * 0.25) / (1e-2 - 3e-3);
    check::relative("table: gamma_f on the last slope",
                    elements.failure_strain(),
                    1e-2 + (su - g0 * 1e-2 * 0.085) / slope,
                    1e-12);

    // s_u = 4 kPa cuts the fourth segment (tau = 2.475 .. 5.5 kPa).
    const MultiSurfaceClay capped = table_clay("4");
    check::equal("table capped at s_u = 4 kPa: 4 elements",
                 capped.elements().n_surfaces(),
                 4);
    check::relative("table capped: tau at 2 gamma_f is s_u",
                    capped
                      .return_map(simple_shear(
                                    2. * capped.elements().failure_strain()),
                                  capped.initial_state())
                      .stress[3],
                    4.,
                    1e-12);

    std::string message;
    try
      {
        // tau = 1.1 kPa at both points: flat, below s_u = 10 kPa.
        SoilPlasticityParameters p;
        p.parse_law_list("0: iwan, su=10, table=1e-4:1 1e-3:0.1");
        MultiSurfaceClay(p.laws.at(0), g0, bulk, 0.);
      }
    catch (const std::exception &e)
      {
        message = one_line_message(e);
      }
    std::cout << "  message: " << message << std::endl;
    check::that("a table ending flat below s_u refused with one line",
                message.find("Soil plasticity/Laws: iwan: the table's last "
                             "point gives tau = 1.1 kPa on a flat last "
                             "segment") == 0 &&
                  message.find('\n') == std::string::npos);
  }
} // namespace

int
main()
{
  for (const unsigned int n : {5u, 10u, 20u, 40u})
    check_fit(n);
  check_limits();
  check_one_element();
  check_depth_profile();
  check_unreachable_strength();
  check_table();
  return check::summary();
}
