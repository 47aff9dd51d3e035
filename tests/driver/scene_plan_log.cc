// The log says what a scene simulates (doc/loads.md): a rigid surface
// footing pushed by V only lists n = 0 symmetric and nothing else, says that
// every other harmonic was skipped and why, and does no interface assembly
// (none declared); the same footing with an interface declared says it
// assembles it. Also: Harmonics = auto on a scene without any load, and
// amplitude expressions that cannot be attributed to harmonics, stop with a
// one-line error.
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/driver/simulator.h>
#include <regex>

using namespace FourierSSI;

namespace
{
  const std::string footing =
    "subsection Discretization\n set Harmonics = auto\nend\n"
    "subsection Mesh\n set R breakpoints = 0, 1, 10\n set R cells = 4, 6\n"
    " set R growth = 1, 1.2\n"
    " set Z breakpoints = -10, -1, 0\n set Z cells = 6, 2\n set Z growth = 0.8, 1\n"
    " set Surface patch radius = 1\nend\n"
    "subsection Materials\n set Materials = 0: G=1000, nu=0.3\nend\n"
    "subsection Boundary conditions\n"
    " set Dirichlet = 1: u=0, v=0, w=0; 2: u=0, v=0, w=0\nend\n"
    "subsection Output\n set Write vtu = false\nend\n";

  std::string
  log_of(const std::string &prm)
  {
    const AllParameters parameters = test_support::parameters_from(prm);
    Simulator           simulator(parameters);
    std::ostringstream  log;
    simulator.run(log, false);
    std::cout << log.str();
    return log.str();
  }

  bool
  contains(const std::string &text, const std::string &pattern)
  {
    return std::regex_search(text, std::regex(pattern));
  }

  std::string
  error_of(const std::string &prm)
  {
    try
      {
        log_of(prm);
      }
    catch (const std::exception &e)
      {
        std::cout << "  error: " << one_line_message(e) << std::endl;
        return one_line_message(e);
      }
    return "";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                v_only =
    footing + "subsection Rigid foundation\n set Enabled = true\n"
              " set Tie = boundary\n set Id = 4\n set Vertical force = 100\n"
              "end\n";
  const std::string log = log_of(v_only);
  check::that("lists n = 0 symmetric, pushed by V",
              contains(log, "\n    n=0 symmetric: V\n"));
  check::that("solves n = 0 symmetric only",
              contains(log, "cycle 0, n=0 symmetric") &&
                !contains(log, "cycle 0, n=[1-9]") &&
                !contains(log, "cycle 0, n=0 antisymmetric"));
  check::that("says n = 1..32 symmetric were skipped",
              contains(log, "skipped symmetric n = 1\\.\\.32: no load"));
  check::that("says n = 0..32 antisymmetric were skipped",
              contains(log, "skipped antisymmetric n = 0\\.\\.32: no load"));
  check::that("no interface assembly",
              contains(log,
                       "interfaces: none declared, no interface "
                       "assembly"));
  check::that("no stiffness extraction asked",
              contains(log, "stiffness coefficients: skipped"));

  const std::string with_interface =
    v_only + "subsection Mesh\n set Interface lines = 5: z=-1, r=0..1\nend\n"
             "subsection Interfaces\n set Interfaces = 5: rough\nend\n";
  check::that("an interface, when declared, is assembled",
              contains(log_of(with_interface),
                       "interfaces: assembled on boundary ids 5"));

  check::that("auto without load: one-line error",
              contains(error_of(footing), "no load .*nothing to solve"));
  check::that(
    "auto with a harmonic amplitude expression: one-line error",
    contains(error_of(footing + "subsection Boundary conditions\n"
                                " set Traction = 4: z = -1\nend\n"),
             "Boundary conditions/Traction: '-1' is a harmonic amplitude"));
  return check::summary();
}
