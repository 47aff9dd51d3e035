// Table 4.1 of Hernoune (2007), section 4.2 (doc/table-4-1.md): a
// rigid circular surface footing (a = 1) under a moment M, rotation reported
// as theta E_s a^3 / M for nu = 0 ... 0.49 and five contact models:
//   bonded ("sans interface"): soil surface nodes r < a follow the rigid
//     motion in u, v, w (Tie = boundary, Id = 4);
//   k = 1e6, 1e8, 1e10: a rigid block (material 1, 0 < z < 0.2) resting on
//     a zero-thickness interface at z = 0 with kn = ks = k [kPa/m];
//   smooth: only the normal component tied; exact 3 (1 - nu^2) / 4 (Poulos &
//     Davis 1974, thesis eq. 4.1).
// Soil G = 1000 kPa (thesis 4.2), E_s = 2 G (1 + nu), M = 1 kN.m.
// The footing edge is a stress singularity, so the rotation converges as
// O(h): every value checked against a reference is Richardson-extrapolated
// from three uniformly refined graded meshes with the observed order.
// Mesh sizes and tolerances come from the committed convergence study
// benchmarks/table-4-1/ (doc/table-4-1.md): a finer base mesh and a fourth
// level move the extrapolated values by < 0.1%, and the domain truncation is
// negligible for rocking (L = 40 a, 100 a, 400 a agree within 0.01%).
#include "check.h"
#include "test_support.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fourier_ssi/input/harmonic.h>
#include <sstream>
#include <stdexcept>

using namespace FourierSSI;

namespace
{
  const double nus[6] = {0.0, 0.1, 0.2, 0.3, 0.4, 0.49};
  // Thesis Table 4.1, theta_M E_s a^3 / M.
  const double thesis_bonded[6] =
    {0.66060, 0.67329, 0.67255, 0.65629, 0.62132, 0.56882};
  const double thesis_k1e10[6] =
    {0.66062, 0.67331, 0.67255, 0.65629, 0.62132, 0.56882};
  // Our converged bonded values (benchmarks/table-4-1/table-4-1.md: 4
  // levels of the finer base mesh, Richardson; the smooth row of the same
  // study matches 3(1-nu^2)/4 within 0.02%). The thesis values are 0.1-0.3%
  // lower (stiffer), as expected of its single coarse mesh.
  const double study_bonded[6] =
    {0.66244, 0.67512, 0.67426, 0.65773, 0.62231, 0.56975};

  enum class Model
  {
    bonded,
    interface,
    smooth
  };

  /** A number as the .prm text of the growth ratios (12 digits). */
  std::string
  text(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(12) << x;
    return s.str();
  }

  /**
   * The growth ratios (R growth on the footing and beyond it, Z growth) of
   * the study's graded mesh with edge cells h_e, as .prm text: read from
   * benchmarks/table-4-1/run.py's mesh_entries() (tools/mesh_grading.py),
   * the one definition of that grading, so that this test and the study
   * grade their meshes alike.
   */
  std::array<std::string, 3>
  study_grading(const double       L,
                const double       h_e,
                const unsigned int n_foot,
                const unsigned int n_out,
                const unsigned int n_depth)
  {
    std::ostringstream command;
    command << "/usr/bin/python3 -c 'import sys; sys.path.insert(0, \""
            << test_support::source_dir()
            << "/benchmarks/table-4-1\"); from run import mesh_entries; "
               "print(*(\"%.12g\" % g for g in mesh_entries("
            << L << ", " << h_e << ", " << n_foot << ", " << n_out << ", "
            << n_depth << ")))'";
    FILE *pipe = popen(command.str().c_str(), "r");
    if (!pipe)
      throw std::runtime_error("cannot run python3 for the study's grading");
    char        buffer[256];
    std::string output;
    while (std::fgets(buffer, sizeof(buffer), pipe))
      output += buffer;
    const int                  status = pclose(pipe);
    std::istringstream         words(output);
    std::array<std::string, 3> grading;
    if (status != 0 || !(words >> grading[0] >> grading[1] >> grading[2]))
      throw std::runtime_error(
        "benchmarks/table-4-1/run.py: mesh_entries() gave no grading");
    return grading;
  }

  /**
   * prm/table-4-1.prm (domain radius = depth = L = 100 a) on a coarser mesh
   * graded toward the footing edge (r, z) = (a, 0) with edge cells
   * h_e = 0.08 a: 4 cells on the footing, 10 beyond, 12 in depth (the
   * scene's and the study's base mesh is 6, 14, 16 with h_e = 0.05; see
   * doc/table-4-1.md for the comparison). The bonded and smooth models
   * drop the footing block and its interface and tie the soil surface
   * r < a (boundary 4) instead.
   */
  std::string
  footing_prm(const Model        model,
              const double       nu,
              const double       k,
              const unsigned int cycles)
  {
    const double       L = 100, h_e = 0.08;
    const unsigned int n_foot = 4, n_out = 10, n_depth = 12;
    const auto [g_foot, g_out, g_depth] =
      study_grading(L, h_e, n_foot, n_out, n_depth);
    const std::string E = text(2 * 1000. * (1 + nu));
    std::vector<std::pair<std::string, std::string>> changes = {
      {"Refinement cycles", std::to_string(cycles)},
      {"R cells", std::to_string(n_foot) + ", " + std::to_string(n_out)},
      {"R growth", g_foot + ", " + g_out},
      {"Reference Poisson ratio", text(nu)}};
    std::string mesh_and_tie;
    if (model == Model::interface)
      changes.insert(changes.end(),
                     {{"Z cells", std::to_string(n_depth) + ", 1"},
                      {"Z growth", g_depth + ", 1"},
                      {"Materials",
                       "0: E=" + E + ", nu=" + text(nu) + "; 1: E=1e6, nu=0.2"},
                      {"Interfaces", "5: kn=" + text(k) + ", ks=" + text(k)}});
    else
      {
        changes.insert(changes.end(),
                       {{"Z breakpoints", "-100, 0"},
                        {"Z cells", std::to_string(n_depth)},
                        {"Z growth", g_depth},
                        {"Material regions", ""},
                        {"Removed regions", ""},
                        {"Interface lines", ""},
                        {"Materials", "0: E=" + E + ", nu=" + text(nu)},
                        {"Interfaces", ""},
                        {"Tie", "boundary"},
                        {"Id", "4"}});
        mesh_and_tie =
          test_support::entries("Mesh", {{"Surface patch radius", "1"}}) +
          test_support::entries("Rigid foundation",
                                {{"Tied components",
                                  model == Model::smooth ? "normal" : "all"}});
      }
    // The study values and the O(h) order check were made with the
    // standard element; Volumetric strain = auto would switch nu = 0.49 to
    // bbar, whose pre-asymptotic order there is 1.7-1.8 (values unchanged
    // within the tolerances).
    return test_support::bundled_prm("prm/table-4-1.prm", changes) +
           mesh_and_tie +
           test_support::entries("Discretization",
                                 {{"Volumetric strain", "standard"}});
  }

  /** theta E_s a^3 / M on each refinement cycle. */
  std::vector<double>
  rotations(const Model        model,
            const double       nu,
            const double       k,
            const unsigned int cycles)
  {
    const ResultsTable results =
      test_support::run(footing_prm(model, nu, k, cycles));
    const double        E = 2 * 1000. * (1 + nu);
    std::vector<double> values;
    for (unsigned int c = 0; c < cycles; ++c)
      values.push_back(E * results.get("foundation_rotation",
                                       Harmonic{1, Family::symmetric},
                                       c));
    return values;
  }

  /** Richardson extrapolation from meshes h, h/2, h/4 (observed order). */
  double
  extrapolate(const std::vector<double> &v, double &order)
  {
    const double d1 = v[1] - v[0], d2 = v[2] - v[1];
    order = std::log2(d1 / d2);
    return v[2] + d2 / (std::pow(2., order) - 1.);
  }

  std::string
  label(const char *what, const double nu)
  {
    std::ostringstream s;
    s << what << ", nu = " << nu;
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       start = std::chrono::steady_clock::now();

  for (unsigned int i = 0; i < 6; ++i)
    {
      const double              nu = nus[i];
      double                    p_b, p_k, p_s;
      const std::vector<double> bonded = rotations(Model::bonded, nu, 0, 3);
      const std::vector<double> k1e10 =
        rotations(Model::interface, nu, 1e10, 3);
      const std::vector<double> smooth = rotations(Model::smooth, nu, 0, 3);
      const double              ext_b  = extrapolate(bonded, p_b);
      const double              ext_k  = extrapolate(k1e10, p_k);
      const double              ext_s  = extrapolate(smooth, p_s);
      std::cout << std::setprecision(6) << "  nu = " << nu << ": bonded "
                << bonded[0] << " " << bonded[1] << " " << bonded[2] << " -> "
                << ext_b << " (p = " << p_b << "); k=1e10 -> " << ext_k
                << " (p = " << p_k << "); smooth " << smooth[2] << " -> "
                << ext_s << " (p = " << p_s << ")" << std::endl;

      // The edge singularity gives O(h); an order far from 1 means the
      // meshes are not in the asymptotic range and the extrapolation is
      // not to be trusted.
      check::in_range(label("observed order, bonded", nu), p_b, 0.6, 1.6);
      check::in_range(label("observed order, smooth", nu), p_s, 0.6, 1.6);

      // 2%: the thesis used one coarse 8-node mesh on a
      // 20 a x 25 e domain; our converged values (study: 4 levels, finer
      // base mesh) agree with the thesis within 0.3% (0.6% at nu = 0), the
      // test's mesh adds < 0.1%, the truncation < 0.01%.
      check::relative(label("bonded vs thesis", nu),
                      ext_b,
                      thesis_bonded[i],
                      0.02);
      check::relative(label("k = 1e10 vs thesis", nu),
                      ext_k,
                      thesis_k1e10[i],
                      0.02);
      // 0.3%: the test's coarser base mesh vs the study's converged value
      // (the study shows 0.08% at nu = 0.3; margin for the other nu).
      check::relative(label("bonded vs converged study value", nu),
                      ext_b,
                      study_bonded[i],
                      0.003);
      // k a / E_s >= 3e6: the interface compliance is ~ E_s / (k a) < 1e-6
      // of the rotation, so the k = 1e10 interface reproduces the bonded
      // contact (thesis: "parfaitement identiques") to round-off of the
      // extrapolation; 1e-4 allows for the different mesh (footing block).
      check::relative(label("k = 1e10 vs bonded (same model)", nu),
                      ext_k,
                      ext_b,
                      1e-4);
      // 1%: the study shows < 0.1% at this mesh, the rest is
      // margin (the study's 4-level value is within 0.02%).
      check::relative(label("smooth vs 3(1-nu^2)/4", nu),
                      ext_s,
                      0.75 * (1 - nu * nu),
                      0.01);

      // Ordering of the interface rows (thesis: the rotation decreases as
      // the interface stiffness grows): on the same coarse mesh the
      // interface compliance adds a positive rotation ~ 1/k, so a strict
      // ordering needs no extrapolation.
      const double k1e6 = rotations(Model::interface, nu, 1e6, 1)[0];
      const double k1e8 = rotations(Model::interface, nu, 1e8, 1)[0];
      std::cout << std::setprecision(6) << "  nu = " << nu
                << ", coarse mesh: k=1e6 " << k1e6 << ", k=1e8 " << k1e8
                << ", k=1e10 " << k1e10[0] << std::endl;
      check::that(label("theta(1e6) > theta(1e8) > theta(1e10)", nu),
                  k1e6 > k1e8 && k1e8 > k1e10[0]);
    }
  std::cout << "  wall time "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
                 .count()
            << " s" << std::endl;
  return check::summary();
}
