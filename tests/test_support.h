// Helpers shared by the fourier-ssi test programs: build parameters from .prm
// text and run the simulator without writing files.
#ifndef fourier_ssi_tests_test_support_h
#define fourier_ssi_tests_test_support_h

#include <deal.II/base/mpi.h>
#include <fourier_ssi/parameters.h>
#include <fourier_ssi/simulator.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace test_support
{
  inline FourierSSI::AllParameters
  parameters_from(const std::string &prm_text)
  {
    FourierSSI::AllParameters parameters;
    parameters.read_string(prm_text);
    return parameters;
  }

  /** Text of a bundled parameter file, path relative to the project root. */
  inline std::string
  bundled_prm(const std::string &relative_path)
  {
    std::ifstream in(std::string(FSSI_SOURCE_DIR) + "/" + relative_path);
    if (!in)
      throw std::runtime_error("cannot open " + relative_path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  inline FourierSSI::ResultsTable
  run(const std::string &prm_text)
  {
    const FourierSSI::AllParameters parameters = parameters_from(prm_text);
    FourierSSI::Simulator           simulator(parameters);
    return simulator.run(std::cout, /*write_files=*/false);
  }
} // namespace test_support

#endif
