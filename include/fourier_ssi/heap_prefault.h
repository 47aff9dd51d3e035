/**
 * Fresh memory for the next mesh, faulted in on an idle core.
 *
 * On the 2-core benchmark machine (a virtual machine) the first touch of
 * memory the process has not used before costs 1.6–2.2 ms per MiB even on
 * huge pages: the host backs the guest's pages on demand. A 487k-DoF member
 * of a Target accuracy design grows the heap by about 1.3 GB, and the
 * kernel's page zeroing was a third of the samples of the rough 1e-6 run
 * (doc/accuracy-vs-time.md, "Fresh memory faulted in on the idle core").
 *
 * HeapPrefault grows the heap by the bytes a mesh is expected to need
 * (glibc's malloc then free: with keep_freed_memory() the block returns to
 * the top of the heap and stays mapped) and, in a thread of its own, asks
 * the kernel to fault that range in (Linux madvise MADV_POPULATE_WRITE,
 * which fills page tables without changing any content). The mesh's own
 * allocations, made meanwhile from the top of the heap, then find their
 * pages present. The contents and the results are the same with or
 * without it; a kernel without MADV_POPULATE_WRITE makes it a no-op.
 */
#ifndef fourier_ssi_heap_prefault_h
#define fourier_ssi_heap_prefault_h

#include <atomic>
#include <cstddef>
#include <thread>

namespace FourierSSI
{
  class HeapPrefault
  {
  public:
    /** Grow the heap by `bytes` and fault them in, in the background. */
    explicit HeapPrefault(const std::size_t bytes);

    /** Stops the background work (what is faulted in stays) and joins. */
    ~HeapPrefault();

    /** Waits until every byte is faulted in. */
    void
    finish();

    HeapPrefault(const HeapPrefault &) = delete;
    HeapPrefault &
    operator=(const HeapPrefault &) = delete;

    /** Bytes glibc's main heap holds, in use or free (mallinfo2().arena). */
    static std::size_t
    heap_bytes();

  private:
    std::atomic<bool> stop{false};
    std::thread       worker;
  };
} // namespace FourierSSI

#endif
