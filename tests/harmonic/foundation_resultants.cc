// Resultants on a rigid foundation map exactly to harmonics (issue #6,
// verify 2), on the bundled embedded footing (prm/embedded-footing.prm,
// coarse mesh, Harmonics = auto):
//  - V + H_x + M_y + T together solve n = 0 symmetric, n = 0 antisymmetric
//    and n = 1 symmetric only, and their 3D field equals the sum of the four
//    separate runs to 1e-8 relative. Same matrices, so the only difference
//    is the round-off of the direct solves, which grows with the condition
//    number, i.e. linearly with the penalty kn: doc/robustness.md measures
//    a round-off drift of 7e-6 at kn = 1e14, hence ~7e-10 at the scene's
//    kn = 1e10; the bound leaves a factor ~10 above that;
//  - H_y gives the H_x field turned by 90 degrees, and M_x = -M the M_y = M
//    field turned by 90 degrees: u(r, z, t) = u_x-case(r, z, t - 90 deg),
//    component by component in cylindrical coordinates (1e-10 relative: the
//    antisymmetric family is the symmetric one with W -> -W, so only
//    round-off separates them).
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/driver/simulator.h>
#include <functional>
#include <set>

using namespace FourierSSI;

namespace
{
  std::string
  scene(const std::string &loads)
  {
    return test_support::bundled_prm("prm/embedded-footing.prm") +
           "subsection Discretization\n set Harmonics = auto\n"
           " set Refinement cycles = 1\nend\n"
           "subsection Rigid foundation\n set Stiffness coefficients = "
           "false\n" +
           loads + "end\n";
  }

  struct Run
  {
    explicit Run(const std::string &loads)
      : parameters(test_support::parameters_from(scene(loads)))
      , simulator(parameters)
      , results(simulator.run(std::cout, false))
    {}

    std::set<std::pair<unsigned int, Family>>
    harmonics() const
    {
      std::set<std::pair<unsigned int, Family>> s;
      for (const ResultRow &row : results.rows())
        s.insert({row.harmonic.n, row.harmonic.family});
      return s;
    }

    FieldValues
    at(const Point<2> &p, const double degrees) const
    {
      return simulator.get_reconstruction().evaluate(p,
                                                     degrees * numbers::PI /
                                                       180.);
    }

    AllParameters parameters;
    Simulator     simulator;
    ResultsTable  results;
  };

  const std::vector<Point<2>> points = {Point<2>(0.5, -0.5),
                                        Point<2>(1.5, -0.2),
                                        Point<2>(0.3, -2.),
                                        Point<2>(3., 0.)};
  const std::vector<double>   angles = {0., 35., 90., 200.};

  /** max |target - other| / max |target| over points, angles, components */
  double
  defect(const std::function<FieldValues(const Point<2> &, double)> &target,
         const std::function<FieldValues(const Point<2> &, double)> &other)
  {
    double d = 0., scale = 0.;
    for (const Point<2> &p : points)
      for (const double t : angles)
        {
          const FieldValues a = target(p, t), b = other(p, t);
          for (unsigned int k = 0; k < 3; ++k)
            {
              d = std::max(d, std::abs(a.displacement[k] - b.displacement[k]));
              scale = std::max(scale, std::abs(a.displacement[k]));
            }
        }
    return d / scale;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const Run all(" set Vertical force = 200\n set Horizontal force = 100\n"
                " set Moment = 50\n set Torque = 30\n");
  const std::set<std::pair<unsigned int, Family>> expected = {
    {0, Family::symmetric}, {0, Family::antisymmetric}, {1, Family::symmetric}};
  check::that("V + H + M + T solves n = 0 (both families) and n = 1 "
              "symmetric only",
              all.harmonics() == expected);

  const Run v(" set Vertical force = 200\n"),
    h(" set Horizontal force = 100\n"), m(" set Moment = 50\n"),
    t(" set Torque = 30\n");
  check::that("V alone solves n = 0 symmetric only",
              v.harmonics() == std::set<std::pair<unsigned int, Family>>{
                                 {0, Family::symmetric}});
  check::small("combined vs sum of four runs, max |du| / max |u|",
               defect([&](const Point<2> &p, double a) { return all.at(p, a); },
                      [&](const Point<2> &p, double a) {
                        FieldValues s;
                        for (const Run *run : {&v, &h, &m, &t})
                          {
                            const FieldValues f = run->at(p, a);
                            for (unsigned int k = 0; k < 3; ++k)
                              s.displacement[k] += f.displacement[k];
                          }
                        return s;
                      }),
               1e-8);

  const Run hy(" set Horizontal force y = 100\n"), mx(" set Moment x = -50\n");
  check::that("H_y solves n = 1 antisymmetric only",
              hy.harmonics() == std::set<std::pair<unsigned int, Family>>{
                                  {1, Family::antisymmetric}});
  check::small("H_y field vs H_x field turned by 90 degrees",
               defect([&](const Point<2> &p, double a) { return hy.at(p, a); },
                      [&](const Point<2> &p, double a) {
                        return h.at(p, a - 90.);
                      }),
               1e-10);
  check::small("M_x = -M field vs M_y = M field turned by 90 degrees",
               defect([&](const Point<2> &p, double a) { return mx.at(p, a); },
                      [&](const Point<2> &p, double a) {
                        return m.at(p, a - 90.);
                      }),
               1e-10);
  // And not trivially: the turned field differs from the unturned one.
  check::that("H_y field differs from the unturned H_x field",
              defect([&](const Point<2> &p, double a) { return hy.at(p, a); },
                     [&](const Point<2> &p, double a) { return h.at(p, a); }) >
                0.1);
  return check::summary();
}
