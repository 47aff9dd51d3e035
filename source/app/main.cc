// fourier-ssi: the executable; the command-line front end does the work.
// Usage: fourier-ssi [PARAMS.prm]      (default: prm/default.prm)
//        fourier-ssi --help            (every mode and sub-command)
#include <fourier_ssi/app/command_line.h>

int
main(int argc, char **argv)
{
  return FourierSSI::run_command_line(argc, argv);
}
