// Stiff coulomb penalties run at any kn and tend to exact contact like
// 1/kappa (doc/nonlinear-interfaces.md sections 5b, 5d): the free-head
// rigid pile of prm/pile-free-head.prm (d = 1 m, L = 10 m, G = 3000 kPa,
// nu = 0.49) in elastic soil, no initial stress, its shaft a tensionless
// coulomb law, phi = 20, c = 0, kn = ks = kappa G / l (l = 10 m / 12 the
// face length, G / l = 3600 kPa/m), harmonics n = 0..4 with Theta samples
// = 9 = 2 n_max + 1, Newton, Interfaces/Nonlinear integration = nodal (one
// sample per node: the samples do not outnumber the displacements), pushed
// to u = 0.02 m in 2 steps. Above K's cap of 1e3 G / l the law is solved by
// the augmented Lagrangian on K's springs with its own kn, ks in the
// multipliers; before, Newton iterated on the stiff law and cycled between
// stick and slip here at kappa = 1e5 and 1e6 (3.5 min of step cuts each).
//  (1) every run converges both steps, with at most 10 multiplier updates
//      (measured 3-4) and 300 Newton iterations (measured 80 at most) a
//      step.
//  (2) the 1/kappa law: C(kappa) = (H_c - H(kappa)) kappa / H_c, H_c the
//      `contact` run, is one constant: C(1e4) and C(1e6), both augmented,
//      agree to 1e-3 relative (measured 2.6e-4); the plain penalty at
//      kappa = 500 (below the cap: no multipliers, K holds kn) agrees with
//      C(1e6) to 1e-2 (measured 5.4e-3, its own 1/kappa^2 term: C moves by
//      2.5e-3 between kappa = 500 and 1e3). A fixed point of the multipliers
//      other than the penalty's would show as a C that drifts with kappa.
//      Every run ends with contact's stick/slip/open set, 33/132/159.
//  (3) kappa = 1e8 and 1e10: H within 1e-7 of contact (measured 2.3e-8 and
//      2.9e-10): the 1/kappa term C / kappa is 2.3e-8 at 1e8 and 2.3e-10
//      at 1e10, and what the multiplier updates leave (they stop on the
//      force test, Tolerance 1e-8 of the force scale) is below that here;
//      1e-7 is four times the larger.
//  (4) homogeneity at kappa = 1e6: H(0.02 m) = 2 H(0.01 m) to 1e-6 (c = 0,
//      no initial stress, elastic soil: the problem is positively
//      homogeneous; the same tolerance and reason as for contact in
//      interface_contact_free_head_pile).
#include "check.h"
#include "coupled_interface_test_support.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

using namespace FourierSSI;

namespace
{
  struct Run
  {
    std::vector<double>         H;
    std::array<unsigned int, 3> states = {{0, 0, 0}};
  };

  /** The scene with `law` on the shaft, (1) checked. */
  Run
  run(const std::string &law)
  {
    std::cout << law << std::endl;
    test_support::FactorizedScene scene_(
      coupled_test::free_head_pile(law, "nodal"));
    CoupledSolver solver(scene_.set, scene_.parameters);
    coupled_test::run_with_log(solver);
    Run r;
    for (const LoadStepResult &s : solver.get_steps())
      {
        r.H.push_back(solver.applied_loads(s.load_factor)[0]);
        check::in_range("multiplier updates in a step",
                        s.multiplier_updates,
                        0,
                        10);
        check::in_range("Newton iterations in a step", s.iterations, 0, 300);
      }
    check::that("2 steps converged (" + law + ")", r.H.size() == 2);
    for (const ContactState s : solver.get_steps().back().interface_state.state)
      ++r.states[static_cast<int>(s)];
    std::cout << "  H = " << std::setprecision(12) << r.H.back()
              << " kN, stick/slip/open " << r.states[0] << '/' << r.states[1]
              << '/' << r.states[2] << std::endl;
    return r;
  }

  /** C(kappa) = (H_c - H(kappa)) kappa / H_c at the last step. */
  double
  coefficient(const Run &exact, const Run &stiff, const double kappa)
  {
    const double C = (exact.H[1] - stiff.H[1]) * kappa / exact.H[1];
    std::cout << "  C(" << kappa << ") = " << std::setprecision(8) << C
              << std::endl;
    return C;
  }
} // namespace

int
main()
{
  // (1) every run converges.
  const Run exact = run("contact, phi=20");
  const Run plain = run(coupled_test::free_head_pile_penalty(500.));
  const Run k4    = run(coupled_test::free_head_pile_penalty(1e4)),
            k6    = run(coupled_test::free_head_pile_penalty(1e6));
  const Run k8    = run(coupled_test::free_head_pile_penalty(1e8)),
            k10   = run(coupled_test::free_head_pile_penalty(1e10));

  // (2) the 1/kappa law, one contact set.
  for (const Run *r : {&plain, &k4, &k6, &k8, &k10})
    check::that("stick/slip/open at the last step as contact's",
                r->states == exact.states);
  const double C6 = coefficient(exact, k6, 1e6);
  check::relative("C(1e4) vs C(1e6)", coefficient(exact, k4, 1e4), C6, 1e-3);
  check::relative("C(500), the plain penalty, vs C(1e6)",
                  coefficient(exact, plain, 500.),
                  C6,
                  1e-2);

  // (3) very stiff penalties are contact.
  check::relative("kappa = 1e8: H vs contact", k8.H[1], exact.H[1], 1e-7);
  check::relative("kappa = 1e10: H vs contact", k10.H[1], exact.H[1], 1e-7);

  // (4) homogeneity.
  check::relative("kappa = 1e6: H(0.02 m) = 2 H(0.01 m)",
                  k6.H[1],
                  2. * k6.H[0],
                  1e-6);
  return check::summary();
}
