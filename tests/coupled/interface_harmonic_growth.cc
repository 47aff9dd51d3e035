// Harmonics chosen by the solution (doc/nonlinear-interfaces.md section 5,
// `Load path/Maximum harmonic`): after a converged step, every
// harmonic n <= Maximum harmonic whose amplitude in the interface traction
// t - t0 exceeds Harmonic tolerance (1e-3) of the largest is added to the
// HarmonicSet (its own factorization) and the step is solved again.
//  (1) A linear scene (prm/disc-smooth.prm) with Maximum harmonic = 12
//      solves exactly the harmonics its plan lists (growth is a coupled-solve
//      feature; the linear path must not pick it up).
//  (2) A nonlinear scene that never yields (prm/disc-gap.prm with c = 1e9,
//      phi = 0, no cut-off) with Maximum harmonic = 12 solves exactly its
//      listed harmonics (n = 1 alone, and n = 0..8) with 0 iterations: its
//      traction is the elastic D d, band-limited to the solved harmonics, so
//      the amplitudes of the others are round-off: checked with Harmonic
//      tolerance = 1e-12 (not the default 1e-3), which adds nothing either.
//  (3) The tensionless disc (prm/disc-gap.prm) listing n = 1 only, with
//      Maximum harmonic = 16: the gap calls for harmonics; the set grows,
//      and P/ubar agrees with the run listing n = 0..16 at once (same theta
//      samples N = 68) to 1e-3 relative: the harmonics left out carry less
//      than the tolerance 1e-3 of the traction spectrum, and P is the n = 1
//      part of the traction integral, so it changes by about that fraction.
//      Positive homogeneity still holds after the growth (P/ubar the same at
//      both steps to 1e-7, the bound of interface_disc_gap_homogeneity).
#include "check.h"
#include "coupled_interface_test_support.h"

#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/mesh/mesh_builder.h>

using namespace FourierSSI;
using test_support::with_entry;

namespace
{
  const std::string growth = "subsection Load path\n"
                             "  set Maximum harmonic = ";

  void
  linear_scene_keeps_its_harmonics()
  {
    const std::string text =
      test_support::bundled_prm("prm/disc-smooth.prm") + growth + "12\nend\n";
    const AllParameters parameters = test_support::parameters_from(text);
    Triangulation<2>    triangulation;
    build_mesh(parameters.mesh, triangulation);
    const unsigned int planned =
      plan_scene(parameters, triangulation).harmonics.size();
    Simulator simulator(parameters);
    simulator.run(std::cout, /*write_files=*/false);
    check::equal("linear scene, Maximum harmonic = 12: harmonics solved",
                 simulator.get_reconstruction().get_problems().size(),
                 planned);
  }

  void
  elastic_scene_keeps_its_harmonics(const std::string &harmonics,
                                    const unsigned int n_listed)
  {
    std::string text = test_support::bundled_prm("prm/disc-gap.prm");
    text             = with_entry(text,
                      "Interfaces",
                      "5: coulomb, kn=1e6, ks=1e6, c=1e9, phi=0, sigma_t=none");
    text             = with_entry(text, "Harmonics", harmonics);
    text += growth + "12\n  set Harmonic tolerance = 1e-12\nend\n";
    const coupled_test::Curve c = coupled_test::run(text);
    check::equal("never yields, Harmonics = " + harmonics + ": harmonics",
                 c.n_harmonics,
                 n_listed);
    unsigned int iterations = 0;
    for (const auto &s : c.steps)
      iterations += s.iterations;
    check::equal("never yields: out-of-balance iterations", iterations, 0);
  }

  double
  last_stiffness(const coupled_test::Curve &c)
  {
    return c.steps.back().H / c.steps.back().u;
  }

  void
  gap_grows_the_set()
  {
    std::string text = test_support::bundled_prm("prm/disc-gap.prm");
    text             = with_entry(text, "Load steps", "2");
    const coupled_test::Curve grown = coupled_test::run(
      with_entry(text, "Harmonics", "1") + growth + "16\nend\n");
    std::string all = "0";
    for (unsigned int n = 1; n <= 16; ++n)
      all += ", " + std::to_string(n);
    const coupled_test::Curve listed =
      coupled_test::run(with_entry(text, "Harmonics", all));
    std::cout << "  grown set: " << grown.n_harmonics << " harmonics, P/ubar "
              << last_stiffness(grown)
              << " kN/m; listed n = 0..16: " << last_stiffness(listed)
              << " kN/m" << std::endl;
    check::in_range("tensionless disc from n = 1: harmonics after growth",
                    grown.n_harmonics,
                    2,
                    17);
    check::relative("P/ubar of the grown set vs n = 0..16 listed",
                    last_stiffness(grown),
                    last_stiffness(listed),
                    1e-3);
    const double first = grown.steps.front().H / grown.steps.front().u;
    check::relative("homogeneity after growth: P/ubar step 2 vs step 1",
                    last_stiffness(grown),
                    first,
                    1e-7);
  }
} // namespace

int
main()
{
  linear_scene_keeps_its_harmonics();
  elastic_scene_keeps_its_harmonics("1", 1);
  elastic_scene_keeps_its_harmonics("0, 1, 2, 3, 4, 5, 6, 7, 8", 9);
  gap_grows_the_set();
  return check::summary();
}
