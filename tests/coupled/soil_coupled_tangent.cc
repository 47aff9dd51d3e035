// The coupled tangent of the plastic soil (Stiffness = tangent,
// include/fourier_ssi/coupled/coupled_tangent.h, doc/soil-plasticity.md section
// 3):
//  (0) derivative: on prm/footing-capacity.prm with harmonics n = 0, 1, 2
//      (both families, N = 13, nu = 0.3 so that the softened shear part is
//      not hidden under the bulk stiffness) and random fields strained to
//      3-15 times the yield strain s_u / G (most samples plastic, on planes
//      and edges, in every principal direction), the softening part
//      K x - K_t x equals (G(u + e x) - G(u - e x)) / (2 e) for random x to
//      1e-6 of its largest entry. The difference quotient is independent of
//      the tangent's assembly (only the return mapping and the projection
//      are shared). e = 1e-9: a perturbation moves a fraction ~ e of the
//      samples across an edge of the yield surface, and the mismatch was
//      measured to scale so (e = 1e-6, 1e-7, 1e-9: 1.2e-3, 1.2e-4, 2.6e-9);
//      1e-6 leaves room for the round-off of the quotient.
//  (1) same answer, fewer iterations: the pile of prm/pile-capacity.prm
//      (n <= 4, 2 steps to 0.01 d) solved by Newton on the coupled tangent
//      and by the initial-stiffness iteration gives the same lateral load at
//      every step to 1e-7 relative (both stop at |R| <= 1e-8 |lambda F|);
//      Newton needs at most 20 iterations a step (quadratic convergence
//      with backtracking; the initial-stiffness iteration takes 60-170).
#include "soil_test_support.h"


using namespace FourierSSI;
using namespace soil_test;

namespace
{
  void
  check_derivative()
  {
    std::cout << "(0) K_t x = K x - dG/du x, n = 0..2, both families"
              << std::endl;
    Run          run(scene({{"Harmonics", "0, 1, 2"},
                            {"Family", "both"},
                            {"Theta samples", "13"},
                            {"Materials", "0: G=3000, nu=0.3"}}));
    std::mt19937 rng(7);
    // Cells of 0.1-0.5 m: DoF values of 5e-3 m give strains of about
    // 1e-2 - 5e-2, 3-15 times s_u / G = 1/300.
    const auto u = random_fields(*run.set, rng, 5e-3);
    const auto x = random_fields(*run.set, rng, 1.);
    const auto m = tangent_mismatch(run, u, x, 1e-9);
    // The check means something only if the plastic part is large.
    std::cout << "  max |dG/du x| / max |K_t x| = " << m.softened / m.tangent
              << std::endl;
    check::small("max |K_t x - (K x - dG/du x)| / max |dG/du x|",
                 m.error / m.softened,
                 1e-6);
  }

  std::vector<LoadStepResult>
  pile_curve(const std::string &stiffness)
  {
    std::string text =
      test_support::bundled_prm("prm/pile-capacity.prm",
                                {{"Harmonics", "0, 1, 2, 3, 4"},
                                 {"Target", "0.01"},
                                 {"Load steps", "2"}});
    text +=
      "subsection Soil plasticity\n  set Stiffness = " + stiffness + "\nend\n";
    Run run(text);
    run.solver->run(std::cout);
    return run.solver->get_steps();
  }

  void
  check_same_curve()
  {
    std::cout << "(1) pile, n <= 4: Newton vs initial stiffness" << std::endl;
    const auto newton  = pile_curve("tangent");
    const auto elastic = pile_curve("elastic");
    check::equal("steps", newton.size(), elastic.size());
    unsigned int most = 0;
    for (unsigned int s = 0; s < newton.size() && s < elastic.size(); ++s)
      {
        check::relative("step " + std::to_string(s + 1) + " load factor",
                        newton[s].load_factor,
                        elastic[s].load_factor,
                        1e-7);
        most = std::max(most, newton[s].iterations);
      }
    check::in_range("Newton iterations per step (most)", most, 1, 20);
  }
} // namespace

int
main()
{
  check_derivative();
  check_same_curve();
  return check::summary();
}
