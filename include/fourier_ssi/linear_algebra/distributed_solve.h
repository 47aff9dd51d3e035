/**
 * Whether a harmonic's linear system takes the distributed (Trilinos) path;
 * the pure linear-algebra decision, apart from the class that assembles the
 * distributed system (harmonic/distributed_linear_system.h).
 */
#ifndef fourier_ssi_distributed_solve_h
#define fourier_ssi_distributed_solve_h

#include <deal.II/base/mpi.h>
#include <fourier_ssi/input/linear_solver_parameters.h>

namespace FourierSSI
{
  /**
   * The one predicate for "is a harmonic's linear system distributed
   * (Trilinos)": more than one rank, or `Distributed = always` under MPI.
   * The solves, the thread count and the output all ask it.
   */
  bool
  uses_distributed_solve(const LinearSolverParameters &solver,
                         const MPI_Comm                communicator);
} // namespace FourierSSI

#endif
