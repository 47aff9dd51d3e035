// Discretization/Target accuracy solves meshes 0 and 1 of its design side by
// side when the harmonics leave cores idle (Simulator::solve_two_members,
// doc/accuracy-vs-time.md "Meshes 0 and 1 side by side"). The cores must
// change the wall time only: the embedded footing of the accuracy benchmark
// (rough, alpha = 0.5; one stiffness harmonic) on 2 cores gives the same
// results.csv rows, bit for bit, as on 1 core (the assembly's sum does not
// depend on its thread count, tests/harmonic/assembly_threads.cc), in the same
// order, and the same log apart from the timings and the side-by-side line. The
// same at target 2e-6, where mesh 2 follows the pair in sequence. With
// Adaptivity/Maximum DoFs between the sizes of meshes 0 and 1 the pair is not
// started, and both runs stop after mesh 0 with the same one-line message.
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/linear_algebra/huge_page_allocation.h>
#include <regex>

using namespace FourierSSI;

namespace
{
  /**
   * prm/embedded-footing-graded.prm at its mesh 0 (FE_Q(2), no point
   * refinement) with Target accuracy = 1e-4: the design starts there.
   */
  std::string
  footing_scene()
  {
    return test_support::bundled_prm("prm/embedded-footing-graded.prm",
                                     {{"Polynomial degree", "2"},
                                      {"Refinement cycles", "1"},
                                      {"Point refinement", ""},
                                      {"Write vtu", "false"}}) +
           test_support::entries("Discretization",
                                 {{"Target accuracy", "1e-4"}});
  }

  struct Run
  {
    std::string  log;
    ResultsTable results;
    std::string  unmet;
  };

  Run
  run_on(const std::string &prm, const unsigned int cores)
  {
    const AllParameters parameters = test_support::parameters_from(prm);
    Simulator           simulator(parameters);
    simulator.set_cores(cores);
    std::ostringstream log;
    Run                run;
    run.results = simulator.run(log, false);
    run.log     = log.str();
    run.unmet   = simulator.unmet_target();
    return run;
  }

  /** The log without wall times and the side-by-side line. */
  std::string
  without_timings(const std::string &log)
  {
    std::string text =
      std::regex_replace(log, std::regex("meshes 0 and 1 [^\n]*\n"), "");
    return std::regex_replace(text,
                              std::regex("summary: ([0-9]+ dofs)[^\n]*"),
                              "summary: $1");
  }

  /** Every row but the time_* ones, bit for bit and in the same order. */
  void
  check_same_rows(const ResultsTable &sequential,
                  const ResultsTable &side_by_side)
  {
    std::vector<ResultRow> a, b;
    for (const ResultRow &row : sequential.rows())
      if (row.quantity.rfind("time_", 0) != 0)
        a.push_back(row);
    for (const ResultRow &row : side_by_side.rows())
      if (row.quantity.rfind("time_", 0) != 0)
        b.push_back(row);
    check::equal("result rows (time_* left out)", b.size(), a.size());
    unsigned int differing = 0;
    for (unsigned int i = 0; i < std::min(a.size(), b.size()); ++i)
      if (a[i].quantity != b[i].quantity || a[i].cycle != b[i].cycle ||
          a[i].harmonic.name() != b[i].harmonic.name() ||
          !(a[i].value == b[i].value ||
            (a[i].value != a[i].value && b[i].value != b[i].value)))
        {
          if (differing++ < 5)
            std::cout << "    differs: " << a[i].quantity << " cycle "
                      << a[i].cycle << ": " << std::setprecision(17)
                      << a[i].value << " vs " << b[i].quantity << " "
                      << b[i].value << std::endl;
        }
    check::equal("rows differing in name, cycle or value", differing, 0);
  }
} // namespace

int
main()
{
  // As the program does (command_line.cc): the heap keeps freed memory.
  keep_freed_memory();
  std::cout << "Target 1e-4, 1 core (one mesh after the other) and 2 cores "
               "(meshes 0 and 1 side by side)"
            << std::endl;
  const std::string footing = footing_scene();
  const Run         one     = run_on(footing, 1);
  const Run         two     = run_on(footing, 2);
  std::cout << two.log;
  check::that("1 core: meshes solved one after the other",
              one.log.find("side by side") == std::string::npos);
  check::that("2 cores: meshes 0 and 1 side by side",
              two.log.find("meshes 0 and 1 of the design solved side by "
                           "side on 1 + 1 cores") != std::string::npos);
  check::that("both reach the target", one.unmet.empty() && two.unmet.empty());
  check_same_rows(one.results, two.results);
  check::that("same log apart from timings",
              without_timings(one.log) == without_timings(two.log));
  // A K that a mesh left out, or the meshes collected in the wrong order,
  // would change the estimate: it is the difference of meshes 0 and 1.
  check::in_range("K_M error bar (2 cores), from meshes 0 and 1",
                  two.results.get("K_M_error",
                                  Harmonic{1, Family::symmetric},
                                  1),
                  1e-6,
                  1e-4);

  std::cout << "\nTarget 2e-6: mesh 2 (147 990 DoFs) after the pair, in "
               "sequence"
            << std::endl;
  const std::string finer = footing + "subsection Discretization\n set Target "
                                      "accuracy = 2e-6\nend\n";
  const Run         one_finer = run_on(finer, 1);
  const Run         two_finer = run_on(finer, 2);
  check::that("both stop at mesh 2",
              one_finer.log.find("mesh 2, 147990 DoFs") != std::string::npos &&
                two_finer.log.find("mesh 2, 147990 DoFs") !=
                  std::string::npos &&
                two_finer.log.find("mesh 3") == std::string::npos);
  check_same_rows(one_finer.results, two_finer.results);
  check::that("same log apart from timings",
              without_timings(one_finer.log) == without_timings(two_finer.log));

  std::cout << "\nAdaptivity/Maximum DoFs = 4e4 (mesh 0: 22 542 DoFs, mesh "
               "1: 53 010): no pair, one mesh, the same unmet line"
            << std::endl;
  const std::string limited =
    footing + "subsection Adaptivity\n set Maximum DoFs = 4e4\n set Allow "
              "unconverged = true\nend\n";
  const Run one_limited = run_on(limited, 1);
  const Run two_limited = run_on(limited, 2);
  std::cout << two_limited.unmet << std::endl;
  check::that("2 cores: no pair under the limit",
              two_limited.log.find("side by side") == std::string::npos);
  check::that("the same unmet line on 1 and 2 cores",
              !one_limited.unmet.empty() &&
                one_limited.unmet == two_limited.unmet);
  check_same_rows(one_limited.results, two_limited.results);
  return check::summary();
}
