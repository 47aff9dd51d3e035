/**
 * Parameter sweeps over MPI ranks:
 *   mpirun -np N fourier-ssi --batch [--csv FILE] CASE.prm... | LIST...
 * Each rank takes the next case when it is free (CaseQueue; on several nodes
 * case i goes to rank i mod N); each case runs serially (MPI_COMM_SELF) exactly
 * as `fourier-ssi CASE.prm` would, writing its own Output/Directory. Rank 0
 * gathers every case's log and scalar results and writes one CSV
 * "case,quantity,n,family,cycle,value,unit" in case order (default batch.csv).
 * The wall times (time_* rows) stay in each case's own results.csv and are left
 * out of the batch CSV, so that the batch CSV is byte-identical for any number
 * of ranks.
 */
#ifndef fourier_ssi_batch_runner_h
#define fourier_ssi_batch_runner_h

#include <deal.II/base/mpi.h>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  /**
   * Expand the --batch arguments into case files: a name ending in .prm is a
   * case; any other is a list file with one .prm path per line ('#' starts a
   * comment, relative paths are relative to the list file). Throws a
   * one-line message for an unreadable list or an empty batch.
   */
  std::vector<std::string>
  batch_cases(const std::vector<std::string> &arguments);

  /**
   * Refuses (one line naming both files and the folder) a batch in which
   * two cases write to the same Output/Directory, before any case runs.
   */
  void
  check_batch_output_folders(const std::vector<std::string> &cases);

  /**
   * Run the batch on all ranks of communicator; out and err are used on rank
   * 0 only. Returns the exit code (1 if any case failed: one error line per
   * failed case, and no batch CSV).
   */
  int
  run_batch(const std::vector<std::string> &arguments,
            const MPI_Comm                  communicator,
            std::ostream                   &out,
            std::ostream                   &err);
} // namespace FourierSSI

#endif
