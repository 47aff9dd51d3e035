// Loads given as functions of theta (doc/loads.md), on the
// bundled scene prm/wind-pressure.prm (a flexible circular surface load):
//  1. p = cos t + 0.5 cos 3t solves exactly harmonics 1 and 3 (symmetric);
//     the superposed 3D field equals the sum of the two single-harmonic
//     runs to round-off (1e-10 relative: the harmonic systems are the same
//     matrices with right-hand sides that differ by the round-off of a
//     256-sample DFT, ~1e-14), and each harmonic equals the run with the
//     amplitude written by hand in Boundary conditions/Traction (strain
//     energy to 1e-12: an independent path through the amplitude
//     convention of thesis eq. 3.1).
//  3. the half-cosine pressure p0 max(cos t, 0): the decomposition's
//     amplitudes match the closed form (2/pi) |cos(n pi/2)|/(n^2 - 1)
//     within 1e-4 p0 (aliasing is held below a tenth of the 1e-3
//     selection tolerance); tolerance 1e-3 selects n = 0, 1, 2, 4, ..., 24
//     (14 harmonics, none antisymmetric); the series of the decomposed
//     (signed) coefficients over the selected harmonics at t = 0 equals the
//     closed-form partial sum 1 - sum_{m>=13} (2/pi)(-1)^m/(1 - 4m^2)
//     within 14 x 1e-4 (the per-coefficient aliasing bound); the even
//     harmonics' contributions to the surface settlement decrease
//     monotonically and those above n = 12 add less than 1%.
//  Concurrency: the same run on 1 and 2 threads agrees to 1e-12.
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <set>

using namespace FourierSSI;

namespace
{
  std::string
  scene(const std::string &traction, const std::string &extra = "")
  {
    return test_support::bundled_prm("prm/wind-pressure.prm") +
           "subsection Loads\n set Traction = 4: z = " + traction + "\nend\n" +
           extra;
  }

  std::set<std::pair<unsigned int, Family>>
  solved(const ResultsTable &results)
  {
    std::set<std::pair<unsigned int, Family>> s;
    for (const ResultRow &row : results.rows())
      s.insert({row.harmonic.n, row.harmonic.family});
    return s;
  }

  /** Max over sample points and angles of |a - (b + c)| and of |a|. */
  std::pair<double, double>
  superposition_defect(const FieldReconstruction &a,
                       const FieldReconstruction &b,
                       const FieldReconstruction &c)
  {
    double defect = 0., scale = 0.;
    for (const double r : {0., 0.4, 1., 2.5})
      for (const double z : {0., -0.7})
        for (const double degrees : {0., 30., 77., 180.})
          {
            const Point<2> p(r, z);
            const double   t  = degrees * numbers::PI / 180.;
            const auto     va = a.evaluate(p, t), vb = b.evaluate(p, t),
                       vc = c.evaluate(p, t);
            for (unsigned int k = 0; k < 3; ++k)
              {
                defect =
                  std::max(defect,
                           std::abs(va.displacement[k] - vb.displacement[k] -
                                    vc.displacement[k]));
                scale = std::max(scale, std::abs(va.displacement[k]));
              }
          }
    return {defect, scale};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 1. Two harmonics and superposition.
  {
    const AllParameters both =
      test_support::parameters_from(scene("-(cos(theta) + 0.5*cos(3*theta))"));
    const AllParameters first =
      test_support::parameters_from(scene("-cos(theta)"));
    const AllParameters third =
      test_support::parameters_from(scene("-0.5*cos(3*theta)"));
    Simulator          s_both(both), s_first(first), s_third(third);
    const ResultsTable r_both = s_both.run(std::cout, false);
    s_first.run(std::cout, false);
    s_third.run(std::cout, false);
    const std::set<std::pair<unsigned int, Family>> expected = {
      {1, Family::symmetric}, {3, Family::symmetric}};
    check::that("cos t + 0.5 cos 3t solves exactly n = 1 and 3 symmetric",
                solved(r_both) == expected);
    const auto [defect, scale] =
      superposition_defect(s_both.get_reconstruction(),
                           s_first.get_reconstruction(),
                           s_third.get_reconstruction());
    check::small("superposition defect / max |u|", defect / scale, 1e-10);

    for (const auto &[n, amplitude] :
         std::vector<std::pair<unsigned int, std::string>>{{1, "-1"},
                                                           {3, "-0.5"}})
      {
        const ResultsTable by_hand = test_support::run(
          test_support::bundled_prm("prm/wind-pressure.prm") +
          "subsection Discretization\n set Harmonics = " + std::to_string(n) +
          "\nend\nsubsection Loads\n set Traction =\nend\n"
          "subsection Boundary conditions\n set Traction = 4: z = " +
          amplitude + "\nend\n");
        const Harmonic h{n, Family::symmetric};
        check::relative("strain energy n = " + std::to_string(n) +
                          ", decomposed vs amplitude by hand",
                        r_both.get("strain_energy", h, 0),
                        by_hand.get("strain_energy", h, 0),
                        1e-12);
      }
  }

  // 3. The half-cosine (wind-like) pressure.
  {
    const AllParameters parameters =
      test_support::parameters_from(scene("-max(cos(theta), 0)"));
    Triangulation<2> triangulation;
    build_mesh(parameters.mesh, triangulation);
    const ScenePlan           plan     = plan_scene(parameters, triangulation);
    std::vector<unsigned int> expected = {0, 1};
    for (unsigned int n = 2; n <= 24; n += 2)
      expected.push_back(n);
    std::vector<unsigned int> selected;
    bool                      any_antisymmetric = false;
    for (const Harmonic &h : plan.harmonics)
      {
        if (h.family == Family::symmetric)
          selected.push_back(h.n);
        else
          any_antisymmetric = true;
      }
    std::cout << "  selected harmonics: " << compact_list(selected)
              << std::endl;
    check::that("tolerance 1e-3 selects n = 0, 1, 2, 4, ..., 24 (14)",
                selected == expected && selected.size() == 14);
    check::that("no antisymmetric harmonic", !any_antisymmetric);
    double               series_at_0 = 0.;
    const PointSpectrum &spectrum =
      plan.loads.traction.at(4)->spectrum(Point<2>(0.5, 0.));
    for (unsigned int n = 0; n <= 26; ++n)
      {
        // (1/pi) int max(cos t, 0) cos nt dt, and 1/pi for n = 0.
        const double exact =
          n == 0 ? 1. / numbers::PI :
          n == 1 ? 0.5 :
                   std::abs(2. / numbers::PI * std::cos(n * numbers::PI / 2.) /
                            (1. - double(n) * n));
        const double decomposed =
          plan.load_amplitudes.at({n, Family::symmetric});
        check::relative(
          "amplitude n = " + std::to_string(n), decomposed, exact, 1e-4, 1.);
        if (std::find(selected.begin(), selected.end(), n) != selected.end())
          series_at_0 -= spectrum.get({n, Family::symmetric})[1]; // t_z = -p
      }
    double tail = 0.; // alternating: the error after 1e6 terms is ~1e-13
    for (unsigned int m = 13; m < 1000000; ++m)
      tail +=
        2. / numbers::PI * (m % 2 == 0 ? 1. : -1.) / (1. - 4. * double(m) * m);
    check::relative("selected series of the load at t = 0",
                    series_at_0,
                    1. - tail,
                    14e-4);

    Simulator simulator(parameters);
    simulator.run(std::cout, false);
    std::vector<double> contribution; // settlement at (0.5, 0), t = 0
    double              total = 0.;
    for (const auto &problem : simulator.get_reconstruction().get_problems())
      {
        const double v =
          FieldReconstruction::amplitudes(*problem, Point<2>(0.5, 0.))
            .displacement[1];
        contribution.push_back(v);
        total += v;
      }
    bool   decreasing = true;
    double above_12   = 0.;
    for (unsigned int i = 0; i < selected.size(); ++i)
      {
        if (selected[i] >= 4 &&
            std::abs(contribution[i]) >= std::abs(contribution[i - 1]))
          decreasing = false;
        if (selected[i] > 12)
          above_12 += contribution[i];
      }
    check::that("even-harmonic contributions decrease monotonically",
                decreasing);
    check::small("|contribution of n > 12| / |settlement|",
                 std::abs(above_12 / total),
                 0.01);

    // The same run on one thread.
    const AllParameters serial = test_support::parameters_from(
      scene("-max(cos(theta), 0)",
            "subsection Discretization\n set Concurrent harmonics = 1\nend\n"));
    Simulator one_thread(serial);
    one_thread.run(std::cout, false);
    double difference = 0., scale = 0.;
    for (const double degrees : {0., 60., 150.})
      for (const double r : {0.2, 0.9, 3.})
        {
          const double t = degrees * numbers::PI / 180.;
          const auto   a =
            simulator.get_reconstruction().evaluate(Point<2>(r, -0.3), t);
          const auto b =
            one_thread.get_reconstruction().evaluate(Point<2>(r, -0.3), t);
          for (unsigned int k = 0; k < 3; ++k)
            {
              difference =
                std::max(difference,
                         std::abs(a.displacement[k] - b.displacement[k]));
              scale = std::max(scale, std::abs(a.displacement[k]));
            }
        }
    check::small("2 threads vs 1 thread, max |du| / max |u|",
                 difference / scale,
                 1e-12);
  }
  return check::summary();
}
