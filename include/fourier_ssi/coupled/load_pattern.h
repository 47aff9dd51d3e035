/**
 * The loads of a nonlinear run and their elastic solutions, as both coupled
 * solvers use them: F, the loads the load factor lambda scales
 * (load_factor_pattern), and F_held, the held loads the held fraction rho
 * brings on (held_stage_load), with K^-1 F and K^-1 F_held of the harmonics
 * this rank owns (zero vectors for the others: their fields come from their
 * owners), and the norms of the applied load scale |lambda F + rho F_held|
 * (ForceScale). The norms are summed per harmonic over the ranks and then
 * in the harmonics' order (sum_over_harmonics): the same bits on any number
 * of ranks.
 */
#ifndef fourier_ssi_load_pattern_h
#define fourier_ssi_load_pattern_h

#include <deal.II/lac/vector.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  struct LoadPattern
  {
    /** None yet (no harmonic). */
    LoadPattern() = default;

    /** Solves K^-1 F and K^-1 F_held on every harmonic of `set`. */
    explicit LoadPattern(const HarmonicSet &set);

    /** True if the scene holds loads (a held stage comes first). */
    bool
    holds_loads() const
    {
      return !held_solution.empty();
    }

    /** |lambda F + rho F_held| (2-norm over the harmonics). */
    double
    applied_norm(const double load_factor, const double held_fraction) const;

    /**
     * u_h = lambda K^-1 F_h + correction + rho K^-1 F_held,h (+ mu K^-1
     * e_V,h in a swipe).
     */
    Vector<double>
    total_displacement(const unsigned int    h,
                       const double          load_factor,
                       const Vector<double> &correction,
                       const double          held_fraction,
                       const double          swipe_force = 0.) const;

    /**
     * A swipe (RigidFoundationParameters::swipes()): e_V, the unit vertical
     * force on the rigid foundation (harmonic 0 symmetric, zero vectors on
     * the others), and K^-1 e_V: the pattern of the multiplier mu that
     * keeps w at the preload's value.
     */
    void
    add_swipe_pattern(const HarmonicSet &set);

    /** F per harmonic (zero on the harmonics this rank does not own). */
    std::vector<Vector<double>> load;
    /** K^-1 F per harmonic (likewise). */
    std::vector<Vector<double>> solution;
    /** K^-1 F_held per harmonic; empty if the scene holds no load. */
    std::vector<Vector<double>> held_solution;
    /** e_V and K^-1 e_V per harmonic; empty without a swipe. */
    std::vector<Vector<double>> swipe_load, swipe_solution;
    /** |F|, |F_held| and F . F_held. */
    double load_norm = 0., held_norm = 0., load_held_dot = 0.;
  };
} // namespace FourierSSI

#endif
