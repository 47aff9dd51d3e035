#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <fourier_ssi/linear_algebra/distributed_sparse_lu.h>

namespace FourierSSI
{
  DistributedSparseLU::DistributedSparseLU(const std::string &what,
                                           const MPI_Comm     communicator)
    : what(what)
    , communicator(communicator)
  {}

  DistributedSparseLU::~DistributedSparseLU() = default;

  void
  DistributedSparseLU::set_pattern(const types::global_dof_index n,
                                   const types::global_dof_index first,
                                   std::vector<long>             rows,
                                   std::vector<long>             global_columns)
  {
    first_row = first;
    row_start = std::move(rows);
    columns.assign(global_columns.begin(), global_columns.end());
    owned_rows = IndexSet(n);
    owned_rows.add_range(first_row, first_row + n_rows());
    owned_rows.compress();
    TrilinosWrappers::SparsityPattern pattern(owned_rows,
                                              owned_rows,
                                              communicator);
    for (std::size_t i = 0; i < n_rows(); ++i)
      pattern.add_entries(first_row + i,
                          columns.begin() + row_start[i],
                          columns.begin() + row_start[i + 1],
                          true);
    pattern.compress();
    matrix.reinit(pattern);
    mumps.reset();
    problem    = std::make_unique<Epetra_LinearProblem>();
    analysed   = false;
    factorized = false;
    problem->SetOperator(
      const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
    Amesos factory;
    mumps.reset(factory.Create("Amesos_Mumps", *problem));
    AssertThrow(mumps,
                ExcMessage(what + ": MUMPS (Trilinos Amesos_Mumps) is not in "
                                  "this Trilinos"));
  }

  void
  DistributedSparseLU::check(const int status, const std::string &step) const
  {
    // MUMPS's errors are global (INFOG): every rank fails, none waits.
    AssertThrow(status == 0,
                ExcMessage(what + ": MUMPS " + step +
                           " failed (Amesos status " + std::to_string(status) +
                           ")"));
  }

  void
  DistributedSparseLU::factorize()
  {
    for (std::size_t i = 0; i < n_rows(); ++i)
      matrix.set(first_row + i,
                 row_start[i + 1] - row_start[i],
                 columns.data() + row_start[i],
                 matrix_values.data() + row_start[i],
                 false);
    matrix.compress(VectorOperation::insert);
    // The pattern is fixed: its analysis (the fill-reducing order, the
    // distribution of the fronts) once, then numeric factorizations.
    if (!analysed)
      check(mumps->SymbolicFactorization(), "analysis");
    analysed   = true;
    factorized = false;
    check(mumps->NumericFactorization(), "factorization");
    factorized = true;
  }

  void
  DistributedSparseLU::solve(const std::vector<double> &b,
                             std::vector<double>       &x) const
  {
    Assert(factorized, ExcMessage("DistributedSparseLU: factorize() first"));
    TrilinosWrappers::MPI::Vector right(owned_rows, communicator),
      left(owned_rows, communicator);
    for (std::size_t i = 0; i < n_rows(); ++i)
      right[first_row + i] = b[i];
    right.compress(VectorOperation::insert);
    problem->SetLHS(&left.trilinos_vector());
    problem->SetRHS(&right.trilinos_vector());
    check(mumps->Solve(), "solve");
    x.resize(n_rows());
    for (std::size_t i = 0; i < n_rows(); ++i)
      x[i] = left[first_row + i];
  }
} // namespace FourierSSI
