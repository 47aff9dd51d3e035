// Rigid disc displaced horizontally in an elastic ring (thesis ch. 5 and
// Table 7.1), the bundled prm/disc-rough.prm with a unit H and the interface
// law and degree under test. Disc radius a = 0.5 m, ring to R = 10 m
// (outer boundary fixed), E = 1e5 kPa, nu = 0.3, plane strain as a slice
// z in [-0.5, 0.5] one element thick with v = 0 on top and bottom (the
// solution is z-independent: checked below), harmonic n = 1 symmetric, the
// disc (material 1, contains the axis) rigid by exact constraints, loaded by
// H = 1 kN (unit thickness: H = P per unit length), so P / ubar = 1 / U_h.
//
// Reference: the plane-strain closed form derived in
// doc/derivations/disc_ring.py (Michell n = 1 solution, Baguelin, Frank &
// Said 1977, all finite-R terms), evaluated here from its general solution
//   U = c b1 r^2 + b2 / r^2 - b3 + b4 / kappa - b4 ln r,
//   W = b1 r^2 + b2 / r^2 + b3 + b4 ln r,   c = (4 nu - 1) / (4 nu - 5),
// with b1..b4 fixed by the four boundary conditions (rough: U = ubar,
// W = -ubar at a; smooth: U = ubar, tau_rtheta = 0 at a; U = W = 0 at R).
// This C++ evaluation is first checked against the numbers the sympy script
// prints (1e-8).
//
// 1. Rough (kn = ks = 1e10), FE_Q(2): P / ubar within 1%, sigma_r,
//    sigma_theta (amplitudes of cos t, i.e. the values along t = 0) and
//    tau_rtheta (amplitude of sin t, the value along t = pi/2: it vanishes on
//    t = 0) at r / a = 1.5, 2, 3, 5 within 1%. Tolerance: the mesh (32 cells
//    graded toward a, quadratic elements) and the interface compliance
//    (traction / 1e10 ~ 1e-6 ubar) give errors well below 1%; 1% is the
//    brief's engineering tolerance, and sigma_theta, which changes sign near
//    r / a = 1.6, is compared with a floor of 1% of |sigma_r| there.
// 2. Smooth (kn = 1e10, ks = 0): P / ubar lower than rough (thesis 5.4,
//    Fig. 5.25b) and within 1% of the smooth closed form; same stresses.
// 3. Plane strain: |V| <= 1e-10 ubar at every DoF, U(r, z) independent of z.
// 4. Table 7.1: FE_Q(4) with the 10-node rough interface (and FE_Q(2) with
//    the 6-node one): at every node pair the CSV jump equals traction / k
//    (1e-6 relative to the largest traction), |jump| <= 1e-4 ubar, and the
//    soil-side and disc-side nodal U and W equal ubar and -ubar within
//    1e-4 ubar (the thesis table shows soil-side nodes departing by up to
//    23% (6-node) and 17% (10-node): not reproduced, see doc/disc.md).
//    The disc side is exact up to round-off: the rigid constraints make it
//    exact, but the disc rotation Theta (zero by symmetry) comes out at
//    ~1e-11 ubar / a (condition ~ kn a / E = 5e4): bound 1e-9.
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/harmonic/rigid_foundation.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <fstream>

using namespace FourierSSI;

namespace
{
  const double E = 1e5, nu = 0.3, a = 0.5, R = 10.;
  const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double mu     = E / (2. * (1. + nu));
  const double kappa  = 3. - 4. * nu;

  /** Closed-form amplitudes at radius r for ubar = 1. */
  struct Exact
  {
    double U, W, Sr, St, T;
  };

  class ClosedForm
  {
  public:
    explicit ClosedForm(const bool rough)
    {
      // Each boundary condition is linear in b: assemble it column by column.
      FullMatrix<double> A(4, 4);
      Vector<double>     rhs(4), b(4);
      for (unsigned int j = 0; j < 4; ++j)
        {
          std::array<double, 4> e = {{0., 0., 0., 0.}};
          e[j]                    = 1.;
          const Exact x_a = evaluate(e, a), x_R = evaluate(e, R);
          A(0, j) = x_a.U;
          A(1, j) = rough ? x_a.W : x_a.T;
          A(2, j) = x_R.U;
          A(3, j) = x_R.W;
        }
      rhs(0) = 1.;
      rhs(1) = rough ? -1. : 0.;
      A.gauss_jordan();
      A.vmult(b, rhs);
      for (unsigned int j = 0; j < 4; ++j)
        coefficients[j] = b(j);
    }

    Exact
    operator()(const double r) const
    {
      return evaluate(coefficients, r);
    }

    /** P / ubar = -pi r (Sr - T), the same at every r. */
    double
    stiffness(const double r = a) const
    {
      const Exact x = (*this)(r);
      return -M_PI * r * (x.Sr - x.T);
    }

  private:
    static Exact
    evaluate(const std::array<double, 4> &b, const double r)
    {
      const double c = (4. * nu - 1.) / (4. * nu - 5.);
      const double U = c * b[0] * r * r + b[1] / (r * r) - b[2] + b[3] / kappa -
                       b[3] * std::log(r);
      const double W =
        b[0] * r * r + b[1] / (r * r) + b[2] + b[3] * std::log(r);
      const double dU = 2. * c * b[0] * r - 2. * b[1] / (r * r * r) - b[3] / r;
      const double dW = 2. * b[0] * r - 2. * b[1] / (r * r * r) + b[3] / r;
      const double er = dU, et = (U + W) / r, g = -U / r + dW - W / r;
      return {U,
              W,
              (lambda + 2. * mu) * er + lambda * et,
              lambda * er + (lambda + 2. * mu) * et,
              mu * g};
    }

    std::array<double, 4> coefficients;
  };

  /**
   * prm/disc-rough.prm with the interface law and degree under test and a
   * unit H (P / ubar = 1 / U_h); FE_Q(4) on the mesh with half the soil
   * cells.
   */
  std::string
  prm(const std::string &interface, const unsigned int degree)
  {
    return test_support::bundled_prm(
      "prm/disc-rough.prm",
      {{"Polynomial degree", std::to_string(degree)},
       {"R cells", degree == 2 ? "2, 32" : "2, 16"},
       {"R growth", degree == 2 ? "1, 1.12" : "1, 1.25"},
       {"Interfaces", "5: " + interface},
       {"Horizontal force", "1"}});
  }

  /** FE stress amplitudes (Sr, St, T) at (r, z). */
  std::array<double, 3>
  fe_stress(const HarmonicProblem &problem, const Point<2> &x)
  {
    Vector<double>            value(3);
    std::vector<Tensor<1, 2>> gradient(3);
    const DoFHandler<2>      &dh = problem.get_dof_handler();
    VectorTools::point_value(dh, problem.get_solution(), x, value);
    VectorTools::point_gradient(dh, problem.get_solution(), x, gradient);
    const StrainVector strain =
      problem.get_operator().strain({{value(0), value(1), value(2)}},
                                    {{gradient[0], gradient[1], gradient[2]}},
                                    x[0]);
    const StrainVector s = hooke_stress(strain, lambda, mu);
    return {{s[StrainIndex::rr], s[StrainIndex::tt], s[StrainIndex::rt]}};
  }

  /** Solve; return P / ubar and check plane strain and the stresses. */
  double
  run_disc(const std::string &law,
           const unsigned int degree,
           const ClosedForm  &exact,
           const bool         check_stresses,
           const std::string &csv)
  {
    const std::string tag = " (" + law.substr(0, law.find(',')) +
                            ", p=" + std::to_string(degree) + ")";
    const AllParameters parameters =
      test_support::parameters_from(prm(law, degree));
    Triangulation<2> triangulation;
    build_mesh(parameters.mesh, triangulation);
    HarmonicProblem problem(parameters, {1, Family::symmetric}, triangulation);
    problem.run();
    const RigidMotion motion =
      problem.get_foundation()->motion(problem.get_solution());
    const double ubar = motion.horizontal_displacement;
    const double k    = 1. / ubar;
    check::small("disc rotation Theta / (ubar / a)" + tag,
                 motion.rotation * a / ubar,
                 1e-9);

    // Plane strain: V = 0 everywhere, U independent of z.
    const DoFHandler<2>                        &dh = problem.get_dof_handler();
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dh, points);
    std::vector<types::global_dof_index> dofs(dh.get_fe().n_dofs_per_cell());
    double                               max_v = 0.;
    for (const auto &cell : dh.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (dh.get_fe().system_to_component_index(i).first == 1)
            max_v = std::max(max_v, std::abs(problem.get_solution()(dofs[i])));
      }
    check::small("plane strain: max |V| / ubar" + tag, max_v / ubar, 1e-10);
    {
      Vector<double> top(3), mid(3);
      VectorTools::point_value(dh,
                               problem.get_solution(),
                               Point<2>(1., 0.4),
                               top);
      VectorTools::point_value(dh,
                               problem.get_solution(),
                               Point<2>(1., 0.),
                               mid);
      check::small("plane strain: |U(1, 0.4) - U(1, 0)| / ubar" + tag,
                   (top(0) - mid(0)) / ubar,
                   1e-10);
    }

    if (check_stresses)
      for (const double x : {1.5, 2., 3., 5.})
        {
          const Exact       ex = exact(x * a);
          const auto        fe = fe_stress(problem, Point<2>(x * a, 0.));
          const std::string at = " at r/a=" + Utilities::to_string(x) + tag;
          check::relative("sigma_r" + at, fe[0] / ubar, ex.Sr, 0.01);
          check::relative("sigma_theta" + at,
                          fe[1] / ubar,
                          ex.St,
                          0.01,
                          0.01 * std::abs(ex.Sr));
          check::relative("tau_rtheta" + at, fe[2] / ubar, ex.T, 0.01);
        }

    if (!csv.empty())
      {
        // Table 7.1: jumps = traction / k at every node pair, tiny jumps, and
        // both sides of the interface follow the disc.
        problem.get_interfaces()->write_csv(5, problem.get_solution(), csv);
        const auto  rows  = test_support::read_csv_numbers(csv);
        const auto &kk    = problem.get_interfaces()->get_stiffness().at(0);
        double      t_max = 0., consistency = 0., jump = 0.;
        for (const auto &row : rows)
          t_max = std::max(
            {t_max, std::abs(row[7]), std::abs(row[8]), std::abs(row[9])});
        for (const auto &row : rows)
          {
            consistency = std::max({consistency,
                                    std::abs(row[5] * kk.normal - row[7]),
                                    std::abs(row[4] * kk.shear - row[8]),
                                    std::abs(row[6] * kk.shear - row[9])});
            jump        = std::max(
              {jump, std::abs(row[4]), std::abs(row[5]), std::abs(row[6])});
          }
        check::that("interface CSV has " + std::to_string(rows.size()) +
                      " node rows" + tag,
                    rows.size() == (degree == 2 ? 3u : 5u));
        check::small("max |k jump - traction| / max |traction|" + tag,
                     consistency / t_max,
                     1e-6);
        check::small("max |jump| / ubar" + tag, jump / ubar, 1e-4);
        // Nodal U, W on the interface line from both sides.
        double dev_soil = 0., dev_disc = 0.;
        std::cout << "  interface nodes r = a (z, side, U/ubar, W/ubar)" << tag
                  << ":\n";
        for (const auto &cell : dh.active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            const bool soil = cell->material_id() == 0;
            std::map<double, std::array<double, 2>> nodes;
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const Point<2> &p = points[dofs[i]];
                const unsigned  c =
                  dh.get_fe().system_to_component_index(i).first;
                if (std::abs(p[0] - a) > 1e-12 || c == 1)
                  continue;
                nodes[p[1]][c == 0 ? 0 : 1] = problem.get_solution()(dofs[i]);
              }
            for (const auto &[z, uw] : nodes)
              {
                const double d =
                  std::max(std::abs(uw[0] - ubar), std::abs(uw[1] + ubar)) /
                  ubar;
                (soil ? dev_soil : dev_disc) =
                  std::max(soil ? dev_soil : dev_disc, d);
                std::cout << "    " << z << (soil ? " soil " : " disc ")
                          << std::setprecision(12) << uw[0] / ubar << " "
                          << uw[1] / ubar << "\n";
              }
          }
        check::small("soil side: max |U - ubar|, |W + ubar| / ubar" + tag,
                     dev_soil,
                     1e-4);
        check::small("disc side: max |U - ubar|, |W + ubar| / ubar" + tag,
                     dev_disc,
                     1e-9);
      }
    return k;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const ClosedForm                 rough(true), smooth(false);

  std::cout << "0. closed form (C++) vs doc/derivations/disc_ring.py\n";
  check::relative("rough P/ubar", rough.stiffness(), 139817.34832893132, 1e-8);
  check::relative("rough P/ubar at r = 3 a (equilibrium)",
                  rough.stiffness(3. * a),
                  139817.34832893132,
                  1e-8);
  check::relative("smooth P/ubar",
                  smooth.stiffness(),
                  122235.03703427878,
                  1e-8);
  check::relative("rough sigma_r(1.5 a), ubar = 1e-3",
                  1e-3 * rough(1.5 * a).Sr,
                  -41.533589,
                  1e-6);
  check::relative("smooth sigma_theta(2 a), ubar = 1e-3",
                  1e-3 * smooth(2. * a).St,
                  6.711308,
                  1e-6);
  check::small("smooth tau_rtheta(a)", smooth(a).T, 1e-6);

  std::cout << "1. rough interface, FE_Q(2), 6-node interface\n";
  const double k_rough =
    run_disc("rough", 2, rough, true, "disc_rough_p2_interface.csv");
  check::relative("rough P/ubar", k_rough, rough.stiffness(), 0.01);

  std::cout << "2. smooth interface, FE_Q(2)\n";
  const double k_smooth = run_disc("smooth", 2, smooth, true, "");
  check::relative("smooth P/ubar", k_smooth, smooth.stiffness(), 0.01);
  check::that("smooth P/ubar < rough P/ubar (thesis 5.4)", k_smooth < k_rough);

  std::cout << "4. Table 7.1: rough, FE_Q(4), 10-node interface\n";
  const double k4 =
    run_disc("rough", 4, rough, true, "disc_rough_p4_interface.csv");
  check::relative("rough P/ubar (p=4)", k4, rough.stiffness(), 0.01);
  return check::summary();
}
