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
// thousand unknowns); the globalisation is the one of every coupled Newton
// (safeguarded_newton.h, set in coupled_interface_solver.cc, iterate).
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

  } // namespace

  FullMatrix<double>
  CoupledInterfaceSolver::out_of_balance_jacobian(const Evaluation &e,
                                                  const StepState  &state) const
  {
    // The held stage prescribes rho: lambda does not follow c there.
    const bool                      displacement_control = controls_motion();
    const std::vector<LocalTangent> follow =
      interface.plastic_tangents(e.relative, state.interfaces.origin);
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
                      (change[k][b] + load_factor_change * cases.pattern[k][b]);
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

} // namespace FourierSSI
