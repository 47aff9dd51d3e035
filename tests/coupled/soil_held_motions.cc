// Rigid foundation/Held motions with plastic soil: the pure-H probe (the
// rotation held at zero, the footing pushed sideways by displacement
// control) on the rough footing on Tresca soil (prm/footing-capacity.prm,
// a = 1 m, s_u = 10 kPa, G = 3000 kPa; the coarse mesh of
// soil_footing_held_loads, n = 0 and 1, 8 theta samples), to u = 0.01 m
// (about 5 elastic yield displacements) in 4 steps. Checks, with reasons:
//  1. the held rotation is zero to the bit at every step (its master DoF
//     is constrained: V_A = 0) while u reaches the target;
//  2. the moment that holds the rotation, read on the foundation (virtual
//     work of K u - G(u) on the unit rotation, RigidFoundation::
//     held_reactions), balances the moment of the support reactions read
//     on the far boundaries (K u there: no plastic point reaches a support,
//     so G = 0 at their DoFs), two different sets of DoFs. Equilibrium
//     holds to the iteration's tolerance (|R| <= 1e-8 |F|-scale): 1e-6
//     relative to H a leaves room for the round-off of the sums;
//  3. the support force balances the applied H the same way.
// A lost plastic load shows as a moment mismatch of the size of the
// plastic part: with G left out the holding moment reads -28.9 kN m
// against the supports' 3.39 kN m (measured).
// The same checks on the free-head rigid pile of prm/pile-free-head.prm
// (n = 0, 1) with a nonlinear shaft interface, coulomb (c = 5 kPa,
// tensionless, kn = ks = 1e5 kPa/m) and exact contact (smooth,
// tensionless: a gap opens behind the pile): the interface's part of G
// (NonlinearInterfacePoints::spring_plastic, the nodal force of its
// tractions) enters the holding moment as the soil's does. Measured
// 1.8e-14 and 1.4e-12; with the interface's part left out the holding
// moment reads -88 023 and -3 024 523 kN m against the supports' 3111 and
// 3144 kN m.
#include "soil_test_support.h"

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  /**
   * Checks 1-3 on a run whose rigid foundation is pushed sideways to
   * u = 0.01 m with its rotation held; `size` [m] scales the moment
   * tolerance (H size).
   */
  void
  check_held_rotation(const std::string &name, Run &run, const double size)
  {
    run.solver->run(std::cout);
    const auto &steps = run.solver->get_steps();
    // Step cuts may add steps; every one holds the rotation.
    for (unsigned int k = 0; k < steps.size(); ++k)
      check::small(name + ": rotation held (step " + std::to_string(k + 1) +
                     ")",
                   steps[k].motion.rotation,
                   0.);
    check::relative(name + ": u at the target",
                    steps.back().motion.horizontal_displacement,
                    0.01,
                    1e-12);
    // The last step: support reactions of the n = 1 harmonic.
    unsigned int lateral = 0;
    for (unsigned int h = 0; h < run.set->size(); ++h)
      if (run.set->harmonic(h).n == 1)
        lateral = h;
    const HarmonicProblem &problem = run.set->problem(lateral);
    const SoilStepResult  &last    = steps.back();
    const double           H = run.solver->applied_loads(last.load_factor)[0];
    const Vector<double>   forces =
      problem.nodal_forces(run.solver->solution(lateral), last.load_factor);
    double support_force = 0., support_moment = 0.;
    for (const types::boundary_id id : {1, 2})
      {
        const BoundaryResultant R = problem.boundary_resultant(id, forces);
        support_force += R.force;
        support_moment += R.moment;
      }
    check::equal(name + ": one held reaction", last.held_reactions.size(), 1);
    if (last.held_reactions.empty())
      return;
    const double M_hold = last.held_reactions.front().second;
    std::cout << "  " << name << ": H " << H << " kN at u = 0.01 m, holding M "
              << M_hold << " kN m, support moment " << support_moment << " kN m"
              << std::endl;
    check::relative(name + ": support moment vs -holding M",
                    support_moment,
                    -M_hold,
                    1e-6,
                    std::abs(H) * size);
    check::relative(name + ": support force vs -H", support_force, -H, 1e-6);
  }

  /**
   * The free-head rigid pile of prm/pile-free-head.prm (d = 1 m, L = 10 m,
   * Tresca s_u = 10 kPa) with `law` on its shaft, n = 0 and 1, pushed to
   * u = 0.01 m at the head in 4 steps with its rotation held.
   */
  std::string
  pile_with_shaft(const std::string &law)
  {
    return test_support::bundled_prm("prm/pile-free-head.prm",
                                     {{"Harmonics", "0, 1"},
                                      {"Theta samples", "8"},
                                      {"Interfaces", "5: " + law},
                                      {"Target", "0.01"},
                                      {"Load steps", "4"},
                                      {"Soil reaction depths", ""}}) +
           test_support::entries("Rigid foundation",
                                 {{"Held motions", "rotation"}});
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The footing's entries changed in place; the new ones appended.
  Run footing(scene(joined(footing_mesh(true),
                           {{"Harmonics", "0, 1"},
                            {"Vertical force", "0"},
                            {"Capacity normalisation", ""},
                            {"Theta samples", "8"},
                            {"Controlled motion", "horizontal"},
                            {"Target", "0.01"},
                            {"Load steps", "4"}})) +
              "subsection Rigid foundation\n"
              "  set Horizontal force = 1\n"
              "  set Held motions     = rotation\n"
              "end\n");
  check_held_rotation("footing", footing, 1.);
  // The holding moment through a nonlinear shaft interface: its tractions'
  // part of G (NonlinearInterfacePoints::spring_plastic) enters the
  // foundation's internal force as the soil's does.
  Run slipping(
    pile_with_shaft("coulomb, kn=1e5, ks=1e5, c=5, phi=0, sigma_t=0"));
  check_held_rotation("pile, coulomb shaft", slipping, 10.);
  Run gapping(pile_with_shaft("contact, phi=0"));
  check_held_rotation("pile, contact shaft", gapping, 10.);
  return check::summary();
}
