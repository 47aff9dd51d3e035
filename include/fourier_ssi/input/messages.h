/**
 * User-facing error text: every error of a run is reported as one line
 * "file: entry: what" (the library's AssertThrow messages), whichever part
 * of the program reports it (the command line, a batch case, a harmonic
 * solved on a worker thread).
 */
#ifndef fourier_ssi_messages_h
#define fourier_ssi_messages_h

#include <exception>
#include <string>

namespace FourierSSI
{
  /**
   * The essential text of an exception, on one line: for a deal.II
   * exception only its ExcMessage text, without the file/line/stacktrace
   * boilerplate.
   */
  std::string
  one_line_message(const std::exception &e);
} // namespace FourierSSI

#endif
