// The pure-H probe's checks (Rigid foundation/Held motions = rotation, the
// foundation pushed sideways to u = 0.01 m by displacement control), shared
// by the coupled solvers' tests:
//  1. the held rotation is zero to the bit at every step (its master DoF is
//     constrained) while u reaches the target;
//  2. the moment that holds the rotation, read on the foundation (virtual
//     work of K u - G(u) on the unit rotation, LoadControl::
//     held_reactions), balances the moment of the support reactions read
//     on the far boundaries 1 and 2 (K u there: no nonlinear source reaches
//     a support, so G = 0 at their DoFs), two different sets of DoFs.
//     Equilibrium holds to the iteration's tolerance (|R| <= 1e-8 of the
//     force scale): 1e-6 relative to H times the foundation's size leaves
//     room for the round-off of the sums;
//  3. the support force balances the applied H the same way.
#ifndef fourier_ssi_tests_held_rotation_check_h
#define fourier_ssi_tests_held_rotation_check_h

#include "check.h"

#include <fourier_ssi/harmonic/harmonic_set.h>
#include <iostream>
#include <string>

namespace held_rotation
{
  using namespace FourierSSI;

  /** Checks 1-3 on a solver that has run; `size` [m] scales the moment. */
  template <class Solver>
  void
  check(const std::string &name,
        const Solver      &solver,
        const HarmonicSet &set,
        const double       size)
  {
    const auto &steps = solver.get_steps();
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
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.harmonic(h).n == 1)
        lateral = h;
    const HarmonicProblem &problem = set.problem(lateral);
    const auto            &last    = steps.back();
    const double           H       = solver.applied_loads(last.load_factor)[0];
    const Vector<double>   forces =
      problem.nodal_forces(solver.solution(lateral), last.load_factor);
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
} // namespace held_rotation

#endif
