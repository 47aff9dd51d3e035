// The harness of the MPI tests that compare a run on 2 ranks with the serial
// run (tests/mpi, run with mpirun -np 2): every rank runs both, rank 0 prints
// and checks, and every rank exits with rank 0's verdict.
#ifndef fourier_ssi_tests_two_ranks_h
#define fourier_ssi_tests_two_ranks_h

#include "check.h"

#include <deal.II/base/mpi.h>
#include <exception>
#include <iostream>
#include <string>
#include <utility>

namespace two_ranks
{
  /** Whether this process is rank 0 of MPI_COMM_WORLD, the one that checks. */
  inline bool
  is_root()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  /**
   * The serial run (every rank alone, MPI_COMM_SELF) with its log silenced,
   * then the run distributed over the ranks with rank 0's log on std::cout
   * after `heading` (none if empty). `solve(distribute, log)` runs one.
   */
  template <typename Solve>
  auto
  serial_and_distributed(const Solve &solve, const std::string &heading = "")
  {
    std::ostream  silent(nullptr);
    std::ostream &log    = is_root() ? std::cout : silent;
    auto          serial = solve(false, silent);
    if (!heading.empty())
      log << heading << std::endl;
    auto distributed = solve(true, log);
    return std::make_pair(std::move(serial), std::move(distributed));
  }

  /**
   * main() of such a test: MPI on exactly 2 ranks, `checks()` on every rank
   * (an exception fails it with one line), and every rank's exit code rank
   * 0's verdict, so that ctest sees a failure whichever rank reports.
   */
  template <typename Checks>
  int
  run(int argc, char **argv, const Checks &checks)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const MPI_Comm                           world = MPI_COMM_WORLD;
    if (dealii::Utilities::MPI::n_mpi_processes(world) != 2)
      {
        std::cerr << "run with mpirun -np 2" << std::endl;
        return 1;
      }
    try
      {
        checks();
      }
    catch (const std::exception &e)
      {
        std::cerr << "error: " << e.what() << std::endl;
        return 1;
      }
    // Rank 0 did the checking; every rank returns its verdict.
    const int failed =
      dealii::Utilities::MPI::broadcast(world, check::n_failed(), /*root=*/0);
    if (is_root())
      return check::summary();
    return failed == 0 ? 0 : 1;
  }
} // namespace two_ranks

#endif
