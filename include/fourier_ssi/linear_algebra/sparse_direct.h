/**
 * One sparse direct factorization of a harmonic's system matrix, reused for
 * every right-hand side (the scene load and the unit-H and unit-M loads of
 * the stiffness coefficients).
 *
 * Two back ends:
 *  - "cholesky": CHOLMOD's supernodal Cholesky L L^T (SuiteSparse). The
 *    harmonic systems are symmetric positive definite once supports,
 *    rigid-foundation and axis constraints are applied, so half the storage
 *    of an LU and dense BLAS-3 kernels on the supernodes. A matrix that is
 *    not positive definite (a body free to move) falls back to the LU path,
 *    whose result the callers' residual and support checks then judge.
 *  - "lu": UMFPACK's unsymmetric LU, kept as the reference path.
 */
#ifndef fourier_ssi_sparse_direct_h
#define fourier_ssi_sparse_direct_h

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/linear_algebra/static_condensation.h>
#include <memory>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class SparseDirect
  {
  public:
    /** `backend`: "cholesky" or "lu". */
    explicit SparseDirect(const std::string &backend = "cholesky");
    ~SparseDirect();
    SparseDirect(const SparseDirect &) = delete;
    SparseDirect &
    operator=(const SparseDirect &) = delete;

    /**
     * Factorize A. Throws a one-line error if A is singular; Cholesky falls
     * back to LU on a matrix that is not positive definite. Cholesky first
     * eliminates `eliminated_blocks` (cell_interior_dofs(): the cells'
     * interior DoFs) by static condensation (static_condensation.h).
     */
    void
    initialize(const SparseMatrix<double> &A,
               const std::vector<std::vector<types::global_dof_index>>
                 &eliminated_blocks = {});

    /** x := A^-1 x. */
    void
    solve(Vector<double> &x) const;

    /** x := A^-1 x for several right-hand sides at once (one BLAS-3 sweep). */
    void
    solve(std::vector<Vector<double>> &x) const;

    /** x := A^-1 b. */
    void
    vmult(Vector<double> &x, const Vector<double> &b) const;

  private:
    std::string backend;
    struct Cholmod;
    std::unique_ptr<Cholmod> cholmod;
    StaticCondensation       condensation;
    SparseDirectUMFPACK      umfpack;
  };
} // namespace FourierSSI

#endif
