// Helpers of the soil-reaction-curve tests: the curves recorded at every
// converged step of a plastic run, and their balance with the applied H
// and M (doc/soil-reaction-curves.md section 2).
#ifndef fourier_ssi_tests_soil_reaction_test_support_h
#define fourier_ssi_tests_soil_reaction_test_support_h

#include "soil_test_support.h"

#include <deal.II/base/quadrature_lib.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/postprocess/soil_reaction_curves.h>

namespace reaction_test
{
  using namespace FourierSSI;

  /** The index of harmonic n = 1 in the run's set (the lateral one). */
  inline unsigned int
  lateral_harmonic(const HarmonicSet &set)
  {
    unsigned int h = 0;
    while (set.harmonic(h).n != 1)
      ++h;
    return h;
  }

  /**
   * Record the curves at every converged step of `run` (call before
   * run.solver->run()): the soil's nodal forces beside the shaft and below
   * the base, the harmonic's solution, the motion and the applied H and M.
   */
  inline void
  record_every_step(soil_test::Run     &run,
                    SoilReactionCurves &curves,
                    const unsigned int  h1)
  {
    run.solver->add_step_observer(
      [&run, &curves, h1](const LoadStepResult &step) {
        const auto shaft = run.solver->soil_nodal_force(
          [&](const Point<2> &c) { return curves.beside_shaft(c); });
        const auto base = run.solver->soil_nodal_force(
          [&](const Point<2> &c) { return curves.below_base(c); });
        const auto loads = run.solver->applied_loads(step.load_factor);
        curves.record(shaft[h1],
                      base[h1],
                      run.solver->solution(h1),
                      step.motion,
                      loads[0],
                      moment_about_reference(loads,
                                             run.parameters.rigid_foundation));
      });
  }

  /** int f(z) dz over the shaft, 3 Gauss points per cell of its line. */
  template <class F>
  double
  over_shaft(const SoilReactionCurves &curves, const F &f)
  {
    const QGauss<1>            gauss(3);
    const std::vector<double> &z   = curves.shaft_vertices();
    double                     sum = 0.;
    for (unsigned int c = 0; c + 1 < z.size(); ++c)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double x = z[c] + gauss.point(q)[0] * (z[c + 1] - z[c]);
          sum += f(x) * gauss.weight(q) * (z[c + 1] - z[c]);
        }
    return sum;
  }

  /** What the curves of step s carry, moments about z_ref [kN, kN m]. */
  struct Resultant
  {
    double shaft_H = 0., shaft_M = 0., base_H = 0., total_M = 0.;
  };

  /**
   * int p dz, int (m + p (z - z_ref)) dz over the shaft, the base shear
   * and the total moment about z_ref (the base's moment and its shear
   * times the lever z_toe - z_ref added).
   */
  inline Resultant
  resultant_at(const SoilReactionCurves &curves,
               const unsigned int        s,
               const double              z_ref,
               const double              z_toe)
  {
    Resultant r;
    const auto [H_B, M_B] = curves.base_reaction(s);
    r.shaft_H             = over_shaft(curves, [&](const double z) {
      return curves.shaft_reaction(s, z).first;
    });
    r.shaft_M             = over_shaft(curves, [&](const double z) {
      const auto [p, m] = curves.shaft_reaction(s, z);
      return m + p * (z - z_ref);
    });
    r.base_H              = H_B;
    r.total_M             = r.shaft_M + M_B + H_B * (z_toe - z_ref);
    return r;
  }
} // namespace reaction_test

#endif
