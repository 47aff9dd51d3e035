/**
 * The command-line front end of the fourier-ssi executable (not part of the
 * library): runs a scene, a batch, or one of the sub-commands
 * --print-parameters and --interface-matrix.
 */
#ifndef fourier_ssi_command_line_h
#define fourier_ssi_command_line_h

namespace FourierSSI
{
  /**
   * Run the program; returns the process exit code. Errors are printed as
   * one line "fourier-ssi: error: <file>: <entry>: <what>" with exit code 1.
   */
  int
  run_command_line(int argc, char **argv);
} // namespace FourierSSI

#endif
