// Requirement "loads mean what the documentation says", plastic soil: with a
// Rigid foundation, the Body force and the tractions are held loads, applied
// in full by the held stage (Load path/Held load steps) and then
// constant while the load factor scales only the foundation's loads or
// motion (CoupledSolver::solve_loads, run_stage; held_stage_load).
// Checks, with their reasons:
//  1. The lateral capacity of the rigid pile in the plane-strain Tresca slice
//     (prm/pile-capacity.prm, N_p = H / (s_u d L)) with the soil's and the
//     pile's self-weight (gamma = 18 kN/m^3, Body force/Axial = -18 in n = 0)
//     equals the capacity without it: the collapse mechanism flows in
//     horizontal planes, so the weight does no work on it, and Tresca strength
//     does not depend on pressure (the elastic weight stresses between the
//     smooth rigid planes, (1 - 2 nu) / (1 - nu) gamma z <= 3.5 kPa, keep
//     sigma_z the intermediate principal stress). Tolerance: the two plateau
//     error bars (capacity_plateau.h, the rise still to come at the end of each
//     curve) added. Scaling the weight with H (the old behaviour) gave
//     N_p = 8.39 instead of 9.2.
//  2. Support reactions of the footing of prm/footing-capacity.prm (coarse
//     mesh, Tresca, s_u = 10 kPa) with its self-weight (gamma = 18 kN/m^3)
//     and a surcharge q = 5 kPa on the surface around the footing: the
//     vertical reactions of the far side and the bottom balance the held
//     weight and surcharge plus the scaled V, W + Q + lambda V, computed
//     here from the geometry. The reactions are K u - f on the support
//     DoFs (HarmonicProblem::nodal_reactions); the cells there stay elastic
//     (the plastic zone of the footing reaches about 2 a of the 5 m mesh),
//     so they are the internal forces exactly. Two states: one loading step
//     (w = -4 mm; the held loads alone settle the footing 2.1 mm) and the
//     plateau (w = -40 mm). Tolerance 1e-8 of W: the iteration
//     tolerance is 1e-10 of the load, and the reactions sum the residuals
//     of the support DoFs' neighbours.
#include "soil_test_support.h"

#include <fourier_ssi/estimation/capacity_plateau.h>
#include <iomanip>

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  struct Capacity
  {
    double H = 0., plateau_error = 0.;
  };

  /** H at the end of the pile's curve and its plateau error bar. */
  Capacity
  pile_capacity(const std::string &body_force)
  {
    std::string text = test_support::bundled_prm("prm/pile-capacity.prm");
    text += "subsection Body force\n  set Axial = " + body_force + "\nend\n";
    Run run(text);
    run.solver->run(std::cout);
    const auto         &steps = run.solver->get_steps();
    std::vector<double> motion, load;
    for (const LoadStepResult &s : steps)
      if (s.load_factor != 0.)
        {
          motion.push_back(s.motion.horizontal_displacement);
          load.push_back(
            run.solver->applied_loads(s.load_factor, s.held_fraction)[0]);
        }
    check_equilibrium_and_yield("Axial body force " + body_force + ": ",
                                steps,
                                10.);
    return {load.back(), plateau_error(motion, load)};
  }

  /** Vertical support reactions against the held and scaled loads. */
  void
  footing_reactions(const std::string &target, const std::string &steps)
  {
    const double gamma = 18., q = 5., a = 1., R = 5., D = 5.;
    std::string  text = scene(joined(
      {{"Target", target}, {"Load steps", steps}, {"Tolerance", "1e-10"}},
      footing_mesh(true)));
    text += "subsection Load path\n  set Held load steps = 2\nend\n"
            "subsection Boundary conditions\n  set Traction = 3: z=-5\nend\n"
            "subsection Body force\n  set Axial = -18\nend\n";
    Run run(text);
    run.solver->run(std::cout);
    const LoadStepResult &last    = run.solver->get_steps().back();
    HarmonicProblem      &problem = run.set->problem(0);
    problem.set_solution(run.solver->solution(0));
    const Vector<double> reactions = problem.nodal_reactions();
    const double supports = problem.boundary_resultant(1, reactions).force +
                            problem.boundary_resultant(2, reactions).force;
    const double weight    = -gamma * numbers::PI * R * R * D;
    const double surcharge = -q * numbers::PI * (R * R - a * a);
    const double V =
      run.solver->applied_loads(last.load_factor, last.held_fraction)[2];
    std::cout << std::setprecision(10)
              << "  w = " << last.motion.vertical_displacement
              << " m: V = " << V << " kN, W = " << weight
              << " kN, Q = " << surcharge << " kN; support reactions "
              << supports << " kN" << std::endl;
    check::relative("held fraction at the end", last.held_fraction, 1., 0.);
    check::small("|support reactions + W + Q + lambda V| / |W| at w = " +
                   target,
                 std::abs(supports + weight + surcharge + V) / std::abs(weight),
                 1e-8);
  }
} // namespace

int
main()
{
  std::cout << "1. pile lateral capacity with and without self-weight"
            << std::endl;
  const Capacity without = pile_capacity("0");
  // n == 0: gravity is uniform in theta (the text applies to every harmonic
  // of the set, doc/loads.md).
  const Capacity with = pile_capacity("-18*(n==0)");
  std::cout << std::setprecision(8) << "  H_ult = " << without.H << " +- "
            << without.plateau_error << " kN without, " << with.H << " +- "
            << with.plateau_error << " kN with gamma = 18 kN/m^3" << std::endl;
  // Both curves on their plateau: a finite error bar below 1 % of H (as
  // the scene's own check of the plateau rise, pile-capacity.*.checks); an
  // infinite bar (a curve that does not bend over) would accept anything.
  for (const Capacity *c : {&without, &with})
    check::in_range("plateau error bar / H_ult",
                    c->plateau_error / std::abs(c->H),
                    0.,
                    0.01);
  const double bars = without.plateau_error + with.plateau_error;
  check::relative("H_ult with self-weight held vs without [kN]",
                  with.H,
                  without.H,
                  std::isfinite(bars) ? bars / without.H : 0.);

  std::cout << "2. footing: support reactions balance W + Q + lambda V"
            << std::endl;
  footing_reactions("-0.004", "1");
  footing_reactions("-0.04", "4");
  return check::summary();
}
