// Newton for interface-only scenes (Load path/Stiffness =
// tangent, doc/nonlinear-interfaces.md section 5b) and the convergence test
// against the internal force scale, on the disc in a ring of
// prm/disc-gap.prm (rigid disc r0 = 0.5 m pushed along x in an elastic ring,
// G = E / (2 (1 + nu)) = 38462 kPa, 4 displacement steps) with harmonics
// n = 0..32 and a tensionless Coulomb interface, mu = tan(phi) = 0.3,
// kn = ks = kappa G / r0 for kappa = kn r0 / G = 1e2 ... 1e5.
//  * Convergence: every step converges and the interface tractions balance
//    the applied H to max(1e-8, 1e-9 kappa): the residual tolerance is
//    1e-10 of the force scale max(|lambda F|, |G|), and here |G| ~ kn gap
//    ~ kappa |lambda F| (measured |G| / |lambda F| = 1.3e6 at kappa = 1e6),
//    so the bound is 10 times what the test on |R| guarantees. Newton
//    updates in the worst step with N = 132 samples, as upper bounds 1.5
//    times the measured counts (3, 4, 34, 52 at kappa = 1e2, 1e3, 1e4, 1e5;
//    the goal of 15 holds up to 1e3 only): 5, 6, 50, 80.
//  * kappa = 1e5: the out-of-balance load G ~ kn gap is 1e5 times the
//    applied load, and the initial-stiffness iteration measured against
//    the applied load alone does not converge there; here it must.
//  * Same answer as the initial-stiffness iteration where that converges
//    quickly (kappa = 1e2 and 1e3, Anderson): the stick/slip/open counts of
//    every step equal, and P/ubar to 1e-7 (both converged to 1e-10 of the force
//    scale, times the condition of the slipping mode).
//  * The penalty error falls like 1/kappa: P/ubar(kappa) = P_inf (1 - a /
//    kappa + ...), so the differences between successive decades shrink by
//    10: the ratios of successive differences within [5, 20] (measured
//    9.7 and 7.4; the contact arc changes between decades, a band-limited
//    gap of n <= 32 pressed by a stiffer penalty, doc/nonlinear-interfaces.md
//    section 5b; a 1/kappa^2 law would give 100).
//  * Theta samples = 2 n_max + 1 = 65, one sample per degree of freedom of
//    the band-limited gap, Newton's default (the initial-stiffness default
//    132 over-constrain it where the penalty presses it to zero, and the
//    active set cycles; the runs above set 132 explicitly, and with them
//    Newton iterates on the stiff law itself). With 65 samples a law
//    stiffer than K's cap of 1e3 G / l is solved by the augmented
//    Lagrangian on K's springs, its own kn, ks in the multipliers
//    (doc/nonlinear-interfaces.md section 5d): at kappa = 1e3 (kn twice
//    the cap) the same counts and P/ubar as the initial-stiffness
//    iteration with kn in K, to 1e-7; at kappa = 1e4, 1e5, 1e6 at most 10
//    Newton updates a step over all multiplier updates (measured 7),
//    equilibrium as above, and the decade ratio (P(1e5) - P(1e4)) /
//    (P(1e6) - P(1e5)) in [5, 20] (measured 9.998).
//  * Newton's default Theta samples is 2 n_max + 1: kappa = 1e5 with the
//    entry left at 0 gives the N = 65 answer to the bit.
#include "check.h"
#include "coupled_interface_test_support.h"

#include <cmath>
#include <iomanip>
#include <sstream>

using namespace FourierSSI;

namespace
{
  const double G  = 1e5 / (2. * 1.3); // kPa
  const double r0 = 0.5;              // m

  /**
   * `samples`: Theta samples (0: the default, 4 (n_max + 1) = 132 for the
   * initial-stiffness iteration, 2 n_max + 1 = 65 for Newton).
   */
  std::string
  scene(const double       kappa,
        const std::string &stiffness,
        const unsigned int samples)
  {
    const double       kn  = kappa * G / r0;
    const double       phi = std::atan(0.3) * 180. / M_PI;
    std::ostringstream law;
    law << std::setprecision(17) << "coulomb, kn=" << kn << ", ks=" << kn
        << ", c=0, phi=" << phi << ", sigma_t=0";
    const std::string text = coupled_test::disc_in_ring(law.str());
    return text + "\nsubsection Load path\n  set Stiffness = " + stiffness +
           "\n  set Acceleration = anderson\n  set Maximum iterations = "
           "20000\n  set Theta samples = " +
           std::to_string(samples) + "\nend\n";
  }

  struct Run
  {
    coupled_test::Curve curve;
    double              stiffness = 0.; // P / ubar of the last step
  };

  /** The scene solved; `most`: the bound on Newton updates per step. */
  Run
  run(const double       kappa,
      const std::string &stiffness,
      const unsigned int most_updates,
      const unsigned int samples = 0)
  {
    std::cout << "kappa = " << kappa << ", Stiffness = " << stiffness
              << std::endl;
    Run r;
    r.curve           = coupled_test::run(scene(kappa, stiffness, samples));
    const auto &last  = r.curve.steps.back();
    r.stiffness       = last.H / last.u;
    unsigned int most = 0;
    double       worst_equilibrium = 0.;
    for (const auto &s : r.curve.steps)
      {
        most              = std::max(most, s.iterations);
        worst_equilibrium = std::max(worst_equilibrium, s.equilibrium);
      }
    const std::string k =
      " (kappa " + std::to_string(int(std::log10(kappa))) + " decades, " +
      stiffness + ", N = " +
      (samples > 0 ? std::to_string(samples) : std::string("default")) + ")";
    check::that("4 steps converged" + k, r.curve.steps.size() == 4);
    check::small("equilibrium |R_x - H| / H, worst step" + k,
                 worst_equilibrium,
                 std::max(1e-8, 1e-9 * kappa));
    if (stiffness == "tangent")
      check::in_range("Newton updates in the worst step" + k,
                      most,
                      1,
                      most_updates);
    std::cout << "  P/ubar = " << std::setprecision(12) << r.stiffness
              << " kN/m, " << r.curve.seconds << " s" << std::endl;
    return r;
  }

  /**
   * The stick/slip/open counts of every step and P/ubar of Newton against
   * the initial-stiffness iteration on the same scene.
   */
  void
  compare(const Run &newton, const Run &fixed, const std::string &kappa)
  {
    bool same_counts = true;
    for (unsigned int s = 0; s < 4; ++s)
      {
        const auto &a = newton.curve.steps[s], &b = fixed.curve.steps[s];
        std::cout << "  step " << s + 1 << " stick/slip/open " << a.stick << '/'
                  << a.slip << '/' << a.open << " (Newton) vs " << b.stick
                  << '/' << b.slip << '/' << b.open << " (initial stiffness)"
                  << std::endl;
        same_counts = same_counts && a.stick == b.stick && a.slip == b.slip &&
                      a.open == b.open;
      }
    check::that("kappa = " + kappa +
                  ": stick/slip/open counts of every step as the "
                  "initial-stiffness iteration",
                same_counts);
    check::relative("kappa = " + kappa +
                      ": P/ubar, Newton vs initial stiffness",
                    newton.stiffness,
                    fixed.stiffness,
                    1e-7);
  }
} // namespace

int
main()
{
  // Newton against the initial-stiffness iteration where both converge.
  // Newton at the initial-stiffness iteration's default N = 132, so that
  // both solve the same discrete problem.
  const Run k2 = run(1e2, "tangent", 5, 132);
  compare(k2, run(1e2, "initial", 0), "1e2");
  const Run k3 = run(1e3, "tangent", 6, 132);
  compare(k3, run(1e3, "initial", 0), "1e3");

  // Stiffer interfaces, and the penalty error: decade differences shrink
  // by about 10.
  const Run    k4 = run(1e4, "tangent", 50, 132);
  const Run    k5 = run(1e5, "tangent", 80, 132);
  const double d2 = k3.stiffness - k2.stiffness,
               d3 = k4.stiffness - k3.stiffness,
               d4 = k5.stiffness - k4.stiffness;
  check::in_range("(P(1e3) - P(1e2)) / (P(1e4) - P(1e3)) ~ 10 (1/kappa)",
                  d2 / d3,
                  5.,
                  20.);
  check::in_range("(P(1e4) - P(1e3)) / (P(1e5) - P(1e4)) ~ 10 (1/kappa)",
                  d3 / d4,
                  5.,
                  20.);
  std::cout << "  extrapolated P_inf = P(1e5) + (P(1e5) - P(1e4)) / 9 = "
            << std::setprecision(10) << k5.stiffness + d4 / 9. << " kN/m"
            << std::endl;

  // N = 2 n_max + 1 = 65 samples, one per degree of freedom of the
  // band-limited gap: springs above K's cap are solved by the augmented
  // Lagrangian on K's springs, and its fixed point is the penalty's: at
  // kappa = 1e3 (kn = 2e3 G / l, twice the cap) against the
  // initial-stiffness iteration with kn itself in K, to 1e-7 as above.
  const Run s3 = run(1e3, "tangent", 10, 65);
  compare(s3, run(1e3, "initial", 0, 65), "1e3, N = 65");
  // At kappa = 1e4 ... 1e6: at most 10 Newton updates a step over all
  // multiplier updates (measured 7), with the 1/kappa error (decade ratio
  // measured 9.998).
  const Run s4 = run(1e4, "tangent", 10, 65);
  const Run s5 = run(1e5, "tangent", 10, 65);
  const Run s6 = run(1e6, "tangent", 10, 65);
  check::in_range("N = 65: (P(1e5) - P(1e4)) / (P(1e6) - P(1e5)) ~ 10",
                  (s5.stiffness - s4.stiffness) / (s6.stiffness - s5.stiffness),
                  5.,
                  20.);

  // Newton's default N is 2 n_max + 1: the stiff case with Theta samples
  // left at 0 is the N = 65 run, to the bit, in at most 10 updates a step.
  const Run by_default = run(1e5, "tangent", 10, 0);
  check::relative("kappa = 1e5, default Theta samples: P/ubar as with N = 65",
                  by_default.stiffness,
                  s5.stiffness,
                  0.);
  return check::summary();
}
