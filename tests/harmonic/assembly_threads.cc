// The cell loop of the assembly on several threads (assembly_loop.h) gives
// the same matrix and load, bit for bit, as on one: the cells go in fixed
// chunks, each chunk on an FEValues of its own, and are added in cell order.
// Checked on the bundled embedded footing (FE_Q(4), graded toward the
// footing edges: hanging nodes, interface pairs and rigid-foundation
// constraints) with a body force, so the cell loads count too, and on
// FE_Q(2). Exact equality is the claim, so the tolerance is zero: a
// chunk-free loop (one FEValues per thread, whose cell-similarity shortcut
// then depends on which cells a thread saw) differs in the last bit.
#include "check.h"
#include "test_support.h"

#include <cstring>
#include <fourier_ssi/mesh/adaptivity.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>

using namespace FourierSSI;

namespace
{
  struct Assembled
  {
    std::vector<double> matrix;
    std::vector<double> rhs;
  };

  Assembled
  assemble(const std::string &prm_text, const unsigned int threads)
  {
    const AllParameters parameters = test_support::parameters_from(prm_text);
    Triangulation<2>    triangulation;
    test_support::build_refined_mesh(parameters, triangulation);
    HarmonicProblem problem(parameters,
                            Harmonic{1, Family::symmetric},
                            triangulation);
    problem.set_assembly_threads(threads);
    problem.setup_system();
    problem.assemble_system();
    Assembled                   a;
    const SparseMatrix<double> &A = problem.get_system_matrix();
    for (unsigned int i = 0; i < A.m(); ++i)
      for (auto entry = A.begin(i); entry != A.end(i); ++entry)
        a.matrix.push_back(entry->value());
    const Vector<double> &b = problem.get_system_rhs();
    a.rhs.assign(b.begin(), b.end());
    return a;
  }

  /** Entries that differ in any bit. */
  unsigned int
  n_different(const std::vector<double> &x, const std::vector<double> &y)
  {
    if (x.size() != y.size())
      return std::max(x.size(), y.size());
    unsigned int n = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      n += std::memcmp(&x[i], &y[i], sizeof(double)) != 0;
    return n;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {2u, 4u})
    {
      const std::string scene =
        test_support::footing_one_cycle(degree) +
        "subsection Body force\n set Radial = 1\n set Axial = 0.5 * r\n"
        " set Circumferential = 2\nend\n";
      const Assembled one = assemble(scene, 1);
      std::cout << "FE_Q(" << degree << "): " << one.matrix.size()
                << " matrix entries, " << one.rhs.size() << " DoFs"
                << std::endl;
      for (const unsigned int threads : {2u, 3u})
        {
          const Assembled   many = assemble(scene, threads);
          const std::string at   = "FE_Q(" + std::to_string(degree) + "), " +
                                 std::to_string(threads) + " threads vs 1";
          check::equal("matrix entries that differ, " + at,
                       n_different(one.matrix, many.matrix),
                       0);
          check::equal("load entries that differ, " + at,
                       n_different(one.rhs, many.rhs),
                       0);
        }
    }
  return check::summary();
}
