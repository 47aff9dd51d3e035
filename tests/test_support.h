// Helpers shared by the fourier-ssi test programs: build parameters from .prm
// text and run the simulator without writing files.
#ifndef fourier_ssi_tests_test_support_h
#define fourier_ssi_tests_test_support_h

#include <deal.II/base/mpi.h>
#include <fourier_ssi/parameters.h>
#include <fourier_ssi/simulator.h>
#include <iostream>
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

  inline FourierSSI::ResultsTable
  run(const std::string &prm_text)
  {
    const FourierSSI::AllParameters parameters = parameters_from(prm_text);
    FourierSSI::Simulator           simulator(parameters);
    return simulator.run(std::cout, /*write_files=*/false);
  }
} // namespace test_support

#endif
