/**
 * One harmonic's linear system distributed over the ranks of an MPI
 * communicator (mpirun -np N fourier-ssi scene.prm), Trilinos backend.
 *
 * Every rank holds the whole 2D mesh, the whole DoFHandler and the whole
 * AffineConstraints (the model of parallel::shared::Triangulation, kept on
 * the serial Triangulation so that the serial code path is untouched): the
 * interface pairing (faces matched by position over the whole mesh) and the
 * rigid-foundation constraints (every tied DoF coupled to 2 master DoFs) then
 * work unchanged. What is distributed is the work and the memory of the
 * matrix, the preconditioner and the factorization:
 *   - cells are partitioned by METIS (computed on rank 0, broadcast);
 *   - a DoF is owned by the lowest rank among the cells that touch it;
 *   - each rank assembles its own cells, and each interface pair on the rank
 *     owning the cell of the pair's side A, so a pair whose two faces live on
 *     different ranks is assembled exactly once (Trilinos sums the rows it
 *     writes on other ranks at compress());
 *   - CG + ML AMG (the serial cg-amg settings and near-null space) or a
 *     parallel direct solver (Amesos MUMPS) solve it;
 *   - the solution is brought back as a replicated Vector<double>, so the
 *     postprocessing (reactions, foundation motion, K_H/K_M/K_MH, errors,
 *     Kelly) runs unchanged on every rank.
 * doc/scaling.md says why, and where this stops scaling. It sits in
 * harmonic/ because it assembles a harmonic (assembly_loop.h) and pairs
 * interfaces; whether a run takes it is
 * linear_algebra/distributed_solve.h's uses_distributed_solve().
 */
#ifndef fourier_ssi_distributed_linear_system_h
#define fourier_ssi_distributed_linear_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/harmonic/assembly_loop.h>
#include <fourier_ssi/interfaces/interface_integrator.h>
#include <fourier_ssi/linear_algebra/distributed_solve.h>
#include <fourier_ssi/linear_algebra/linear_solver.h>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class DistributedLinearSystem
  {
  public:
    DistributedLinearSystem(const MPI_Comm                communicator,
                            const LinearSolverParameters &solver_parameters);

    /**
     * Partition the cells, own the DoFs, count the interface pairs that
     * straddle ranks and build the Trilinos matrix over the owned rows.
     * Call after the constraints are closed and interfaces->setup().
     */
    void
    setup(const DoFHandler<2>             &dof_handler,
          const AffineConstraints<double> &constraints,
          const InterfaceIntegrator       *interfaces);

    /**
     * Assemble the owned cells and interface pairs into the matrix; rhs
     * (replicated, size n_dofs) receives the summed load of all ranks,
     * exactly what the serial assembly puts there before the foundation loads.
     * Returns this rank's wall time on the interface pairs.
     */
    double
    assemble(const LocalMatrixFactory &local_matrix, Vector<double> &rhs);

    /**
     * Solve A x = b (replicated vectors); the first nonzero solve builds the
     * AMG hierarchy or the factorization, later ones (the unit-H and unit-M
     * stiffness cases) reuse it. Same one-line errors as LinearSolver.
     */
    SolverReport
    solve(Vector<double> &x, const Vector<double> &b);

    /** The rank that assembles a cell (and owns most of its rows). */
    unsigned int
    cell_owner(const unsigned int active_cell_index) const
    {
      return cell_partition[active_cell_index];
    }

    unsigned int
    this_rank() const
    {
      return rank;
    }

    /** Interface pairs whose faces A and B are assembled on different ranks. */
    unsigned int
    n_straddling_pairs() const
    {
      return n_straddling;
    }

    const MPI_Comm &
    get_communicator() const
    {
      return communicator;
    }

  private:
    /** MUMPS through Amesos; the factorization is kept for later solves. */
    void
    solve_direct(TrilinosWrappers::MPI::Vector       &x,
                 const TrilinosWrappers::MPI::Vector &b);

    /** CG + ML AMG (hierarchy kept); returns the iteration count. */
    unsigned int
    solve_cg_amg(TrilinosWrappers::MPI::Vector       &x,
                 const TrilinosWrappers::MPI::Vector &b);

    const MPI_Comm                                     communicator;
    const LinearSolverParameters                      &parameters;
    const unsigned int                                 rank;
    const DoFHandler<2>                               *dof_handler = nullptr;
    const AffineConstraints<double>                   *constraints = nullptr;
    const InterfaceIntegrator                         *interfaces  = nullptr;
    std::vector<unsigned int>                          cell_partition;
    IndexSet                                           owned_dofs;
    unsigned int                                       n_straddling = 0;
    TrilinosWrappers::SparseMatrix                     matrix;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    SolverControl                                      direct_control;
    std::unique_ptr<TrilinosWrappers::SolverDirect>    direct;
  };
} // namespace FourierSSI

#endif
