// The closed-form return mapping of the perfectly plastic soil laws
// (include/fourier_ssi/coupled/soil_law.h, doc/soil-plasticity.md section 2)
// against hand-computed returns, the yield condition after every return, the
// closest-point property of associated flow, and the rejected inputs.
//
// Hand cases, G = 1000 kPa, K = 2000 kPa (stresses in kPa, tension +):
//  Tresca s_u = 50: trial diag(100, -100, 0) -> f = 100, plane return
//    dgamma = f / 4G: (50, -50, 0).
//  Tresca right edge: trial diag(100, 90, -100): the plane return gives
//    s2 > s1, the edge s1 = s2 = p + 2 s_u/3 = 63.3333, s3 = p - 4 s_u/3 =
//    -36.6667 with p = 30 [soil_return_mapping.py section 2].
//  Tresca with k: s_u = 10 + 4 depth at depth 10 m = 50: the first case.
//  Mohr-Coulomb c = 10, phi = 30, psi = 0: trial diag(0, -50, -200):
//    f = 82.67949, dgamma = f / 4G, s1 = -41.33975, s3 = -158.66025.
//  Mohr-Coulomb apex: trial diag(120, 100, 80) -> c cot phi = 17.32051 I.
// Tolerances: 1e-12 relative on the closed forms (a few roundings of numbers
// of order 100); hand values given to 7 digits are compared at 1e-8;
// f <= 1e-10 * (|trial| + 1 kPa) after a return (eigenvalues of a 3 x 3
// tensor to round-off).
#include "check.h"

#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <fourier_ssi/coupled/soil_law.h>
#include <fourier_ssi/input/messages.h>
#include <random>

using namespace FourierSSI;

namespace
{
  const double G = 1000., K = 2000.;

  SoilReturnMapping
  law_of(const std::string &text)
  {
    SoilPlasticityParameters p;
    p.parse_law_list("0: " + text);
    return SoilReturnMapping(p.laws.at(0));
  }

  void
  check_stress(const std::string  &what,
               const SoilReturn   &r,
               const StrainVector &expected,
               const double        tolerance)
  {
    const char *name[6] = {"s_r", "s_z", "s_t", "s_rz", "s_zt", "s_rt"};
    for (unsigned int c = 0; c < 6; ++c)
      check::relative(
        what + " " + name[c], r.stress[c], expected[c], tolerance, 1.);
  }

  std::string
  error_of(const std::string &text)
  {
    try
      {
        SoilPlasticityParameters p;
        p.parse_law_list(text);
      }
    catch (const std::exception &e)
      {
        return one_line_message(e);
      }
    return "";
  }

  /** (s - t)^T D^-1 (s - t): the complementary energy of a stress change. */
  double
  energy_distance(const StrainVector &s, const StrainVector &t)
  {
    StrainVector d;
    for (unsigned int c = 0; c < 6; ++c)
      d[c] = s[c] - t[c];
    const double p = (d[0] + d[1] + d[2]) / 3.;
    // d = p I + s: d : D^-1 d = p^2 / K + s : s / (2 G).
    double e = p * p / K;
    for (unsigned int c = 0; c < 3; ++c)
      e += (d[c] - p) * (d[c] - p) / (2. * G);
    for (unsigned int c = 3; c < 6; ++c)
      e += 2. * d[c] * d[c] / (2. * G);
    return e;
  }
} // namespace

int
main()
{
  std::cout << "Hand cases" << std::endl;
  const SoilReturnMapping tresca = law_of("tresca, su=50");
  check_stress("Tresca plane",
               tresca.return_map({{100., -100., 0., 0., 0., 0.}}, G, K, 0.),
               {{50., -50., 0., 0., 0., 0.}},
               1e-12);
  const SoilReturn edge =
    tresca.return_map({{100., 90., -100., 0., 0., 0.}}, G, K, 0.);
  check_stress(
    "Tresca right edge",
    edge,
    {{30. + 100. / 3., 30. + 100. / 3., 30. - 200. / 3., 0., 0., 0.}},
    1e-12);
  check::equal("Tresca right edge state",
               int(edge.state),
               int(SoilState::edge));
  const SoilReturn left =
    tresca.return_map({{100., -90., -100., 0., 0., 0.}}, G, K, 0.);
  check_stress(
    "Tresca left edge",
    left,
    {{-30. + 200. / 3., -30. - 100. / 3., -30. - 100. / 3., 0., 0., 0.}},
    1e-12);
  const SoilReturnMapping graded = law_of("tresca, su=10, k=4");
  check_stress("Tresca s_u = 10 + 4 depth at 10 m",
               graded.return_map({{100., -100., 0., 0., 0., 0.}}, G, K, 10.),
               {{50., -50., 0., 0., 0., 0.}},
               1e-12);
  check_stress("Tresca elastic (f < 0) unchanged",
               tresca.return_map({{30., -60., 10., 5., 0., 0.}}, G, K, 0.),
               {{30., -60., 10., 5., 0., 0.}},
               0.);
  // Pure shear in the rz plane, rotated principal axes: tau = 80 > s_u, the
  // return scales the shear to s_u and keeps the normal stresses.
  check_stress("Tresca pure shear s_rz = 80",
               tresca.return_map({{-20., -20., -20., 80., 0., 0.}}, G, K, 0.),
               {{-20., -20., -20., 50., 0., 0.}},
               1e-12);
  const SoilReturnMapping mc = law_of("mohr-coulomb, c=10, phi=30");
  check_stress("Mohr-Coulomb plane",
               mc.return_map({{0., -50., -200., 0., 0., 0.}}, G, K, 0.),
               {{-41.33974596, -50., -158.66025404, 0., 0., 0.}},
               1e-8);
  const SoilReturn apex =
    mc.return_map({{120., 100., 80., 0., 0., 0.}}, G, K, 0.);
  check_stress("Mohr-Coulomb apex",
               apex,
               {{17.32050808, 17.32050808, 17.32050808, 0., 0., 0.}},
               1e-8);
  check::equal("Mohr-Coulomb apex state",
               int(apex.state),
               int(SoilState::apex));

  std::cout << "Random trials: on the surface, closest point" << std::endl;
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> u(-300., 300.);
  const SoilReturnMapping                laws[3] = {
                   tresca,
                   law_of("mohr-coulomb, c=10, phi=30, psi=30"),
                   law_of("mohr-coulomb, c=5, phi=25, psi=10")};
  for (unsigned int l = 0; l < 3; ++l)
    {
      double       worst_f = 0., worst_pressure = 0.;
      unsigned int closer = 0, n_plastic = 0;
      for (unsigned int trial_index = 0; trial_index < 5000; ++trial_index)
        {
          StrainVector trial;
          for (double &c : trial)
            c = u(rng);
          const SoilReturn r     = laws[l].return_map(trial, G, K, 0.);
          double           scale = 1.;
          for (double c : trial)
            scale += std::abs(c);
          const double f = laws[l].yield_function(r.stress, 0.);
          if (r.state != SoilState::elastic)
            {
              ++n_plastic;
              worst_f = std::max(worst_f, std::abs(f) / scale);
            }
          else
            worst_f = std::max(worst_f, std::max(f, 0.) / scale);
          if (l == 0)
            worst_pressure =
              std::max(worst_pressure,
                       std::abs((r.stress[0] + r.stress[1] + r.stress[2]) -
                                (trial[0] + trial[1] + trial[2])) /
                         scale);
          // Associated flow (Tresca, MC with psi = phi): the return is the
          // closest admissible stress in the energy norm; no admissible
          // stress near it (random perturbations, scaled back onto the
          // admissible set if needed) may be closer.
          if (l < 2 && r.state != SoilState::elastic)
            for (unsigned int m = 0; m < 5; ++m)
              {
                StrainVector other = r.stress;
                for (double &c : other)
                  c += 0.05 * u(rng);
                if (laws[l].yield_function(other, 0.) > 0.)
                  continue;
                if (energy_distance(trial, other) <
                    energy_distance(trial, r.stress) * (1. - 1e-12))
                  ++closer;
              }
        }
      const std::string name[3] = {"Tresca",
                                   "MC phi 30 psi 30 (associated)",
                                   "MC phi 25 psi 10"};
      std::cout << "  " << name[l] << ": " << n_plastic << " of 5000 plastic"
                << std::endl;
      check::small(name[l] + " |f| after return / |trial|", worst_f, 1e-10);
      if (l == 0)
        check::small("Tresca keeps the mean stress", worst_pressure, 1e-12);
      if (l < 2)
        check::equal(name[l] + " admissible stresses closer than the return",
                     closer,
                     0);
    }

  // The return skips the eigenvalues where a bound on the deviator shows a
  // trial elastic (s1 - s3 <= sqrt(2) |dev|, equal for a deviator (a, 0,
  // -a)): trials 1e-9 inside and outside the surface, in random principal
  // frames, with the middle value at zero (the bound tight) or at random,
  // must be returned exactly when the yield function is positive.
  std::cout << "Trials 1e-9 inside and outside the surface" << std::endl;
  std::normal_distribution<double> normal(0., 1.);
  for (unsigned int l = 0; l < 3; ++l)
    {
      unsigned int misjudged = 0, n_trials = 0;
      for (unsigned int trial_index = 0; trial_index < 2000; ++trial_index)
        {
          // A random rotation: a normalised quaternion (w, x, y, z).
          double q[4], norm = 0.;
          for (double &c : q)
            {
              c = normal(rng);
              norm += c * c;
            }
          for (double &c : q)
            c /= std::sqrt(norm);
          const double w = q[0], x = q[1], y = q[2], z = q[3];
          const double R[3][3] = {
            {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y),
             2 * (y * z + w * x),
             1 - 2 * (x * x + y * y)}};
          // Principal deviator d1 >= d2 >= d3 (sum 0) and a mean stress.
          const double a      = 1. + std::abs(u(rng)) / 100.;
          const double middle = trial_index % 2 == 0 ? 0. : a * u(rng) / 600.;
          const double d[3]   = {a, middle, -a - middle};
          const double mean   = u(rng) / 10.;
          const double sin_phi =
            l == 0 ? 0. : std::sin((l == 1 ? 30. : 25.) * M_PI / 180.);
          const double strength =
            l == 0 ? 100. :
                     2. * (l == 1 ? 10. : 5.) *
                       std::cos((l == 1 ? 30. : 25.) * M_PI / 180.);
          // The deviator's scale that puts f at relative +-1e-9.
          const double slope = (d[0] - d[2]) + (d[0] + d[2]) * sin_phi;
          const double room  = strength - 2. * mean * sin_phi;
          if (slope <= 0. || room <= 0.)
            continue;
          for (const double side : {-1e-9, 1e-9})
            {
              const double lambda  = room * (1. + side) / slope;
              double       t[3][3] = {};
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int j = 0; j < 3; ++j)
                  for (unsigned int k = 0; k < 3; ++k)
                    t[i][j] += R[i][k] * lambda * d[k] * R[j][k];
              const StrainVector trial = {{t[0][0] + mean,
                                           t[1][1] + mean,
                                           t[2][2] + mean,
                                           t[0][1],
                                           t[1][2],
                                           t[0][2]}};
              const bool       yields  = laws[l].yield_function(trial, 0.) > 0.;
              const SoilReturn r       = laws[l].return_map(trial, G, K, 0.);
              misjudged += yields != (r.state != SoilState::elastic);
              ++n_trials;
            }
        }
      check::equal("law " + std::to_string(l) + ": of " +
                     std::to_string(n_trials) +
                     " trials near the surface, returned against the yield "
                     "function's sign",
                   misjudged,
                   0);
    }

  std::cout << "Rejected input" << std::endl;
  const std::pair<std::string, std::string> bad[] = {
    {"0: tresca, su=0", "su = 0 kPa must be > 0"},
    {"0: tresca, su=-5", "must be > 0"},
    {"0: tresca", "su is missing"},
    {"0: tresca, su=10, k=-1", "k must be >= 0"},
    {"0: mohr-coulomb, c=5, phi=90", "must satisfy 0 < phi < 90"},
    {"0: mohr-coulomb, c=5, phi=0", "use tresca"},
    {"0: mohr-coulomb, c=-1, phi=30", "c must be >= 0"},
    {"0: mohr-coulomb, c=1, phi=30, psi=40", "psi must satisfy"},
    {"0: cam-clay, c=1", "unknown law"},
    {"0: tresca, su=10; 0: tresca, su=20", "defined twice"}};
  for (const auto &[text, expected] : bad)
    {
      const std::string message = error_of(text);
      const bool        ok =
        message.find(expected) != std::string::npos &&
        message.find("Soil plasticity/Laws") != std::string::npos &&
        message.find('\n') == std::string::npos;
      check::equal("'" + text + "' -> '" + message + "'", ok, 1);
    }
  return check::summary();
}
