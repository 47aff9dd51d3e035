/**
 * MUMPS's distributed sparse LU (through Trilinos Amesos) of one fixed
 * sparsity pattern, refactorized for new values: the coupled Newton tangent
 * over the MPI ranks (coupled_tangent.h, `Linear solver/Distributed =
 * always`). Each rank holds one contiguous range of the rows (CSR, global
 * columns sorted in each row) and gives only those; MUMPS keeps its part of
 * the factors on each rank, so the memory of the factors is shared by the
 * ranks instead of held by one. The right-hand side and the solution are
 * given and returned by the same row ranges. MUMPS analyses the pattern
 * once (Amesos' symbolic factorization, at the first factorize()); every
 * later factorization is numeric only, as UmfpackLU's (umfpack_lu.h).
 */
#ifndef fourier_ssi_distributed_sparse_lu_h
#define fourier_ssi_distributed_sparse_lu_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace FourierSSI
{
  using namespace dealii;

  class DistributedSparseLU
  {
  public:
    /** `what`: the start of the one-line message if a factorization fails. */
    DistributedSparseLU(const std::string &what, const MPI_Comm communicator);
    ~DistributedSparseLU();

    /**
     * This rank's rows first_row .. first_row + row_start.size() - 2 of an
     * n × n matrix: row_start[i]..row_start[i+1] index `columns` (global,
     * sorted in each row). Collective; the ranges of the ranks, in rank
     * order, must tile 0..n.
     */
    void
    set_pattern(const types::global_dof_index n,
                const types::global_dof_index first_row,
                std::vector<long>             row_start,
                std::vector<long>             columns);

    /** The values of this rank's rows in the order of `columns`. */
    std::vector<double> &
    values()
    {
      matrix_values.resize(columns.size());
      return matrix_values;
    }

    /** LU of the current values (collective); one line if it fails. */
    void
    factorize();

    /**
     * x := (A^-1 b) on this rank's rows, b given on them (collective;
     * b and x of size n_rows()).
     */
    void
    solve(const std::vector<double> &b, std::vector<double> &x) const;

    /** The rows this rank holds. */
    std::size_t
    n_rows() const
    {
      return row_start.empty() ? 0 : row_start.size() - 1;
    }

  private:
    std::string                                            what;
    MPI_Comm                                               communicator;
    IndexSet                                               owned_rows;
    types::global_dof_index                                first_row = 0;
    std::vector<long>                                      row_start;
    std::vector<TrilinosWrappers::SparseMatrix::size_type> columns;
    std::vector<double>                                    matrix_values;
    TrilinosWrappers::SparseMatrix                         matrix;
    std::unique_ptr<Epetra_LinearProblem>                  problem;
    std::unique_ptr<Amesos_BaseSolver>                     mumps;
    bool                                                   analysed   = false;
    bool                                                   factorized = false;

    /** One line naming `what` if an Amesos call returned `status` != 0. */
    void
    check(const int status, const std::string &step) const;
  };
} // namespace FourierSSI

#endif
