/**
 * Static condensation of cell-interior DoFs in front of the sparse Cholesky
 * factorization (sparse_direct.h).
 *
 * A cell's interior DoFs (FE_Q(4): 9 of its 25 nodes, 27 of 75 DoFs; 56 % of
 * the DoFs of a large mesh) couple only to the DoFs of their own cell.
 * Ordered as A = [A_II A_IC; A_CI A_CC] for one such block I and its
 * coupling set C, the block is eliminated exactly:
 *
 *     A_II = L L^T,   W = L^-1 A_IC,   S_CC = A_CC - W^T W,
 *
 * and the remaining (kept) system S x_K = b_K - sum W^T L^-1 b_I is what
 * CHOLMOD factorizes; afterwards x_I = L^-T (L^-1 b_I - W x_C). This is
 * the block Gaussian elimination a sparse Cholesky would do on these DoFs
 * itself, done with dense 27 x 48 kernels before the sparse analysis:
 * CHOLMOD's graph, copies and supernode count shrink (the embedded footing
 * design's member 1: 53k DoFs, 17k supernodes of about three columns;
 * doc/accuracy-vs-time.md, "Cell interiors condensed").
 *
 * The blocks are a hint: a block whose DoFs couple to another block's DoFs
 * is kept whole; a diagonal block that is not positive definite, or a
 * Schur entry outside A's sparsity pattern, switches the condensation off
 * (initialize() returns false) and the caller factorizes A as it is.
 */
#ifndef fourier_ssi_static_condensation_h
#define fourier_ssi_static_condensation_h

#include <cstdint>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** The DoFs of each cell's interior (FE_Q(p), p >= 2), one block per cell. */
  std::vector<std::vector<types::global_dof_index>>
  cell_interior_dofs(const DoFHandler<2> &dof_handler);

  class StaticCondensation
  {
  public:
    /**
     * The upper triangle of the kept system, compressed by columns, rows
     * ascending in each column (the diagonal last): CHOLMOD's stype = +1
     * form with 64-bit indices.
     */
    struct UpperMatrix
    {
      std::vector<std::int64_t> column_start;
      std::vector<std::int64_t> row_index;
      std::vector<double>       value;
    };

    /**
     * Eliminate `blocks` from the symmetric matrix A and write the kept
     * system to `kept`. With no blocks (or after a false return) the kept
     * system is A itself. Returns false if the condensation had to be
     * switched off (class documentation).
     */
    bool
    initialize(const SparseMatrix<double>                              &A,
               const std::vector<std::vector<types::global_dof_index>> &blocks,
               UpperMatrix                                             &kept);

    /** The size of the kept system. */
    std::size_t
    n_kept() const;

    /**
     * Forward elimination of the right-hand sides b (full size, in place:
     * their eliminated entries are overwritten by L^-1 b_I), and the kept
     * right-hand sides gathered into `kept_rhs` (n_kept x b.size(), by
     * columns).
     */
    void
    condense(std::vector<Vector<double>> &b, double *kept_rhs) const;

    /**
     * x_K from the kept solution (n_kept x x.size(), by columns), then the
     * eliminated entries by back substitution. x holds what condense()
     * left in it.
     */
    void
    expand(const double *kept_solution, std::vector<Vector<double>> &x) const;

  private:
    void
    reset(const types::global_dof_index n_dofs);

    /**
     * Each DoF's block if it is condensed, else -1 (kept DoFs, and the DoFs
     * of blocks kept whole).
     */
    std::vector<int>
    condensed_block_of(
      const SparseMatrix<double>                              &A,
      const std::vector<std::vector<types::global_dof_index>> &blocks) const;

    /** kept_index and kept_dofs from the condensed DoFs. */
    void
    number_kept_dofs(const std::vector<int> &block_of);

    /** The upper triangle of A's kept rows and columns. */
    void
    copy_kept_part(const SparseMatrix<double> &A, UpperMatrix &kept) const;

    /** The condensed blocks, their coupling sets and their storage. */
    void
    plan_blocks(const SparseMatrix<double>                              &A,
                const std::vector<std::vector<types::global_dof_index>> &blocks,
                const std::vector<int> &block_of);

    /** eliminate_block() on every planned block; false if one cannot. */
    bool
    eliminate_blocks(const SparseMatrix<double> &A, UpperMatrix &kept);

    struct Block;

    /**
     * Work arrays of eliminate_blocks(), shared by its blocks:
     * local_position[i] is DoF i's row in [A_II A_IC]^T of the block at
     * hand (-1 elsewhere), update its W^T W.
     */
    struct Workspace
    {
      std::vector<int>    local_position;
      std::vector<double> update;
    };

    /**
     * Factor one block into its slots of `factors` and `w` and subtract
     * W^T W from `kept`; false if it cannot.
     */
    bool
    eliminate_block(const SparseMatrix<double> &A,
                    const Block                &block,
                    Workspace                  &work,
                    UpperMatrix                &kept);

    /** Full index -> kept index (-1: eliminated). */
    std::vector<std::int64_t> kept_index;
    /** Kept index -> full index. */
    std::vector<types::global_dof_index> kept_dofs;

    /** Per eliminated block: its DoFs, its coupling set, L and W. */
    struct Block
    {
      std::size_t  interior_start, coupling_start, factor_start, w_start;
      unsigned int n_interior, n_coupling;
    };
    std::vector<Block>                   eliminated;
    std::vector<types::global_dof_index> interior;
    std::vector<types::global_dof_index> coupling;
    std::vector<double>                  factors; // L, p x p by columns
    std::vector<double>                  w;       // W, p x |C| by columns
  };
} // namespace FourierSSI

#endif
