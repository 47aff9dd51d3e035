// Run with mpirun -np 2. The same scene on 1 rank (the serial code, UMFPACK,
// on MPI_COMM_SELF: exactly what `fourier-ssi scene.prm` does without mpirun)
// and distributed on 2 ranks (Trilinos matrix; MUMPS and CG + ML AMG) gives
// the same K_H, K_M, K_MH to a relative 1e-8, on scenes whose interface pairs
// straddle the two ranks (counted and required > 0); and, with Q4 and two
// Kelly-adaptive cycles, the same refined meshes (n_dofs) and K per cycle.
//
// Why 1e-8: both answers are exact solutions of the same assembled system up
// to the solver error. For the direct solvers that is roundoff amplified by
// the condition number (with the bundled rough interfaces, kn = 1e10,
// UMFPACK and MUMPS already differ by 4e-9, hence kn = ks = 1e8 here); for CG
// it is the residual tolerance, set to 1e-12 below, times the condition of the
// K(u) map. 1e-8 is well above both (the runs agree to ~1e-11) and still
// catches a wrongly assembled straddling pair: assembling those pairs on both
// ranks (each spring counted twice) moves K by 5e-7 to 2e-5 here, although
// kn = 1e8 interfaces are nearly rigid; a dropped pair moves it far more.
#include <check.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <test_support.h>
#include <two_ranks.h>

using namespace FourierSSI;

namespace
{
  /** extra: more subsections (a later one wins); 1 cycle unless changed. */
  std::string
  scene(const std::string &bundled,
        const std::string &method,
        const std::string &extra = "")
  {
    return test_support::bundled_prm(bundled) +
           "subsection Discretization\n"
           "  set Refinement cycles = 1\n"
           "end\n" +
           extra +
           "subsection Interfaces\n"
           "  set Interfaces = 5: kn=1e8, ks=1e8\n"
           "end\n"
           "subsection Linear solver\n"
           "  set Method    = " +
           method +
           "\n"
           "  set Tolerance = 1e-12\n"
           "end\n";
  }

  void
  compare(const std::string &bundled,
          const std::string &method,
          const std::string &extra    = "",
          const unsigned int n_cycles = 1)
  {
    const MPI_Comm      world      = MPI_COMM_WORLD;
    const std::string   text       = scene(bundled, method, extra);
    const AllParameters parameters = test_support::parameters_from(text);

    // Interface pairs straddling the ranks: the case this test is about.
    Triangulation<2> triangulation;
    build_mesh(parameters.mesh, triangulation);
    HarmonicProblem problem(parameters,
                            Harmonic{1, Family::symmetric},
                            triangulation,
                            nullptr,
                            world);
    problem.setup_system();
    const unsigned int n_pairs = problem.get_interfaces()->get_pairs().size();
    const unsigned int n_straddling =
      problem.get_distributed()->n_straddling_pairs();

    // The simulator's log is not this test's output: silent in both runs.
    std::ostream silent(nullptr);
    const auto [serial, distributed] = two_ranks::serial_and_distributed(
      [&](const bool distribute, std::ostream &) {
        return Simulator(parameters, distribute ? world : MPI_COMM_SELF)
          .run(silent, false);
      });
    // Rank 0 checks; a missing result must fail the test, not leave rank 1
    // waiting in the final broadcast.
    if (two_ranks::is_root())
      try
        {
          std::cout << bundled << ", " << method
                    << (extra.empty() ? "" : ", Q4, Kelly") << ": "
                    << n_straddling << " of " << n_pairs
                    << " interface pairs straddle the 2 ranks" << std::endl;
          check::in_range("interface pairs straddling ranks",
                          n_straddling,
                          1,
                          n_pairs);
          const Harmonic h{1, Family::symmetric};
          for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
            {
              check::relative("cycle " + std::to_string(cycle) +
                                ": n_dofs on 2 ranks vs 1",
                              distributed.get("n_dofs", h, cycle),
                              serial.get("n_dofs", h, cycle),
                              0.);
              for (const std::string k : {"K_H", "K_M", "K_MH"})
                check::relative("cycle " + std::to_string(cycle) + ": " + k +
                                  " on 2 ranks vs 1",
                                distributed.get(k, h, cycle),
                                serial.get(k, h, cycle),
                                1e-8);
            }
        }
      catch (const std::exception &e)
        {
          check::that(std::string("results present: ") + e.what(), false);
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  return two_ranks::run(argc, argv, [] {
    for (const std::string method : {"direct", "cg-amg"})
      {
        compare("prm/embedded-footing.prm", method);
        compare("prm/pile.prm", method);
      }
    // Hanging-node constraints across ranks and the replicated Kelly
    // indicator: Q4, two adaptive cycles, the same meshes and K.
    compare("prm/embedded-footing.prm",
            "direct",
            "subsection Discretization\n"
            "  set Refinement cycles = 2\n"
            "  set Polynomial degree = 4\n"
            "end\n"
            "subsection Adaptivity\n"
            "  set Strategy = kelly\n"
            "end\n",
            2);
  });
}
