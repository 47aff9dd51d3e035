/**
 * The loops of a coupled run on a cyclic path (Load path/Targets): the
 * cycle table load-cycles.csv, its main values as results.csv rows
 * load_cycle_* (the cycle in the cycle column) and one log line per cycle
 * (postprocess/load_cycles.h; doc/cyclic-loading.md).
 */
#ifndef fourier_ssi_cyclic_output_h
#define fourier_ssi_cyclic_output_h

#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/driver/result_files.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <ostream>

namespace FourierSSI
{
  /**
   * Nothing on a monotonic path. The loops are those of the controlled
   * motion and its conjugate load under displacement control; under load
   * control of the first of H, M, T, V that the foundation carries, with
   * its motion.
   */
  void
  write_cyclic_output(const CoupledSolver &solver,
                      const AllParameters &parameters,
                      ResultFiles         &files,
                      ResultsTable        &results,
                      std::ostream        &log);
} // namespace FourierSSI

#endif
