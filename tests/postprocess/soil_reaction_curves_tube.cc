// Soil-reaction curves of a hollow, flexible pile (requirement: PISA curves
// for the monopile, a tube whose wall is an elastic material region and
// whose loads arrive through a tied ring on its head; doc/soil-reaction-
// curves.md section 8): the scene of prm/monopile-clay-lateral.prm (D = 9 m,
// t = 0.11 m, L = 42 m, steel wall, clay plug bonded to both faces) on a very
// coarse mesh, n <= 1, the clay elastic in practice (s_u = 1e6 kPa), pushed
// at the mudline in 2 steps to 0.001 D.
// Checks, with their reasons:
//  1. equilibrium of the pile (wall and ring) at every step, p and m from
//     both faces integrated by Gauss quadrature of the recovered fields:
//       int p dz + H_B = H,
//       int (m + p (z - z_ref)) dz + M_B + H_B (z_toe - z_ref) = M_ref;
//     the wall's internal forces do no work on a rigid mode, so the
//     imbalance is the rigid-body part of the converged residual (|R| <=
//     1e-10 |lambda F|) plus the round-off of the steel's stiffness forces,
//     eps k u per node with k = E (h / t) r (h the tallest wall cell);
//     bound: 10 x that over the pile's node components;
//  2. the plug reacts: the inner face carries more than 1e-3 |H|, so a
//     balance from the outer face alone misses it by far more than the
//     bound of 1 (the curves must take both faces);
//  3. v and psi are the wall section's (the flexible pile's own motion):
//     at the mudline the section lies on the tied ring, so v(0) = U_h and
//     psi(0) = Theta of the rigid motion to round-off; below, the wall
//     bends, so psi(toe) differs from Theta by more than 1e-3 of it.
#include "check.h"
#include "soil_reaction_test_support.h"

#include <deal.II/base/quadrature_lib.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/postprocess/soil_reaction_curves.h>
#include <iomanip>
#include <limits>

using namespace FourierSSI;
using namespace reaction_test;

namespace
{
  const double       E_steel = 2.1e8, wall = 0.11, radius = 4.5, length = 42.;
  const unsigned int cells_along = 4;

  std::string
  tube_scene()
  {
    return test_support::bundled_prm(
      "prm/monopile-clay-lateral.prm",
      {{"Harmonics", "0, 1"},
       {"R cells", "1, 1, 4"},
       {"R growth", "1, 1, 2"},
       {"Z cells", "1, " + std::to_string(cells_along) + ", 1"},
       {"Z growth", "1, 1, 1"},
       {"Laws", "0: tresca, su=1e6"},
       {"Theta samples", "8"},
       {"Target", "0.009"},
       {"Load steps", "2"}});
  }
} // namespace

int
main()
{
  soil_test::Run     run(tube_scene());
  const unsigned int h1 = lateral_harmonic(*run.set);
  SoilReactionCurves curves(run.set->problem(h1).get_dof_handler(),
                            run.parameters);
  check::that("the wall is a flexible pile", !curves.rigid());
  check::relative("inner radius r_i = R - t [m]",
                  curves.inner_radius(),
                  radius - wall,
                  1e-14);
  record_every_step(run, curves, h1);
  run.solver->run(std::cout);
  const auto &steps = run.solver->get_steps();
  check::equal("steps recorded", curves.n_steps(), steps.size());

  const double z_ref = 0., z_toe = -length;
  const double lever        = std::sqrt(radius * radius + length * length);
  const double pattern_norm = run.set->problem(h1).get_system_rhs().l2_norm();
  // The steel's stiffness per node, E (h / t) r, and the pile's node
  // components: 3 per node on both faces and the tip, FE_Q(2).
  const double wall_stiffness =
    E_steel * (length / cells_along) / wall * radius;
  const double node_components = 3. * (2. * (2 * cells_along + 1) + 3.);
  std::cout << std::setprecision(10);
  for (unsigned int s = 0; s < steps.size(); ++s)
    {
      const auto   loads = run.solver->applied_loads(steps[s].load_factor);
      const double H     = loads[0];
      const double M_ref =
        moment_about_reference(loads, run.parameters.rigid_foundation);
      const Resultant r       = resultant_at(curves, s, z_ref, z_toe);
      const double    shaft_H = r.shaft_H, H_B = r.base_H;
      const double    M_total = r.total_M;
      const double    outer_H = over_shaft(curves, [&](double z) {
        return curves.outer_face_reaction(s, z).first;
      });
      const double    u_max   = std::abs(curves.displacement(s, 0.)) +
                           std::abs(curves.displacement(s, z_toe));
      const double bound =
        steps[s].residual * steps[s].load_factor * pattern_norm +
        10. * std::numeric_limits<double>::epsilon() * wall_stiffness * u_max *
          node_components;
      const std::string at = " at step " + std::to_string(s + 1);
      std::cout << "step " << s + 1 << ": H = " << H
                << " kN, int p dz = " << shaft_H << " kN (outer face "
                << outer_H << ", inner face " << shaft_H - outer_H
                << "), H_B = " << H_B << " kN; imbalance H "
                << shaft_H + H_B - H << " kN, M " << M_total - M_ref
                << " kN m; bound " << bound << " kN" << std::endl;
      // 1. Both balances.
      check::small("|int p dz + H_B - H| [kN]" + at,
                   std::abs(shaft_H + H_B - H),
                   bound);
      check::small("|int (m + p (z - z_ref)) dz + M_B + H_B (z_toe - "
                   "z_ref) - M_ref| [kN m]" +
                     at,
                   std::abs(M_total - M_ref),
                   bound * lever);
      // 2. The plug's share is far above the balance's bound.
      check::that("the inner face (the plug) carries > 1e-3 |H|" + at,
                  std::abs(shaft_H - outer_H) > 1e-3 * std::abs(H));
      check::that("the outer face alone does not balance H" + at,
                  std::abs(outer_H + H_B - H) > 1e3 * bound);
      // 3. The section's motion: on the ring at the mudline, bent below.
      const RigidMotion &motion = steps[s].motion;
      check::small("|v(0) - U_h| [m]" + at,
                   std::abs(curves.displacement(s, 0.) -
                            motion.horizontal_displacement),
                   1e-12 * std::abs(motion.horizontal_displacement));
      check::small("|psi(0) - Theta| [rad]" + at,
                   std::abs(curves.rotation(s, 0.) - motion.rotation),
                   1e-12 * std::abs(motion.horizontal_displacement) / radius);
      check::that("psi(toe) differs from Theta by > 1e-3 Theta" + at,
                  std::abs(curves.rotation(s, z_toe) - motion.rotation) >
                    1e-3 * std::abs(motion.rotation));
    }
  return check::summary();
}
