// The program's own parallelism (harmonics in threads, the cell loop on the
// idle core, meshes side by side, MPI ranks) is all the parallelism it
// wants: a CHOLMOD factorization must start no OpenMP threads of its own.
// CHOLMOD's supernodal loops ask for num_threads(4) explicitly, which a
// thread count of one does not override; on 2 cores those threads contended
// with the harmonics and meshes (about 12 000 context switches per rough
// 1e-4 run; doc/accuracy-vs-time.md, "Meshes 0 and 1 side by side").
//
// Checked by counting the process's threads (/proc/self/task): libgomp keeps
// the team of a parallel region alive in the thread that started it, so a
// factorization that went parallel leaves threads behind. Counts are exact,
// so are the checks:
//  - a supernodal factorization (FE_Q(2) Laplacian, 16 641 DoFs: its
//    supernodes are large enough for CHOLMOD's parallel loops) in the main
//    thread after use_serial_blas(): no thread more than before;
//  - the same in a serial_thread(): no thread left after it is joined, and
//    OpenMP's nesting limit there is 0 (read through dlsym: libgomp is the
//    one CHOLMOD loads).
#include "check.h"

#include <chrono>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/numerics/matrix_creator.h>
#include <dlfcn.h>
#include <filesystem>
#include <fourier_ssi/linear_algebra/serial_blas.h>
#include <fourier_ssi/linear_algebra/sparse_direct.h>
#include <fstream>
#include <thread>

using namespace FourierSSI;

namespace
{
  unsigned int
  process_threads()
  {
    unsigned int n = 0;
    for ([[maybe_unused]] const auto &task :
         std::filesystem::directory_iterator("/proc/self/task"))
      ++n;
    return n;
  }

  /** Laplacian + mass (positive definite) of FE_Q(2) on a 64 x 64 square. */
  struct TestMatrix
  {
    Triangulation<2>     mesh;
    FE_Q<2>              fe{2};
    DoFHandler<2>        dofs;
    SparsityPattern      pattern;
    SparseMatrix<double> matrix;

    TestMatrix()
    {
      GridGenerator::hyper_cube(mesh);
      mesh.refine_global(6);
      dofs.reinit(mesh);
      dofs.distribute_dofs(fe);
      DynamicSparsityPattern dsp(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, dsp);
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      MatrixCreator::create_laplace_matrix(dofs, QGauss<2>(3), matrix);
      for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
        matrix.diag_element(i) += 1.;
    }
  };

  /** Factorize and solve once; the solution of A x = A 1 must be 1. */
  double
  factorize_and_solve(const SparseMatrix<double> &A)
  {
    SparseDirect   solver("cholesky");
    Vector<double> ones(A.m()), x(A.m());
    ones = 1.;
    A.vmult(x, ones);
    solver.initialize(A);
    solver.solve(x);
    x -= ones;
    return x.linfty_norm();
  }
} // namespace

int
main()
{
  const TestMatrix test;
  std::cout << "FE_Q(2) Laplacian + mass: " << test.matrix.m() << " DoFs\n";

  use_serial_blas();
  const unsigned int before = process_threads();
  std::cout << "threads before any solve (deal.II's TBB pool among them):";
  for (const auto &task :
       std::filesystem::directory_iterator("/proc/self/task"))
    std::cout << ' ' << std::ifstream(task.path() / "comm").rdbuf();
  std::cout << std::endl;
  const double error = factorize_and_solve(test.matrix);
  check::small("main thread: solution error (round-off)", error, 1e-10);
  check::equal("main thread: threads after the factorization",
               process_threads(),
               before);

  int         nesting = -1;
  std::thread worker  = serial_thread([&]() {
    using GetInt = int (*)();
    if (const auto get = reinterpret_cast<GetInt>(
          dlsym(RTLD_DEFAULT, "omp_get_max_active_levels")))
      nesting = get();
    check::small("serial_thread: solution error (round-off)",
                 factorize_and_solve(test.matrix),
                 1e-10);
    // The worker and nothing else beside the threads there were before.
    check::equal("serial_thread: threads during its work",
                 process_threads(),
                 before + 1);
  });
  worker.join();
  check::equal("serial_thread: OpenMP active levels allowed", nesting, 0);
  // join() returns when the thread has released its stack; the kernel
  // drops its /proc entry a moment later.
  for (unsigned int wait = 0; wait < 100 && process_threads() > before; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  check::equal("threads after the worker is joined", process_threads(), before);
  return check::summary();
}
