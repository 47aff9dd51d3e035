#include <cstdlib>
#include <cstring>
#include <fourier_ssi/linear_algebra/huge_page_allocation.h>
#include <limits>
#include <malloc.h>
#include <new>
#include <sys/mman.h>

namespace FourierSSI
{
  namespace
  {
    constexpr std::size_t huge_page = std::size_t(2) << 20;
  }

  void *
  huge_page_malloc(const std::size_t size)
  {
    if (size < huge_page)
      return std::malloc(size);
    const std::size_t rounded = (size + huge_page - 1) / huge_page * huge_page;
    void             *block   = std::aligned_alloc(huge_page, rounded);
#ifdef MADV_HUGEPAGE
    if (block)
      madvise(block, rounded, MADV_HUGEPAGE);
#endif
    return block;
  }

  void *
  huge_page_calloc(const std::size_t count, const std::size_t size)
  {
    if (size != 0 && count > std::size_t(-1) / size)
      return nullptr;
    if (count * size < huge_page)
      return std::calloc(count, size);
    void *block = huge_page_malloc(count * size);
    if (block)
      std::memset(block, 0, count * size);
    return block;
  }

  void
  keep_freed_memory()
  {
    // A block above the mmap threshold (at most 32 MiB in glibc) would be
    // unmapped on free and its pages faulted in again by the next one.
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
  }
} // namespace FourierSSI

// The replaceable global allocation functions of the program (and of the
// deal.II calls it makes): large blocks on huge pages, everything else as
// before. The array, nothrow, sized and aligned forms of the standard
// library forward to these two or free with std::free, which is what a
// block from std::malloc or std::aligned_alloc needs.
void *
operator new(std::size_t size)
{
  void *block = FourierSSI::huge_page_malloc(size == 0 ? 1 : size);
  if (!block)
    throw std::bad_alloc();
  return block;
}

void *
operator new[](std::size_t size)
{
  return ::operator new(size);
}

void
operator delete(void *block) noexcept
{
  std::free(block);
}

void
operator delete[](void *block) noexcept
{
  std::free(block);
}

void
operator delete(void *block, std::size_t) noexcept
{
  std::free(block);
}

void
operator delete[](void *block, std::size_t) noexcept
{
  std::free(block);
}
