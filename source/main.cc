// fourier-ssi: parse the command line and the .prm file, run, report.
// Usage: fourier-ssi [PARAMS.prm]      (default: prm/default.prm)
//        fourier-ssi --print-parameters
#include <deal.II/base/mpi.h>
#include <fourier_ssi/command_line.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return FourierSSI::run_command_line(argc, argv);
}
