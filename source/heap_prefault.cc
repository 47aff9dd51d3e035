#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fourier_ssi/heap_prefault.h>
#include <fourier_ssi/huge_page_allocation.h>
#include <fourier_ssi/serial_blas.h>
#include <malloc.h>
#include <sys/mman.h>

namespace FourierSSI
{
  namespace
  {
    constexpr std::uintptr_t huge_page = std::uintptr_t(2) << 20;
    // Faulted in piece by piece: the kernel holds the process's memory-map
    // lock for a piece, and the main thread's madvise and brk calls wait for
    // it (64 MiB pieces tripled the setup of a 487k-DoF mesh).
    constexpr std::uintptr_t piece = huge_page;
  } // namespace

  HeapPrefault::HeapPrefault(const std::size_t bytes)
  {
#ifdef MADV_POPULATE_WRITE
    // Without keep_freed_memory() the freed block could be unmapped or
    // trimmed, and the range would no longer be the heap's.
    if (bytes < huge_page || !freed_memory_kept())
      return;
    // malloc then free: the block, taken from the top of the heap, goes
    // back to it and (trimming off, keep_freed_memory()) stays mapped, so
    // the next allocations are carved from this very range.
    void *block = std::malloc(bytes);
    if (!block)
      return;
    const auto start = reinterpret_cast<std::uintptr_t>(block);
    std::free(block);
    const std::uintptr_t first = (start + huge_page - 1) & ~(huge_page - 1);
    const std::uintptr_t end   = (start + bytes) & ~(huge_page - 1);
    if (end <= first)
      return;
    // Failures are harmless: the pages are then faulted in on use.
    madvise(reinterpret_cast<void *>(first), end - first, MADV_HUGEPAGE);
    worker = serial_thread([this, first, end]() {
      for (std::uintptr_t at = first; at < end && !stop; at += piece)
        madvise(reinterpret_cast<void *>(at), piece, MADV_POPULATE_WRITE);
    });
#else
    (void)bytes;
#endif
  }

  HeapPrefault::~HeapPrefault()
  {
    stop = true;
    if (worker.joinable())
      worker.join();
  }

  void
  HeapPrefault::finish()
  {
    if (worker.joinable())
      worker.join();
  }

  std::size_t
  HeapPrefault::heap_bytes()
  {
    return mallinfo2().arena;
  }
} // namespace FourierSSI
