// fourier-ssi: parse the command line and the .prm file, run, report.
// Usage: fourier-ssi [PARAMS.prm]      (default: prm/default.prm)
//        fourier-ssi --print-parameters
#include <fourier_ssi/command_line.h>

int
main(int argc, char **argv)
{
  return FourierSSI::run_command_line(argc, argv);
}
