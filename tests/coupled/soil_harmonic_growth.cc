// Harmonics that follow the plastic zone (doc/soil-plasticity.md section
// 3e, `Load path/Maximum harmonic` with plastic soil): after a converged
// step, every harmonic n <= Maximum harmonic whose amplitude in the theta
// spectrum of the soil's stress change exceeds Harmonic tolerance of the
// largest is added, and the step is solved again on the coupled tangent.
//
// The scene: prm/pile-capacity.prm (the rigid pile slice in Tresca clay,
// pushed sideways) on a coarser ring, listing n = 1 only, Maximum
// harmonic = 3. The load is pure n = 1, so while the soil is elastic every
// other harmonic is exactly zero (no load, no plastic correction). The
// first step where the soil yields is solved with n = 1, its stress
// spectrum calls for n = 3, and the step is solved again from the last
// converged (elastic) state with n = 3 added at zero: the state a run
// listing n = 1, 3 from the start has there too, on the same theta samples
// (both chosen for n_max = 3: N = 16). From then on the two runs take the
// same steps, so
//  (1) Growth is exact: the capacity, its plateau error and every step's
//      load factor, H, u, Newton iterations and plastic sample count agree
//      with the run listing n = 1, 3 to 1e-10 relative (bitwise equality
//      is not promised: the first attempt of the growth step leaves no
//      trace, but sums may be ordered differently). The premise is checked
//      too: the first step is elastic, and n = 3 is added at the first step
//      with plastic samples, no earlier.
//  (2) The growth is reported: one log line names the step, the harmonic
//      and its relative amplitude; results.csv has step_harmonics at every
//      step (1 before the growth, 2 from it on).
//  (3) Both sources: the same pile with its coulomb shaft of
//      prm/pile-adhesion.prm (c = 5 kPa, phi = 0) slips at the first step,
//      while the soil is still elastic; the interface traction calls for
//      n = 3 (the soil's stress does not: round-off), the line names both
//      sources' amplitudes, and the path again equals the run listing
//      n = 1, 3 to 1e-10.
//  (4) Growth never adds a harmonic an elastic state does not have: the
//      same pile with s_u = 1e6 kPa (it never yields) and Maximum harmonic
//      = 3 solves n = 1 alone even at Harmonic tolerance = 1e-12 (D eps is
//      band-limited to the solved harmonics; the others are round-off).
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/driver/simulator.h>
#include <regex>

using namespace FourierSSI;

namespace
{
  /**
   * The pile slice on 2 + 8 radial cells (ratio 1.12^3), pushed to 0.01 d
   * in 10 steps: the first is elastic, the soil yields from the second.
   */
  std::string
  pile_scene(const std::string &harmonics, const std::string &extra)
  {
    return test_support::bundled_prm("prm/pile-capacity.prm",
                                     {{"Harmonics", harmonics},
                                      {"R cells", "2, 8"},
                                      {"R growth", "1, 1.404928"},
                                      {"Target", "0.01"},
                                      {"Load steps", "10"}}) +
           extra;
  }

  struct Run
  {
    std::string  log;
    ResultsTable results;
  };

  Run
  run(const std::string &prm)
  {
    const AllParameters parameters = test_support::parameters_from(prm);
    Simulator           simulator(parameters);
    std::ostringstream  log;
    Run                 r;
    r.results = simulator.run(log, false);
    r.log     = log.str();
    return r;
  }

  /** The rows named `quantity`, in step order. */
  std::vector<double>
  rows(const Run &r, const std::string &quantity)
  {
    std::vector<double> values;
    for (const ResultRow &row : r.results.rows())
      if (row.quantity == quantity)
        values.push_back(row.value);
    return values;
  }

  const std::string growth = "subsection Load path\n"
                             "  set Maximum harmonic = 3\n"
                             "end\n";

  /** Every step's path and the capacity, grown vs listed, to 1e-10. */
  void
  check_same_path(const Run &grown, const Run &listed)
  {
    for (const std::string quantity : {"step_load_factor",
                                       "step_horizontal_force",
                                       "step_horizontal_displacement",
                                       "step_iterations",
                                       "step_plastic_samples",
                                       "capacity_H",
                                       "capacity_H_plateau_error",
                                       "capacity_normalised"})
      {
        const std::vector<double> a = rows(grown, quantity),
                                  b = rows(listed, quantity);
        check::equal(quantity + ": rows", a.size(), b.size());
        for (unsigned int i = 0; i < std::min(a.size(), b.size()); ++i)
          check::relative(quantity + " " + std::to_string(i + 1) +
                            ", grown vs listed n = 1, 3",
                          a[i],
                          b[i],
                          1e-10);
      }
  }

  void
  growth_is_exact()
  {
    const Run grown  = run(pile_scene("1", growth));
    const Run listed = run(pile_scene("1, 3", ""));
    std::cout << grown.log;
    // The premise: n = 3 added at the first step with plastic samples.
    const std::vector<double> plastic = rows(listed, "step_plastic_samples");
    const std::vector<double> solved  = rows(grown, "step_harmonics");
    check::equal("steps of both runs",
                 rows(grown, "step_plastic_samples").size(),
                 plastic.size());
    check::equal("step_harmonics rows: one per step",
                 solved.size(),
                 plastic.size());
    unsigned int first_plastic = 0;
    while (first_plastic < plastic.size() && plastic[first_plastic] == 0.)
      ++first_plastic;
    check::that("the soil yields within the path, after an elastic step",
                first_plastic > 0 && first_plastic < plastic.size());
    for (unsigned int s = 0; s < solved.size(); ++s)
      check::equal("harmonics solved at step " + std::to_string(s + 1),
                   static_cast<long>(solved[s]),
                   s < first_plastic ? 1 : 2);
    const std::regex line("step " + std::to_string(first_plastic + 1) +
                          ": harmonics added, soil-stress amplitude relative "
                          "to the largest above 0\\.001: n=3 symmetric "
                          "\\([0-9.e-]+\\); the step is solved again");
    check::that("one log line names the step, n = 3 and its amplitude",
                std::regex_search(grown.log, line));
    // (1) The same path to round-off.
    check_same_path(grown, listed);
  }

  void
  both_sources_grow_the_set()
  {
    const std::string shaft =
      "5: coulomb, kn=1e6, ks=1e6, c=5, phi=0, sigma_t=none";
    const Run grown = run(
      test_support::with_entry(pile_scene("1", growth), "Interfaces", shaft));
    const Run listed = run(
      test_support::with_entry(pile_scene("1, 3", ""), "Interfaces", shaft));
    std::cout << grown.log;
    const std::regex line(
      "step 1: harmonics added, soil-stress / interface-traction amplitude "
      "relative to the largest above 0\\.001: n=3 symmetric \\([0-9.e-]+ / "
      "[0-9.e-]+\\); the step is solved again");
    check::that("coulomb shaft: one line, both sources' amplitudes",
                std::regex_search(grown.log, line));
    check_same_path(grown, listed);
  }

  void
  elastic_soil_adds_nothing()
  {
    const Run never_yields = run(test_support::with_entry(pile_scene("1", ""),
                                                          "Laws",
                                                          "0: tresca, su=1e6") +
                                 "subsection Load path\n"
                                 "  set Maximum harmonic = 3\n"
                                 "  set Harmonic tolerance = 1e-12\n"
                                 "end\n");
    for (const double n : rows(never_yields, "step_harmonics"))
      check::equal("never yields: harmonics solved", static_cast<long>(n), 1);
    check::that("never yields: no growth line",
                never_yields.log.find("harmonics added") == std::string::npos);
  }
} // namespace

int
main()
{
  growth_is_exact();
  both_sources_grow_the_set();
  elastic_soil_adds_nothing();
  return check::summary();
}
