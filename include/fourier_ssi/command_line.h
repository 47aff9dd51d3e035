/** The command-line front end of the fourier-ssi executable. */
#ifndef fourier_ssi_command_line_h
#define fourier_ssi_command_line_h

#include <string>

namespace FourierSSI
{
  /**
   * Run the program; returns the process exit code. Errors are printed as
   * one line "fourier-ssi: error: <file>: <entry>: <what>" with exit code 1.
   */
  int
  run_command_line(int argc, char **argv);

  /** The essential text of an exception, on one line. */
  std::string
  one_line_message(const std::exception &e);
} // namespace FourierSSI

#endif
