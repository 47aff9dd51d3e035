/**
 * Every harmonic of a run, each with its assembled system and its kept
 * factorization: the building block of a solve that couples harmonics (a
 * nonlinear interface or soil law sampled in theta, doc/theory.md). After
 * one factorization per harmonic, every harmonic can be re-solved for new
 * right-hand sides without refactorizing.
 *
 * Harmonics are independent systems on one read-only mesh, so the work on
 * them runs concurrently on threads; a distributed solve (MPI ranks, or
 * `Linear solver/Distributed = always`) runs one harmonic at a time, since
 * collective calls must not interleave on one communicator.
 *
 * A solve that couples harmonics under mpirun (CoupledSolver)
 * distributes them instead: distribute_over() gives each rank its own
 * harmonics (serial systems), which only it assembles, factorizes and
 * solves (doc/nonlinear-interfaces.md section 5, "Under MPI").
 */
#ifndef fourier_ssi_harmonic_set_h
#define fourier_ssi_harmonic_set_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <exception>
#include <fourier_ssi/fourier/load_decomposition.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/input/parameters.h>
#include <functional>
#include <memory>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class HarmonicSet
  {
  public:
    /**
     * `max_threads`: how many harmonics may run at once (0 = the cores);
     * forced to 1 for a distributed solve. `cores`: the cores the set may
     * use (0 = cores_per_rank()); the harmonics run at once share them, and
     * the ones they leave idle serve the cell loops of their assembly.
     */
    HarmonicSet(const AllParameters         &parameters,
                const std::vector<Harmonic> &harmonics,
                const Triangulation<2>      &triangulation,
                const LoadDecomposition     &loads,
                const MPI_Comm               communicator,
                const unsigned int           max_threads,
                const unsigned int           cores = 0);

    /** The node's cores shared among the MPI ranks of the job. */
    static unsigned int
    cores_per_rank();

    /**
     * How many of `n_harmonics` harmonics run at once (`max_threads` as in
     * the constructor; 1 for a distributed solve), at most `cores` of them
     * when `cores` > 0.
     */
    static unsigned int
    concurrent_harmonics(const AllParameters &parameters,
                         const unsigned int   n_harmonics,
                         const MPI_Comm       communicator,
                         const unsigned int   max_threads,
                         const unsigned int   cores);

    unsigned int
    size() const
    {
      return problems.size();
    }

    /** The harmonics of the set, in the order of problem(i). */
    const std::vector<Harmonic> &
    get_harmonics() const
    {
      return harmonics;
    }

    const Harmonic &
    harmonic(const unsigned int i) const
    {
      return harmonics[i];
    }

    HarmonicProblem &
    problem(const unsigned int i)
    {
      return *problems[i];
    }

    const HarmonicProblem &
    problem(const unsigned int i) const
    {
      return *problems[i];
    }

    /** Shared, so a 3D reconstruction can keep a harmonic's field. */
    std::shared_ptr<HarmonicProblem>
    shared_problem(const unsigned int i) const
    {
      return problems[i];
    }

    /** Threads the harmonics run on (1 for a distributed solve). */
    unsigned int
    n_threads() const
    {
      return threads;
    }

    /**
     * Threads for loops over independent points (the soil's return
     * mapping and softening): every core the set may use, also where it
     * has fewer harmonics than cores (a lone n = 0); 1 for a distributed
     * solve.
     */
    unsigned int
    n_point_threads() const
    {
      return point_threads;
    }

    /**
     * Run task(i) for every harmonic, up to n_threads() at once. A task
     * that throws does not stop the others; afterwards the first failure
     * (in harmonic order) is rethrown as one line naming its harmonic.
     */
    void
    for_each(const std::function<void(const unsigned int)> &task) const;

    /** for_each over the harmonics first, first + 1, ... only. */
    void
    for_each_from(const unsigned int                             first,
                  const std::function<void(const unsigned int)> &task) const;

    /** DoFs, constraints and sparsity, then matrix and load, every harmonic. */
    void
    setup_and_assemble();

    /** One factorization per harmonic, kept (HarmonicProblem::factorize). */
    void
    factorize();

    /**
     * For every harmonic i: b_to_x[i][k] := K_i^-1 b_to_x[i][k] with the
     * kept factorizations (condensed loads in, displacement increments out,
     * HarmonicProblem::solve_increments), harmonics concurrently.
     */
    void
    solve_increments(std::vector<std::vector<Vector<double>>> &b_to_x) const;

    /**
     * Add harmonics to the set: each is set up, assembled and factorized
     * (concurrently), as the constructor, setup_and_assemble() and
     * factorize() do for the first ones; the earlier harmonics and their
     * factorizations are kept. For a solve that finds during its iteration
     * that its solution contains harmonics the load does not (a slipping or
     * opening interface, CoupledSolver).
     */
    void
    add(const std::vector<Harmonic> &new_harmonics);

    /** Factorizations computed so far, summed over the harmonics. */
    unsigned int
    n_factorizations() const;

    /**
     * Distribute the harmonics over the ranks of `ranks`: harmonic i (in
     * the set's order, those added later included) belongs to rank
     * i mod P. Every harmonic has the same mesh and element, so its
     * factorization and its solves cost about the same: the count balances
     * the cost, and a harmonic added later goes to a least-loaded rank.
     * Every rank still sets up every harmonic (DoFs and constraints: what
     * maps an interface force onto it); assembly, factorization and solves
     * run on the owner only. The problems must be serial (constructed on
     * MPI_COMM_SELF). From then on every call of for_each_from (and so
     * setup_and_assemble, factorize, solve_increments, add) is collective
     * over `ranks`: a harmonic failing on its owner fails on every rank
     * with the same message, instead of leaving the others waiting. Call
     * right after the constructor; with one rank it changes nothing.
     */
    void
    distribute_over(const MPI_Comm ranks);

    /** Does this rank assemble, factorize and solve harmonic i? */
    bool
    owns(const unsigned int i) const
    {
      return i % n_ranks == rank;
    }

    /** The rank that owns harmonic i. */
    unsigned int
    owner(const unsigned int i) const
    {
      return i % n_ranks;
    }

    /** The ranks the harmonics are distributed over (distribute_over()). */
    MPI_Comm
    get_ranks() const
    {
      return ranks;
    }

    /** Number of ranks the harmonics are distributed over (1: none). */
    unsigned int
    n_owning_ranks() const
    {
      return n_ranks;
    }

    /**
     * values := their sum over the owning ranks, in place (one
     * MPI_Allreduce; on one rank nothing). The coupled solvers make about
     * one per iteration: what keeps the ranks in step.
     */
    void
    sum_over_ranks(std::vector<double> &values) const;

    /**
     * values[0..n) := the owner of harmonic i's copy, on every rank (one
     * MPI_Bcast; on one rank nothing): what only the owner computed
     * (harmonic i's solution, a motion read from it) made known to all.
     */
    void
    broadcast_from_owner(const unsigned int i,
                         double            *values,
                         const std::size_t  n) const;

    /** Sums made by sum_over_ranks() and the wall time in them [s]. */
    unsigned int
    n_rank_sums() const
    {
      return rank_sums;
    }
    double
    rank_sum_time() const
    {
      return rank_sum_seconds;
    }

  private:
    mutable unsigned int rank_sums        = 0;
    mutable double       rank_sum_seconds = 0.;
    /** What a harmonic added later is built from (the constructor's). */
    const AllParameters     &parameters;
    const Triangulation<2>  &triangulation;
    const LoadDecomposition &loads;
    const MPI_Comm           communicator;

    std::vector<Harmonic>                         harmonics;
    std::vector<std::shared_ptr<HarmonicProblem>> problems;
    unsigned int                                  threads;
    unsigned int                                  point_threads = 1;
    /** distribute_over(): the ranks, their number, this rank. */
    MPI_Comm     ranks   = MPI_COMM_SELF;
    unsigned int n_ranks = 1;
    unsigned int rank    = 0;

    /** Every rank throws the first failure of any rank (distributed). */
    void
    agree_on_failure(const std::vector<std::exception_ptr> &errors,
                     const unsigned int                     first) const;
  };
} // namespace FourierSSI

#endif
