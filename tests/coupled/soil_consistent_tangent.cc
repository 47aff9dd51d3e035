// The closed-form algorithmic tangent of the soil return mapping
// (SoilReturnMapping::return_map_with_tangent,
// doc/derivations/soil_consistent_tangent.md) against central differences of
// the return mapping itself, at random trial stresses with random principal
// directions in every region of the surface: the plane, the right edge (s1 = s2
// after the return), the left edge (s2 = s3) and, for Mohr-Coulomb, the apex;
// Tresca (s_u = 50 kPa) and non-associated Mohr-Coulomb (c' = 10 kPa, phi' =
// 30, psi = 10 degrees). Also: D_e where the trial is admissible, zero at the
// apex.
//
// Difference step: strain h = 1e-6 (stress changes of about 1e-3 kPa on
// stresses of 100 kPa). Central differences err by O(h^2) times the third
// derivative, which is the rotation of the principal axes, relative size
// (change / eigenvalue gap)^2 ~ (1e-3 / 20)^2 = 3e-9 with the gaps kept
// >= 20 kPa; round-off (1e-16 x 100 kPa / 1e-3 kPa from the Jacobi
// eigen-decomposition) is 1e-11. Tolerance: 1e-6 of the largest entry of
// D_e (lambda + 2 G), far above both and far below the spin terms that a
// wrong tangent lacks (order (sigma_i - sigma_j) / (s_i - s_j) G ~ 0.1 G).
// A sample is used only if the return at both differenced points ends in
// the same region.
#include "check.h"

#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <fourier_ssi/coupled/soil_law.h>
#include <random>

using namespace FourierSSI;

namespace
{
  const double G = 1000., K = 2000., lambda = K - 2. * G / 3.;
  const double strain_step = 1e-6;

  enum Region
  {
    plane,
    right_edge,
    left_edge,
    apex,
    n_regions
  };
  const char *region_name[n_regions] = {"plane",
                                        "right edge (s1 = s2)",
                                        "left edge (s2 = s3)",
                                        "apex"};

  SoilReturnMapping
  law_of(const std::string &text)
  {
    SoilPlasticityParameters p;
    p.parse_law_list("0: " + text);
    return SoilReturnMapping(p.laws.at(0));
  }

  /** Q diag(s) Q^T with Q a random rotation, as a stress vector. */
  StrainVector
  rotated(const std::array<double, 3> &s, std::mt19937 &rng)
  {
    std::normal_distribution<double> normal;
    Tensor<1, 3>                     e[3];
    for (unsigned int i = 0; i < 3; ++i)
      {
        for (unsigned int c = 0; c < 3; ++c)
          e[i][c] = normal(rng);
        for (unsigned int j = 0; j < i; ++j)
          e[i] -= (e[i] * e[j]) * e[j];
        e[i] /= e[i].norm();
      }
    SymmetricTensor<2, 3> t;
    for (unsigned int i = 0; i < 3; ++i)
      t += s[i] * symmetrize(outer_product(e[i], e[i]));
    return {{t[0][0], t[1][1], t[2][2], t[0][1], t[1][2], t[0][2]}};
  }

  /** The region of a return, from the returned principal stresses. */
  Region
  region_of(const SoilReturn &r)
  {
    if (r.state == SoilState::apex)
      return apex;
    if (r.state == SoilState::plane)
      return plane;
    SymmetricTensor<2, 3> t;
    t[0][0]      = r.stress[0];
    t[1][1]      = r.stress[1];
    t[2][2]      = r.stress[2];
    t[0][1]      = r.stress[3];
    t[1][2]      = r.stress[4];
    t[0][2]      = r.stress[5];
    const auto s = eigenvalues(t);
    return s[0] - s[1] < s[1] - s[2] ? right_edge : left_edge;
  }

  /** D_e (engineering shears) times a unit strain l. */
  StrainVector
  elastic_column(const unsigned int l)
  {
    StrainVector column{};
    for (unsigned int a = 0; a < 3; ++a)
      column[a] = l < 3 ? lambda + (a == l ? 2. * G : 0.) : 0.;
    if (l >= 3)
      column[l] = G;
    return column;
  }

  /**
   * Largest |D_ep - central difference| / (lambda + 2 G) at one trial, or
   * a negative number if a differenced return left the trial's region.
   */
  double
  tangent_error(const SoilReturnMapping &law, const StrainVector &trial)
  {
    StressTangent    d_ep;
    const SoilReturn at    = law.return_map_with_tangent(trial, G, K, 0., d_ep);
    double           error = 0.;
    for (unsigned int l = 0; l < 6; ++l)
      {
        const StrainVector change = elastic_column(l);
        StrainVector       plus = trial, minus = trial;
        for (unsigned int a = 0; a < 6; ++a)
          {
            plus[a] += strain_step * change[a];
            minus[a] -= strain_step * change[a];
          }
        const SoilReturn up   = law.return_map(plus, G, K, 0.),
                         down = law.return_map(minus, G, K, 0.);
        if (region_of(up) != region_of(at) || region_of(down) != region_of(at))
          return -1.;
        for (unsigned int a = 0; a < 6; ++a)
          {
            const double difference =
              (up.stress[a] - down.stress[a]) / (2. * strain_step);
            error = std::max(error, std::abs(d_ep[a * 6 + l] - difference));
          }
      }
    return error / (lambda + 2. * G);
  }

  /**
   * Random trials until `wanted` per region of the law are checked;
   * checks the largest error per region and that each region was reached.
   */
  void
  check_law(const std::string       &name,
            const SoilReturnMapping &law,
            const bool               has_apex)
  {
    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> uniform(-300., 300.);
    const unsigned int                     wanted = 8;
    std::array<unsigned int, n_regions>    found{};
    std::array<double, n_regions>          largest{};
    for (unsigned int attempt = 0; attempt < 200000; ++attempt)
      {
        std::array<double, 3> s = {{uniform(rng), uniform(rng), uniform(rng)}};
        std::sort(s.begin(), s.end(), std::greater<double>());
        // Distinct trial eigenvalues (gaps >= 20 kPa): the rotation of the
        // principal axes is then differentiable at the step used.
        if (s[0] - s[1] < 20. || s[1] - s[2] < 20.)
          continue;
        const StrainVector trial = rotated(s, rng);
        const SoilReturn   r     = law.return_map(trial, G, K, 0.);
        if (r.state == SoilState::elastic)
          continue;
        const Region region = region_of(r);
        if (found[region] == wanted)
          continue;
        const double error = tangent_error(law, trial);
        if (error < 0.)
          continue;
        ++found[region];
        largest[region] = std::max(largest[region], error);
      }
    for (unsigned int region = 0; region < n_regions; ++region)
      {
        if (region == apex && !has_apex)
          continue;
        const std::string what = name + " " + region_name[region];
        check::equal(what + ": trials checked", found[region], wanted);
        check::small(what + ": largest |D_ep - central difference| / "
                            "(lambda + 2G)",
                     largest[region],
                     1e-6);
      }
  }
} // namespace

int
main()
{
  const SoilReturnMapping tresca = law_of("tresca, su=50");
  const SoilReturnMapping mc     = law_of("mohr-coulomb, c=10, phi=30, psi=10");
  std::cout << "Tresca s_u = 50 kPa" << std::endl;
  check_law("Tresca", tresca, false);
  std::cout << "Mohr-Coulomb c' = 10 kPa, phi' = 30, psi = 10" << std::endl;
  check_law("Mohr-Coulomb", mc, true);

  std::cout << "Admissible trial: D_ep = D_e; apex: D_ep = 0" << std::endl;
  StressTangent d_ep;
  tresca.return_map_with_tangent(
    {{30., -60., 10., 5., 0., 0.}}, G, K, 0., d_ep);
  double error = 0.;
  for (unsigned int l = 0; l < 6; ++l)
    for (unsigned int a = 0; a < 6; ++a)
      error = std::max(error, std::abs(d_ep[a * 6 + l] - elastic_column(l)[a]));
  check::small("elastic: largest |D_ep - D_e| [kPa]", error, 0.);
  mc.return_map_with_tangent({{120., 100., 80., 5., 3., 1.}}, G, K, 0., d_ep);
  error = 0.;
  for (const double d : d_ep)
    error = std::max(error, std::abs(d));
  check::small("apex: largest |D_ep| [kPa]", error, 0.);
  return check::summary();
}
