#include <fourier_ssi/linear_algebra/distributed_solve.h>

namespace FourierSSI
{
  bool
  uses_distributed_solve(const LinearSolverParameters &solver,
                         const MPI_Comm                communicator)
  {
    // (Library users and unit tests may not have initialized MPI.)
    if (!Utilities::MPI::job_supports_mpi())
      return false;
    // A system made on MPI_COMM_SELF is serial by its maker's choice: the
    // coupled path, which deals whole harmonics to the ranks (there
    // Distributed = always distributes the coupled tangent instead), and a
    // --batch case.
    int self = MPI_UNEQUAL;
    MPI_Comm_compare(communicator, MPI_COMM_SELF, &self);
    if (self == MPI_IDENT)
      return false;
    return Utilities::MPI::n_mpi_processes(communicator) > 1 ||
           solver.distributed_always;
  }
} // namespace FourierSSI
