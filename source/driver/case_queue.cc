#include <fourier_ssi/driver/case_queue.h>

namespace FourierSSI
{
  CaseQueue::CaseQueue(const MPI_Comm communicator, const unsigned int n_cases)
    : n_cases(n_cases)
  {
    int r = 0;
    MPI_Comm_rank(communicator, &r);
    MPI_Comm_size(communicator, &n_ranks);
    next_in_turn = r;
    if (n_ranks == 1)
      return;
    MPI_Comm_split_type(
      communicator, MPI_COMM_TYPE_SHARED, r, MPI_INFO_NULL, &node);
    int node_size = 0;
    MPI_Comm_size(node, &node_size);
    if (node_size != n_ranks)
      return; // several nodes: dealt in turn
    long *base = nullptr;
    MPI_Win_allocate_shared(r == 0 ? sizeof(long) : 0,
                            sizeof(long),
                            MPI_INFO_NULL,
                            node,
                            &base,
                            &window);
    MPI_Aint size         = 0;
    int      displacement = 0;
    MPI_Win_shared_query(window, 0, &size, &displacement, &counter);
    if (r == 0)
      __atomic_store_n(counter, 0L, __ATOMIC_SEQ_CST);
    MPI_Barrier(node); // the counter is set before any rank takes a case
  }

  CaseQueue::~CaseQueue()
  {
    if (window != MPI_WIN_NULL)
      MPI_Win_free(&window);
    if (node != MPI_COMM_NULL)
      MPI_Comm_free(&node);
  }

  unsigned int
  CaseQueue::next()
  {
    if (counter)
      {
        const long c = __atomic_fetch_add(counter, 1L, __ATOMIC_SEQ_CST);
        return c < static_cast<long>(n_cases) ? static_cast<unsigned int>(c) :
                                                n_cases;
      }
    const unsigned int c = next_in_turn;
    next_in_turn += n_ranks;
    return c < n_cases ? c : n_cases;
  }
} // namespace FourierSSI
