#include <dlfcn.h>
#include <fourier_ssi/serial_blas.h>

namespace FourierSSI
{
  void
  use_serial_blas()
  {
    // Looked up at run time: the BLAS is whichever libblas.so.3 the system
    // selects (Debian's alternatives), and only OpenBLAS has this call.
    using SetThreads = void (*)(int);
    if (const auto openblas = reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      openblas(1);
    if (const auto openmp = reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "omp_set_num_threads")))
      openmp(1);
  }
} // namespace FourierSSI
