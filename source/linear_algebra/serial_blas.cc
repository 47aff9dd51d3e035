#include <dlfcn.h>
#include <fourier_ssi/linear_algebra/serial_blas.h>

namespace FourierSSI
{
  namespace
  {
    /** A function of the loaded libraries by name, or null. */
    template <typename Function>
    Function
    find(const char *name)
    {
      return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
    }
  } // namespace

  void
  use_serial_blas()
  {
    // Looked up at run time: the BLAS is whichever libblas.so.3 the system
    // selects (Debian's alternatives), and only OpenBLAS has these calls.
    if (const auto set = find<void (*)(int)>("openblas_set_num_threads"))
      set(1);
    // With one thread OpenBLAS never hands work to its pool; a call that
    // asks for more threads later starts it again.
    if (const auto stop = find<int (*)()>("blas_thread_shutdown_"))
      stop();
    use_serial_openmp_in_this_thread();
  }

  void
  use_serial_openmp_in_this_thread()
  {
    // CHOLMOD's supernodal loops ask for num_threads(4) explicitly
    // (CHOLMOD_OMP_NUM_THREADS, cholmod_core.h), which overrides the thread
    // count; with no active parallel level allowed every region runs on
    // the thread that meets it.
    static const auto set_threads = find<void (*)(int)>("omp_set_num_threads");
    static const auto set_levels =
      find<void (*)(int)>("omp_set_max_active_levels");
    if (set_threads)
      set_threads(1);
    if (set_levels)
      set_levels(0);
  }

  std::thread
  serial_thread(std::function<void()> work)
  {
    return std::thread([work = std::move(work)]() {
      use_serial_openmp_in_this_thread();
      work();
    });
  }
} // namespace FourierSSI
