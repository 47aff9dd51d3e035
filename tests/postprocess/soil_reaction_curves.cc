// Soil-reaction curves of a rigid pile (requirement: what foundation
// engineers take away, the PISA curves; doc/soil-reaction-curves.md): the
// free-head pile of prm/pile-free-head.prm (rigid, d = 1 m, L = 10 m, Tresca
// clay s_u = 10 kPa) on a coarse mesh, pushed sideways by a force H applied
// 1 m above the ground (Reference elevation = 1: M_ref = 0 while the
// shaft's moment about z_ref is not), in 4 displacement-controlled steps
// into the plastic range; the shaft tied (exact constraints) and rough (the
// shipped penalty interface, kn = ks = 1e10 kPa/m).
// Checks, with their reasons:
//  1. equilibrium of the rigid pile at every step, with p and m integrated
//     over the shaft by Gauss quadrature of the recovered fields (not their
//     nodal sums):
//       int p dz + H_B = H,
//       int (m + p (z - z_ref)) dz + M_B + H_B (z_toe - z_ref) = M_ref;
//     the reactions are the soil's nodal forces, so the imbalance is the
//     rigid-body part of the converged residual, |R| <= residual x lambda
//     |F| (Tolerance 1e-10 here), plus round-off: 1e-12 H, and for the
//     penalty shaft its forces' k A eps |u| (A = pi R L; measured 2 x that,
//     bound 10 x); the moment's lever arm is at most the pile's extent
//     from the reference point. A reaction that missed a component (f_W),
//     the base or the corner's share would be off by per cents of H;
//  2. the curves are the ones of the load path: p opposes v near the head
//     and near the toe (v changes sign along a rotating rigid pile) and
//     grows along the path near the head; head and toe move opposite ways;
//  3. the depths 'auto 4' are the middles of four equal parts.
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
  std::string
  pile_scene(const std::string &shaft)
  {
    return test_support::bundled_prm("prm/pile-free-head.prm",
                                     {{"Harmonics", "0, 1"},
                                      {"R cells", "1, 8"},
                                      {"R growth", "1, 1.4"},
                                      {"Z cells", "2, 6"},
                                      {"Reference elevation", "1"},
                                      {"Theta samples", "8"},
                                      {"Target", "0.05"},
                                      {"Load steps", "4"},
                                      {"Tolerance", "1e-10"},
                                      {"Interfaces", "5: " + shaft}}) +
           test_support::entries("Output",
                                 {{"Soil reaction depths", "auto 4"}});
  }
} // namespace

namespace
{
  /**
   * The pile with the shaft `law` (Interfaces entry); `penalty` [kPa/m] its
   * stiffness (0: exact constraints). Checks 1 and 2 at every step.
   */
  void
  check_case(const std::string &law, const double penalty)
  {
    std::cout << "shaft: " << law << std::endl;
    soil_test::Run     run(pile_scene(law));
    const unsigned int h1 = lateral_harmonic(*run.set);
    SoilReactionCurves curves(run.set->problem(h1).get_dof_handler(),
                              run.parameters);
    record_every_step(run, curves, h1);
    run.solver->run(std::cout);
    const auto &steps = run.solver->get_steps();
    check::equal("steps recorded", curves.n_steps(), steps.size());

    const double z_ref = 1., z_toe = -10., z_top = 0., R = 0.5, L = 10.;
    const double lever = std::sqrt(R * R + (z_ref - z_toe) * (z_ref - z_toe));
    const double pattern_norm = run.set->problem(h1).get_system_rhs().l2_norm();
    std::cout << std::setprecision(10);
    double previous_p = 0.;
    for (unsigned int s = 0; s < steps.size(); ++s)
      {
        const auto   loads = run.solver->applied_loads(steps[s].load_factor);
        const double H     = loads[0];
        const double M_ref =
          moment_about_reference(loads, run.parameters.rigid_foundation);
        const Resultant r       = resultant_at(curves, s, z_ref, z_toe);
        const double    shaft_H = r.shaft_H, H_B = r.base_H;
        const double    shaft_M = r.shaft_M, M_total = r.total_M;
        // The converged residual's rigid-body part, and the round-off of
        // a penalty shaft: its forces k A du with du ~ eps |u| (A = pi R L,
        // the shaft's area in the n = 1 integral), ten times for the sum.
        const double v_max = std::max(std::abs(curves.displacement(s, z_top)),
                                      std::abs(curves.displacement(s, z_toe)));
        const double bound =
          steps[s].residual * steps[s].load_factor * pattern_norm + 1e-12 * H +
          10. * std::numeric_limits<double>::epsilon() * penalty * numbers::PI *
            R * L * v_max;
        const std::string at = " at step " + std::to_string(s + 1);
        std::cout << "step " << s + 1 << ": H = " << H
                  << " kN, int p dz = " << shaft_H << " kN, H_B = " << H_B
                  << " kN; moment about z_ref: shaft " << shaft_M << ", base "
                  << M_total - shaft_M << " kN m; imbalance H "
                  << shaft_H + H_B - H << " kN, M " << M_total - M_ref
                  << " kN m" << std::endl;
        check::small("|int p dz + H_B - H| [kN]" + at,
                     std::abs(shaft_H + H_B - H),
                     bound);
        check::small("|int (m + p (z - z_ref)) dz + M_B + H_B (z_toe - "
                     "z_ref) - M_ref| [kN m]" +
                       at,
                     std::abs(M_total - M_ref),
                     bound * lever);
        // 2. p opposes v near the head and near the toe, and grows.
        const double z_upper = -2.5, z_lower = -9.;
        const double p_upper = curves.shaft_reaction(s, z_upper).first;
        check::that("p and v of one sign near the head" + at,
                    p_upper * curves.displacement(s, z_upper) > 0.);
        check::that("p and v of one sign near the toe" + at,
                    curves.shaft_reaction(s, z_lower).first *
                        curves.displacement(s, z_lower) >
                      0.);
        check::that("p near the head grows along the path" + at,
                    p_upper > previous_p);
        previous_p = p_upper;
      }
    check::that("head and toe move opposite ways",
                curves.displacement(steps.size() - 1, z_top) *
                    curves.displacement(steps.size() - 1, z_toe) <
                  0.);
    const std::vector<double> expected = {1.25, 3.75, 6.25, 8.75};
    check::equal("auto 4: four depths", curves.depths().size(), 4);
    for (unsigned int i = 0; i < 4; ++i)
      check::relative("auto 4: depth " + std::to_string(i),
                      curves.depths()[i],
                      expected[i],
                      1e-14);
  }
} // namespace

int
main()
{
  check_case("tied", 0.);
  check_case("rough", 1e10);
  return check::summary();
}
