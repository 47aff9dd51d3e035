// A frictional tensionless shaft under the plastic soil's Newton
// (doc/soil-plasticity.md section 3b, doc/nonlinear-interfaces.md section
// 5d): the free-head rigid pile of prm/pile-free-head.prm (d = 1 m, L = 10 m,
// G = 3000 kPa, nu = 0.49), n = 0 and 1, its shaft coulomb with c = 0,
// phi = 20 deg, tensionless, kn = ks = 1e10 kPa/m (2.8e6 G / l: through the
// augmented Lagrangian's multipliers on 2 n_max + 1 = 3 samples), pushed
// sideways at the head. From the elastic start the contact states of the 3
// samples per shaft point chatter (stick, slip, open) and Newton finds no
// descent; the problem is homogeneous in the load, so a cut step chatters
// the same. Before, the step failed after every cut. Now the retry after
// the last cut (LoadPath, retry_persistently) takes an initial-stiffness
// update where Newton finds no descent, as the interfaces' condensed Newton
// does. Maximum step cuts = 0 here: the retry at once.
//  (1) Soil that never yields (Tresca s_u = 1e6 kPa), 2 steps to 0.005 m:
//      the coupled-tangent Newton against the condensed interface Newton
//      (CoupledSolver, Stiffness = tangent, the same 3 samples),
//      an independent linearisation and iteration of the same equations:
//      H at each step to 1e-7 (both stop at |R| <= 1e-8 of their force
//      scale; measured 1.2e-12), and the same stick/slip/open counts.
//  (2) Tresca s_u = 10 kPa, 4 steps to 0.004 m (the soil yields from
//      about 0.0015 m): every step converges, in equilibrium and on or
//      inside Tresca (soil_test::check_equilibrium_and_yield), and H at
//      0.004 m lies below the never-yielding soil's (plastic flow only
//      softens; the elastic H there is 0.8 x 126.238 kN, linear;
//      measured 0.942 of it).
#include "coupled_interface_test_support.h"
#include "soil_test_support.h"

#include <iomanip>

using namespace FourierSSI;

namespace
{
  const std::string shaft = "coulomb, kn=1e10, ks=1e10, c=0, phi=20, "
                            "sigma_t=0";

  struct Curve
  {
    std::vector<double>                      H;
    std::vector<std::array<unsigned int, 3>> states;
  };

  Curve
  soil_run(const std::string &name,
           const std::string &su,
           const std::string &target,
           const std::string &steps)
  {
    std::cout << name << std::endl;
    soil_test::Run pile(
      soil_test::free_head_pile(shaft,
                                {{"Laws", "0: tresca, su=" + su},
                                 {"Target", target},
                                 {"Load steps", steps}}) +
      "subsection Load path\n  set Maximum step cuts = 0\nend\n");
    pile.solver->run(std::cout);
    const std::vector<LoadStepResult> &result = pile.solver->get_steps();
    check::equal(name + ": steps",
                 result.size(),
                 std::size_t(std::stoi(steps)));
    soil_test::check_equilibrium_and_yield(name, result, std::stod(su));
    Curve c;
    for (const LoadStepResult &s : result)
      {
        c.H.push_back(pile.solver->applied_loads(s.load_factor)[0]);
        c.states.push_back(s.contact);
      }
    return c;
  }

  Curve
  interface_run()
  {
    std::cout << "condensed interface Newton, elastic soil" << std::endl;
    std::string text = test_support::bundled_prm("prm/pile-free-head.prm",
                                                 {{"Harmonics", "0, 1"},
                                                  {"Laws", ""},
                                                  {"Soil reaction depths", ""},
                                                  {"Interfaces", "5: " + shaft},
                                                  {"Theta samples", "3"},
                                                  {"Load steps", "2"},
                                                  {"Target", "0.005"}});
    text += "subsection Load path\n  set Stiffness = tangent\nend\n";
    const coupled_test::StepResults r = coupled_test::solve_steps(text);
    Curve                           c;
    for (unsigned int s = 0; s < r.steps.size(); ++s)
      {
        c.H.push_back(r.applied[s]);
        c.states.push_back(r.steps[s].contact);
      }
    return c;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // (1)
  const Curve soil      = soil_run("soil never yields", "1e6", "0.005", "2");
  const Curve condensed = interface_run();
  check::equal("(1) steps of the condensed Newton",
               condensed.H.size(),
               std::size_t(2));
  for (unsigned int s = 0; s < std::min(soil.H.size(), condensed.H.size()); ++s)
    {
      const std::string step = "(1) step " + std::to_string(s + 1);
      std::cout << step << ": H " << std::setprecision(12) << soil.H[s]
                << " vs " << condensed.H[s] << " kN" << std::endl;
      check::relative(step + ": H, coupled tangent vs condensed",
                      soil.H[s],
                      condensed.H[s],
                      1e-7);
      for (unsigned int k = 0; k < 3; ++k)
        check::equal(step + ": stick/slip/open count " + std::to_string(k),
                     soil.states[s][k],
                     condensed.states[s][k]);
    }
  // (2)
  const Curve plastic = soil_run("Tresca s_u = 10 kPa", "10", "0.004", "4");
  if (!plastic.H.empty() && !soil.H.empty())
    check::in_range("(2) H at 0.004 m over the never-yielding soil's",
                    plastic.H.back() / (0.8 * soil.H.back()),
                    0.5,
                    1. - 1e-6);
  return check::summary();
}
