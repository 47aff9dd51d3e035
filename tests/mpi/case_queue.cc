// CaseQueue (case_queue.h) on 2 ranks of one node: every case is handed out
// exactly once, and a rank that is free takes the next case. Rank 0 spends
// 100 ms on each case it takes, rank 1 none, on 20 cases. Dealt in turn each
// rank would take 10; from the queue rank 1 must take more than rank 0, since
// it is free again at once (measured: 20 of 20). The counts are exact checks
// except this one, whose bound (more than half) holds unless rank 1 waits
// 100 ms to take a case, which a shared-memory fetch-and-add never does.
#include "check.h"

#include <chrono>
#include <deal.II/base/mpi.h>
#include <fourier_ssi/driver/case_queue.h>
#include <thread>
#include <vector>

using namespace FourierSSI;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           world = MPI_COMM_WORLD;
  const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(world);
  const unsigned int n_cases = 20;
  std::vector<int>   taken(n_cases, 0);
  bool               shared = false;
  {
    CaseQueue queue(world, n_cases);
    shared = queue.shared();
    for (unsigned int c = queue.next(); c < n_cases; c = queue.next())
      {
        ++taken[c];
        if (rank == 0)
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
  }
  std::vector<int> times_taken(n_cases);
  MPI_Allreduce(
    taken.data(), times_taken.data(), n_cases, MPI_INT, MPI_SUM, world);
  int mine = 0;
  for (const int t : taken)
    mine += t;
  const std::vector<int> per_rank =
    dealii::Utilities::MPI::all_gather(world, mine);
  if (rank == 0)
    {
      std::cout << "cases taken: rank 0 " << per_rank[0] << ", rank 1 "
                << per_rank[1] << std::endl;
      check::that("the ranks share one node (the queue is in use)", shared);
      unsigned int exactly_once = 0;
      for (const int t : times_taken)
        exactly_once += (t == 1);
      check::equal("cases taken exactly once", exactly_once, n_cases);
      check::that("the free rank takes more than half",
                  2 * per_rank[1] > static_cast<int>(n_cases));
    }
  return rank == 0 ? check::summary() : 0;
}
