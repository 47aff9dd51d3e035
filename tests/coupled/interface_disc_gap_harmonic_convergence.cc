// Convergence of the tensionless disc's stiffness P/ubar in the number of
// harmonics (doc/nonlinear-interfaces.md section 7).
// prm/disc-gap.prm (rigid disc in an elastic ring, plane strain, c = 0,
// sigma_t = 0, no initial stress: positively homogeneous, so one load step
// gives P/ubar), harmonics n = 0..n_max for n_max = 2, 4, 8, 16, 32, all
// with the same N = 132 theta samples (alias-free up to n_max = 65), so that
// only the harmonics change: with the automatic N = 4 (n_max + 1) the
// contact arc is quantized differently at every n_max and the sequence is
// not monotone (measured: rate -3.6 at the last doubling). Frictionless
// and Coulomb mu = 0.3. The gap makes the contact pressure a non-smooth
// function of theta, so its Fourier series converges algebraically and
// P/ubar with it. Checked:
//  * the relative changes d_k = |P(2^(k+1)) - P(2^k)| / P(32) shrink at
//    every doubling, and the observed rate log2(d_k / d_(k+1)) at the last
//    doubling is >= 1 (measured, at the three doublings: 3.0, 3.1, 3.2
//    frictionless, i.e. P/ubar converges like n_max^-3; 3.4, 2.1, 4.1 with
//    Coulomb friction, whose stick/slip boundary is also quantized by the
//    samples);
//  * the last change (n_max 16 -> 32) is below 1e-3 of P (measured 7e-6 and
//    1e-5);
//  * at every n_max the frictionless disc stays below the linear bilateral
//    smooth one (kn, ks = 0) and the Coulomb disc between the frictionless
//    and the linear bilateral bonded one (kn = ks): the physical bounds of a
//    tensionless, frictional interface.
#include "check.h"
#include "coupled_interface_test_support.h"

#include <cmath>

using namespace FourierSSI;
using test_support::with_entry;

namespace
{
  const std::vector<unsigned int> n_max         = {2, 4, 8, 16, 32};
  const unsigned int              theta_samples = 132;

  std::vector<double>
  stiffness_by_harmonics(const std::string &law)
  {
    std::string text = test_support::bundled_prm("prm/disc-gap.prm");
    text             = with_entry(text, "Interfaces", law);
    text             = with_entry(text, "Load steps", "1");
    text             = with_entry(text, "Target", "1e-3");
    // One theta sampling for every n_max, so that only the harmonics change.
    text += "subsection Load path\n  set Theta samples = " +
            std::to_string(theta_samples) + "\nend\n";
    std::vector<double> result;
    for (const unsigned int top : n_max)
      {
        std::string list = "0";
        for (unsigned int n = 1; n <= top; ++n)
          list += ", " + std::to_string(n);
        std::ostringstream        log;
        const coupled_test::Curve c =
          coupled_test::run(with_entry(text, "Harmonics", list), log);
        result.push_back(c.steps.back().H / c.steps.back().u);
        std::cout << "  " << law << ": n_max " << top << ": P/ubar "
                  << std::setprecision(10) << result.back() << " kN/m, "
                  << c.steps.back().iterations << " iterations, "
                  << c.steps.back().open << " open samples" << std::endl;
      }
    return result;
  }

  void
  check_convergence(const std::string &name, const std::vector<double> &P)
  {
    std::vector<double> d;
    for (unsigned int k = 0; k + 1 < P.size(); ++k)
      d.push_back(std::abs(P[k + 1] - P[k]) / P.back());
    for (unsigned int k = 0; k + 1 < d.size(); ++k)
      {
        const double rate = std::log2(d[k] / d[k + 1]);
        std::cout << "  " << name << ": change " << n_max[k] << "->"
                  << n_max[k + 1] << " " << d[k] << ", " << n_max[k + 1] << "->"
                  << n_max[k + 2] << " " << d[k + 1] << ", observed rate "
                  << rate << std::endl;
        check::that(name + ": the change shrinks at doubling " +
                      std::to_string(k + 1),
                    d[k + 1] < d[k]);
        if (k + 2 >= d.size())
          check::in_range(name + ": observed rate of the last doubling",
                          rate,
                          1.,
                          1e3);
      }
    check::small(name + ": relative change n_max 16 -> 32", d.back(), 1e-3);
  }
} // namespace

int
main()
{
  const std::vector<double> frictionless =
    stiffness_by_harmonics("5: coulomb, kn=1e6, ks=1e6, c=0, phi=0");
  const std::vector<double> coulomb =
    stiffness_by_harmonics("5: coulomb, kn=1e6, ks=1e6, c=0, phi=16.69924423");
  check_convergence("frictionless", frictionless);
  check_convergence("Coulomb mu = 0.3", coulomb);
  const std::string disc = test_support::bundled_prm("prm/disc-gap.prm");
  const double      smooth =
    coupled_test::linear_lateral_slope(disc, "5: kn=1e6, ks=0");
  const double bonded =
    coupled_test::linear_lateral_slope(disc, "5: kn=1e6, ks=1e6");
  for (unsigned int k = 0; k < n_max.size(); ++k)
    {
      check::in_range("frictionless below bilateral smooth, n_max " +
                        std::to_string(n_max[k]),
                      frictionless[k],
                      0.,
                      smooth);
      check::in_range("Coulomb between frictionless and bilateral bonded, "
                      "n_max " +
                        std::to_string(n_max[k]),
                      coulomb[k],
                      frictionless[k],
                      bonded);
    }
  return check::summary();
}
