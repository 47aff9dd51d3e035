// Newton for the interface-only coupled iteration (Load path/
// Stiffness = tangent, doc/nonlinear-interfaces.md section 5b): the unknown
// is the correction load c on the write DoFs of every harmonic, the
// residual R(c) = G(c) - c, and
//   dG/dc = load_of( (I - D_K^-1 D_t) dd/dc ),  dd/dc = B F (+ dlambda/dc d_F),
// with D_K the springs assembled into K and in the return mapping (a
// coulomb interface's kn, ks capped at interface_iteration_stiffness G / l,
// so that K, F and c stay those of a moderate interface however stiff the
// law, whose own springs come in through the augmented Lagrangian's
// multipliers; the augmentation for contact), D_t the closed-form consistent
// tangent of the return mapping, F the flexibility blocks K^-1 (read x write)
// kept by the condensation and, under displacement control, dlambda/dc =
// -m(K^-1 e_j) / m(u_F) (lambda keeps the controlled motion on its target). The
// update solves (I - dG/dc) dc = R, dense on the write DoFs (tens to a few
// thousand unknowns). Full steps are taken while they improve on the best |R|
// within a few steps (a gap that closes or a slip that reverses beyond the
// tangent's foresight is corrected by the next tangent, as in an active-set
// Newton); otherwise (the states cycle) the iteration returns to the best
// iterate and a backtracking line search halves the step until |R| falls by the
// Armijo fraction, so the best |R| decreases at least every few updates and
// stick/slip cycling cannot go on. Where not even that lowers |R| (a kink of
// the return mapping at the iterate), the solver takes one initial-stiffness
// update (coupled_interface_solver.cc, solve_step).
//
// Under MPI (harmonics distributed over the ranks, HarmonicSet::
// distribute_over) harmonic g's flexibility block lives on its owner only: each
// rank fills the columns of dG/dc of the harmonics it owns (the projection of
// their plastic change onto every harmonic is local math on the samples every
// rank shares), one sum over the ranks completes the matrix (each column
// non-zero on exactly one rank: exact), and the owner of the first harmonic
// solves the dense system and broadcasts dc, so every rank takes the same step
// and the line search and watchdog compare the same |R| on every rank.
#include <deal.II/lac/lapack_full_matrix.h>
#include <fourier_ssi/coupled/coupled_interface_solver.h>

namespace FourierSSI
{
  namespace
  {
    /**
     * The whole matrix on every rank from the columns each rank filled
     * (zero elsewhere): one sum over the ranks the harmonics are
     * distributed over, exact since every column comes from one rank.
     */
    void
    sum_columns_over_ranks(const HarmonicSet &set, FullMatrix<double> &matrix)
    {
      if (set.n_owning_ranks() == 1 || matrix.m() == 0)
        return;
      double *const       first = &matrix(0, 0);
      const std::size_t   n     = matrix.m() * matrix.n();
      std::vector<double> entries(first, first + n);
      set.sum_over_ranks(entries);
      std::copy(entries.begin(), entries.end(), first);
    }

    /** Armijo fraction: accept a step alpha if |R| falls by c1 alpha |R|. */
    constexpr double armijo_fraction = 1e-4;
    /** Halvings of the Newton step before the update gives up (2^-16). */
    constexpr unsigned int maximum_halvings = 16;
    /**
     * Full Newton steps that may fail to improve on the best |R| before
     * the iteration returns to the best iterate and searches along its
     * direction (the watchdog of Chamberlain et al., 1982).
     */
    constexpr unsigned int watchdog_steps = 4;
  } // namespace

  FullMatrix<double>
  CoupledInterfaceSolver::out_of_balance_jacobian(const Evaluation &e,
                                                  const StepState  &state) const
  {
    // The held stage prescribes rho: lambda does not follow c there.
    const bool                      displacement_control = controls_motion();
    const std::vector<LocalTangent> follow =
      interface.plastic_tangents(e.relative, state.origin);
    std::vector<unsigned int> offset(set.size() + 1, 0);
    for (unsigned int h = 0; h < set.size(); ++h)
      offset[h + 1] = offset[h] + condensed[h].write.size();
    FullMatrix<double>          jacobian(offset.back(), offset.back());
    std::vector<Vector<double>> unit(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      unit[h].reinit(pattern_solution[h].size());
    std::vector<LocalVector> plastic_change(e.relative.size());
    for (unsigned int g = 0; g < set.size(); ++g)
      {
        // Only g's owner holds its flexibility block (file comment).
        if (!set.owns(g))
          continue;
        const Condensation &column = condensed[g];
        for (unsigned int j = 0; j < column.write.size(); ++j)
          {
            // 1. dd of c = e_j at every sample: K^-1 e_j at the read DoFs
            //    (the flexibility column), and lambda's change.
            for (unsigned int i = 0; i < column.read.size(); ++i)
              unit[g](column.read[i]) = column.flexibility(i, j);
            std::vector<LocalVector> change =
              interface.owned_relative_displacements(unit, sampling);
            unit[g] = 0.;
            const double load_factor_change =
              displacement_control ?
                -column.controlled_motion[j] / pattern_motion :
                0.;
            // 2. dd_p = (I - D^-1 D_t) dd, and dG = load_of(dd_p).
            for (unsigned int k = 0; k < change.size(); ++k)
              for (unsigned int a = 0; a < 3; ++a)
                {
                  plastic_change[k][a] = 0.;
                  for (unsigned int b = 0; b < 3; ++b)
                    plastic_change[k][a] +=
                      follow[k][a * 3 + b] *
                      (change[k][b] +
                       load_factor_change * pattern_relative[k][b]);
                }
            const std::vector<Vector<double>> load_change =
              on_write_dofs(interface.load_of(plastic_change, sampling));
            for (unsigned int h = 0; h < set.size(); ++h)
              for (unsigned int i = 0; i < load_change[h].size(); ++i)
                jacobian(offset[h] + i, offset[g] + j) = load_change[h](i);
          }
      }
    sum_columns_over_ranks(set, jacobian);
    return jacobian;
  }

  Vector<double>
  CoupledInterfaceSolver::newton_direction(const Evaluation &e,
                                           const StepState  &state) const
  {
    const FullMatrix<double>    dG = out_of_balance_jacobian(e, state);
    const unsigned int          n  = dG.m();
    LAPACKFullMatrix<double>    system(n, n);
    Vector<double>              dc(n);
    std::vector<Vector<double>> residual = on_write_dofs(e.residual);
    for (unsigned int r = 0, h = 0; h < set.size(); ++h)
      for (unsigned int i = 0; i < residual[h].size(); ++i, ++r)
        dc(r) = residual[h](i);
    // One rank solves, the others receive its dc (the same bits on every
    // rank whatever the BLAS does; on one rank the broadcast is nothing).
    if (set.owns(0))
      {
        for (unsigned int r = 0; r < n; ++r)
          for (unsigned int c = 0; c < n; ++c)
            system(r, c) = (r == c ? 1. : 0.) - dG(r, c);
        system.compute_lu_factorization();
        system.solve(dc);
      }
    set.broadcast_from_owner(0, dc.begin(), n);
    return dc;
  }

  void
  CoupledInterfaceSolver::add_scaled_correction(const double          alpha,
                                                const Vector<double> &dc,
                                                StepState &state) const
  {
    std::vector<Vector<double>> step(set.size());
    for (unsigned int r = 0, h = 0; h < set.size(); ++h)
      {
        step[h].reinit(condensed[h].write.size());
        for (unsigned int i = 0; i < step[h].size(); ++i, ++r)
          step[h](i) = alpha * dc(r);
      }
    add_correction(step, state);
  }

  bool
  CoupledInterfaceSolver::line_search(const double target,
                                      StepState   &state,
                                      Evaluation  &e) const
  {
    const Vector<double> dc    = newton_direction(e, state);
    const StepState      start = state;
    // The first step that meets the Armijo condition, else the step of the
    // smallest |R| if it is below the start's.
    double alpha = 1., best_alpha = 0., best_norm = e.residual_norm;
    for (unsigned int halving = 0; halving <= maximum_halvings; ++halving)
      {
        add_scaled_correction(alpha, dc, state);
        Evaluation trial = evaluate(target, state);
        if (std::isfinite(trial.residual_norm) &&
            trial.residual_norm <=
              (1. - armijo_fraction * alpha) * e.residual_norm)
          {
            e = std::move(trial);
            return true;
          }
        if (std::isfinite(trial.residual_norm) &&
            trial.residual_norm < best_norm)
          best_alpha = alpha, best_norm = trial.residual_norm;
        state = start;
        alpha /= 2.;
      }
    if (best_alpha == 0.)
      return false;
    add_scaled_correction(best_alpha, dc, state);
    e = evaluate(target, state);
    return true;
  }

  bool
  CoupledInterfaceSolver::newton_update(const double    target,
                                        StepState      &state,
                                        Evaluation     &e,
                                        NewtonWatchdog &watchdog) const
  {
    // 1. The best iterate so far; the full steps keep going while they
    //    improve on it within watchdog_steps.
    if (e.residual_norm < watchdog.best_norm)
      {
        watchdog.best       = state;
        watchdog.best_norm  = e.residual_norm;
        watchdog.since_best = 0;
      }
    else if (++watchdog.since_best > watchdog_steps)
      {
        // 2. No improvement over watchdog_steps full steps (the states
        //    cycle): back to the best iterate and along its Newton
        //    direction only as far as |R| decreases.
        state               = watchdog.best;
        e                   = evaluate(target, state);
        watchdog.since_best = 0;
        if (!line_search(target, state, e))
          return false;
        watchdog.best      = state;
        watchdog.best_norm = e.residual_norm;
        return true;
      }
    // 3. The full Newton step: a state change it does not foresee (a gap
    //    that closes, a slip that reverses) is corrected by the next
    //    tangent, as in an active-set (semismooth) Newton.
    add_scaled_correction(1., newton_direction(e, state), state);
    e = evaluate(target, state);
    return std::isfinite(e.residual_norm);
  }
} // namespace FourierSSI
