#include <fourier_ssi/linear_algebra/distributed_solve.h>

namespace FourierSSI
{
  bool
  uses_distributed_solve(const LinearSolverParameters &solver,
                         const MPI_Comm                communicator)
  {
    // (Library users and unit tests may not have initialized MPI.)
    return Utilities::MPI::job_supports_mpi() &&
           (Utilities::MPI::n_mpi_processes(communicator) > 1 ||
            solver.distributed_always);
  }
} // namespace FourierSSI
