/**
 * Which case of a batch a rank solves next.
 *
 * The cases of a sweep differ in cost by up to 50× (one or four nested
 * meshes, 22k to 489k DoFs). Dealt in turn (case c to rank c mod N), one
 * rank could stand idle while the other finished the large cases: 25 s of
 * the 137 s pile sweep on 2 ranks (doc/accuracy-vs-time.md, "What is
 * left"). When all ranks share one node, a counter in an MPI shared-memory
 * window hands each rank the next case as soon as it is free; across nodes
 * the cases are dealt in turn as before. Which rank solves a case does not
 * change its results (each runs on MPI_COMM_SELF).
 */
#ifndef fourier_ssi_case_queue_h
#define fourier_ssi_case_queue_h

#include <mpi.h>

namespace FourierSSI
{
  class CaseQueue
  {
  public:
    /** Collective over `communicator`. */
    CaseQueue(const MPI_Comm communicator, const unsigned int n_cases);

    /** Collective: every rank calls it once next() has returned n_cases. */
    ~CaseQueue();

    CaseQueue(const CaseQueue &) = delete;
    CaseQueue &
    operator=(const CaseQueue &) = delete;

    /** The next case for this rank, or n_cases when none is left. */
    unsigned int
    next();

    /** True if the cases go to whichever rank is free (one node). */
    bool
    shared() const
    {
      return counter != nullptr;
    }

  private:
    const unsigned int n_cases;
    int                n_ranks = 1;
    /** Dealt in turn: this rank's next case. */
    unsigned int next_in_turn = 0;
    MPI_Comm     node         = MPI_COMM_NULL;
    MPI_Win      window       = MPI_WIN_NULL;
    long        *counter      = nullptr;
  };
} // namespace FourierSSI

#endif
