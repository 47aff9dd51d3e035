/**
 * The tangent stiffness of a set of harmonics that a nonlinear law couples
 * through theta (doc/soil-plasticity.md section 3, "Tangent"): one block per
 * pair of harmonics (h, g),
 *   K_t,hg = delta_hg K_h - int Bbar_h^T S_hg Bbar_g r dr dz,
 * with K_h the kept elastic (condensed) matrix of harmonic h and S_hg the
 * theta integral of factor_h (D_e - D_ep) factor_g at the points that yield.
 * Each block is condensed with the constraints of its row harmonic (rows)
 * and of its column harmonic (columns), so the block system is the
 * condensed Newton system of all harmonics together; it is factorized with
 * UMFPACK (the softened part of D_ep need not be symmetric: Mohr-Coulomb
 * with psi < phi) as one matrix whose pattern is analysed once
 * (umfpack_lu.h).
 *
 * Under MPI (harmonics distributed over the ranks, HarmonicSet::
 * distribute_over) every rank builds the same pattern (every harmonic's
 * sparsity is set up on every rank) and fills the block rows of the
 * harmonics it owns: the elastic K_h lives on h's owner only, and the
 * caller gives every rank every point's softening. One sum over the ranks
 * then completes the matrix, exactly (each entry is non-zero on one rank:
 * x + 0 = x), so the rank that owns the first harmonic factorizes the
 * serial run's matrix bit for bit; it solves and broadcasts the solution.
 *
 * Over the ranks (`Linear solver/Distributed = always`, `over_ranks`) the
 * matrix is instead one distributed matrix, factorized by MUMPS
 * (distributed_sparse_lu.h): its rows are numbered rank by rank (the
 * harmonics of rank 0, then of rank 1, ...), each rank builds the pattern
 * and the values of its own harmonics' block rows only, and no sum over the
 * ranks is needed; each harmonic's part of the solution is broadcast from
 * its owner. The factors are shared by the ranks, and the answer is the
 * one-rank answer to round-off, not bit for bit.
 */
#ifndef fourier_ssi_coupled_tangent_h
#define fourier_ssi_coupled_tangent_h

#include <deal.II/lac/block_sparse_matrix.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/linear_algebra/distributed_sparse_lu.h>
#include <fourier_ssi/linear_algebra/umfpack_lu.h>
#include <memory>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class CoupledTangent
  {
  public:
    /**
     * `cell_dofs[c][h]`: the DoF indices of harmonic h on the c-th cell
     * whose law can yield (their couplings between harmonics are the only
     * ones the softening adds). An index may repeat (an interface pair
     * whose line ends inside the body lists its end node on both faces):
     * the pattern takes it once.
     */
    CoupledTangent(
      const HarmonicSet &set,
      const std::vector<std::vector<std::vector<types::global_dof_index>>>
                &cell_dofs,
      const bool over_ranks = false);

    /** Every block to the elastic matrices: K_t = diag(K_h). */
    void
    reset_to_elastic();

    /**
     * Block (h, g) += the condensed local matrix (the softening enters
     * negated; thread-safe per block row h). The rows and columns of a
     * repeated index are summed first. Nothing on a rank that does not own
     * harmonic h (its owner adds the same matrix).
     */
    void
    add(const unsigned int                          h,
        const unsigned int                          g,
        const FullMatrix<double>                   &local,
        const std::vector<types::global_dof_index> &row_dofs,
        const std::vector<types::global_dof_index> &column_dofs);

    /**
     * LU of K_t (collective under MPI: every rank's block rows summed, one
     * rank factorizes).
     */
    void
    factorize();

    /**
     * y_h = sum_g K_t,hg x_g (condensed; a check of the assembly), of the
     * harmonics h this rank owns (zero for the others).
     */
    void
    vmult(std::vector<Vector<double>>       &y,
          const std::vector<Vector<double>> &x) const;

    /**
     * b_to_x[h] := (K_t^-1 b)_h for condensed loads b of every harmonic;
     * the constraints of every harmonic then distributed (increments).
     * Collective under MPI: b must be the same on every rank, and so is x.
     */
    void
    solve(std::vector<Vector<double>> &b_to_x) const;

    unsigned int
    n_factorizations() const
    {
      return factorizations;
    }

  private:
    /** Its owner factorizes and solves the whole matrix under MPI. */
    static constexpr unsigned int solving_harmonic = 0;

    const HarmonicSet &set;
    /** MUMPS over the ranks instead of UMFPACK on one (the class comment). */
    const bool                over_ranks;
    BlockSparsityPattern      pattern;
    BlockSparseMatrix<double> matrix;
    /**
     * The block rows this rank builds and gives to the factorization: every
     * harmonic's for UMFPACK (summed over the ranks), its own over the
     * ranks, in the order of the factorized matrix.
     */
    std::vector<unsigned int> held;
    /** The whole matrix by rows (one rank), or this rank's rows of it. */
    UmfpackLU                            lu;
    std::unique_ptr<DistributedSparseLU> distributed_lu;
    /**
     * Harmonic h's first row in the factorized matrix, and the first row
     * this rank holds (0 for UMFPACK).
     */
    std::vector<unsigned int> offset;
    unsigned int              first_held_row = 0;
    unsigned int              n_rows         = 0;
    /**
     * Where each entry of the blocks goes among lu.values(), in the order
     * of copy_to_lu()'s sweep (block row, block column, row, entry).
     */
    std::vector<unsigned int> position;
    unsigned int              factorizations = 0;

    /** held, offset and the rows this rank holds. */
    void
    number_rows();
    /** The rows of the held block rows and position[], from the pattern. */
    void
    make_lu_pattern();
    /** The values of the held rows, in the factorization's order. */
    std::vector<double> &
    held_values();
    void
    copy_to_lu();
    /** b_to_x := K_t^-1 b_to_x, constraints not yet distributed. */
    void
    solve_on_one_rank(std::vector<Vector<double>> &b_to_x) const;
    void
    solve_over_ranks(std::vector<Vector<double>> &b_to_x) const;
  };
} // namespace FourierSSI

#endif
