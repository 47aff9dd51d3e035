// The bundled scene prm/disc-gap.prm (a rigid disc pushed along x in an
// elastic ring, plane strain, tensionless interface, harmonics n = 0..8)
// and its Coulomb variant (mu = tan(phi) = 0.3), solved by the coupled
// iteration (doc/nonlinear-interfaces.md section 7):
//  * positive homogeneity: with c = 0, sigma_t = 0 and no initial stress the
//    law is positively homogeneous of degree 1, so P/ubar and the contact
//    arc are the same at every displacement step; checked to 1e-7 (the
//    force residual is converged to 1e-10 of the load; P/ubar is read from
//    the controlled motion, exact, and the load factor, accurate to the
//    residual times the condition of the slipping/opening mode);
//  * bounds: the tensionless frictionless disc is softer than the bilateral
//    smooth one (the linear law with the same kn and ks = 0) and the
//    Coulomb one lies between it and the bilateral bonded one (kn = ks);
//  * equilibrium: the interface tractions balance the applied H to 1e-8.
#include "check.h"
#include "coupled_interface_test_support.h"
#include "factorized_scene.h"

#include <fourier_ssi/coupled/coupled_solver.h>

using namespace FourierSSI;

namespace
{
  struct Curve
  {
    std::vector<double>       stiffness; // P / ubar [kN/m per m of thickness]
    std::vector<unsigned int> open, iterations;
    double                    worst_equilibrium = 0.;
  };

  std::string
  with_law(const std::string &law)
  {
    return test_support::bundled_prm("prm/disc-gap.prm", {{"Interfaces", law}});
  }

  Curve
  run(const std::string &text)
  {
    test_support::FactorizedScene scene(text);
    const AllParameters          &parameters = scene.parameters;
    HarmonicSet                  &set        = scene.set;
    CoupledSolver                 solver(set, parameters);
    solver.run(std::cout);
    Curve curve;
    for (const LoadStepResult &step : solver.get_steps())
      {
        const double H = solver.applied_loads(step.load_factor)[0];
        curve.stiffness.push_back(H / step.motion.horizontal_displacement);
        curve.open.push_back(step.contact[2]);
        curve.iterations.push_back(step.iterations);
        curve.worst_equilibrium =
          std::max(curve.worst_equilibrium,
                   std::abs(step.resultant[0] - H) / std::abs(H));
      }
    return curve;
  }

  void
  check_homogeneous(const std::string &name, const Curve &c)
  {
    double spread = 0.;
    for (const double k : c.stiffness)
      spread = std::max(spread, std::abs(k - c.stiffness[0]) / c.stiffness[0]);
    std::cout << "  " << name << ": P/ubar = " << c.stiffness.back()
              << " kN/m, open samples " << c.open.back() << ", iterations";
    for (const unsigned int i : c.iterations)
      std::cout << ' ' << i;
    std::cout << std::endl;
    check::small(name + ": max relative spread of P/ubar over the steps",
                 spread,
                 1e-7);
    check::that(name + ": the open arc is the same at every step",
                std::all_of(c.open.begin(),
                            c.open.end(),
                            [&](unsigned n) { return n == c.open[0]; }) &&
                  c.open[0] > 0);
    check::small(name + ": max |interface resultant - H| / H",
                 c.worst_equilibrium,
                 1e-8);
  }
} // namespace

int
main()
{
  const Curve frictionless = run(test_support::bundled_prm("prm/disc-gap.prm"));
  check_homogeneous("tensionless frictionless", frictionless);
  const Curve coulomb =
    run(with_law("5: coulomb, kn=1e6, ks=1e6, c=0, phi=16.69924423"));
  check_homogeneous("tensionless Coulomb mu = 0.3", coulomb);

  const double smooth = coupled_test::linear_lateral_slope(
    test_support::bundled_prm("prm/disc-gap.prm"), "5: kn=1e6, ks=0");
  const double bonded = coupled_test::linear_lateral_slope(
    test_support::bundled_prm("prm/disc-gap.prm"), "5: kn=1e6, ks=1e6");
  std::cout << "  linear bilateral: smooth " << smooth << ", bonded " << bonded
            << " kN/m" << std::endl;
  check::in_range("frictionless tensionless below bilateral smooth",
                  frictionless.stiffness.back(),
                  0.,
                  smooth);
  check::in_range("Coulomb mu = 0.3 between frictionless and bonded",
                  coulomb.stiffness.back(),
                  frictionless.stiffness.back(),
                  bonded);
  return check::summary();
}
