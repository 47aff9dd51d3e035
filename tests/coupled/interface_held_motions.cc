// Rigid foundation/Held motions through nonlinear interfaces on elastic
// soil, where the interface solver runs (doc/nonlinear-interfaces.md): the
// free-head rigid pile of prm/pile-free-head.prm (d = 1 m, L = 10 m, G =
// 3000 kPa, nu = 0.49) in soil that stays elastic (no Soil plasticity),
// n = 0 and 1, its shaft a coulomb interface (c = 5 kPa, phi = 0,
// tensionless, kn = ks = 1e5 kPa/m: it slips and a gap opens behind the
// pile), pushed to u = 0.01 m at the head in 4 steps with its rotation held.
// The checks and their reasons: tests/support/held_rotation_check.h (the
// held rotation stays 0, the holding moment and H balance the far
// supports). The interface's part of G (NonlinearInterfacePoints::
// spring_plastic, the nodal force of its tractions) is the only nonlinear
// load. Measured: the holding moment 5262.00 kN m against the supports'
// within 1.7e-9 of H L (the condensed Newton's tolerance); with the
// interface's part left out it reads -70 483 kN m.
#include "coupled_interface_test_support.h"
#include "held_rotation_check.h"

using namespace FourierSSI;

int
main()
{
  const std::string text =
    test_support::bundled_prm(
      "prm/pile-free-head.prm",
      {{"Harmonics", "0, 1"},
       {"Laws", ""},
       {"Interfaces", "5: coulomb, kn=1e5, ks=1e5, c=5, phi=0, sigma_t=0"},
       {"Target", "0.01"},
       {"Load steps", "4"},
       {"Soil reaction depths", ""}}) +
    test_support::entries("Rigid foundation", {{"Held motions", "rotation"}}) +
    test_support::entries("Load path", {{"Stiffness", "tangent"}});
  test_support::FactorizedScene scene(text);
  CoupledSolver                 solver(scene.set, scene.parameters);
  solver.run(std::cout);
  const auto &last = solver.get_steps().back();
  check::in_range("samples slipping or open at the last step",
                  last.contact[1] + last.contact[2],
                  1u,
                  100000u);
  held_rotation::check("pile, coulomb shaft, elastic soil",
                       solver,
                       scene.set,
                       10.);
  return check::summary();
}
