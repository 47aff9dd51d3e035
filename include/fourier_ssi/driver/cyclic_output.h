/**
 * The loops of a coupled run on a cyclic path (Load path/Targets): their
 * main values as results.csv rows load_cycle_* (the cycle in the cycle
 * column), one log line per cycle and the cycle table load-cycles.csv
 * (postprocess/load_cycles.h; doc/cyclic-loading.md). Nothing on a
 * monotonic path.
 *
 * The loops are those of the controlled motion and its conjugate load
 * under displacement control; under load control of the first of H, M, T,
 * V that the foundation carries, with its motion.
 */
#ifndef fourier_ssi_cyclic_output_h
#define fourier_ssi_cyclic_output_h

#include <fourier_ssi/driver/coupled_run_postprocessor.h>

namespace FourierSSI
{
  class LoadCycleOutput : public CoupledRunPostprocessor
  {
  public:
    /** The results.csv rows (every rank: the steps are everywhere). */
    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log) override;

    /** The log lines and load-cycles.csv (the rank that writes). */
    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;
  };
} // namespace FourierSSI

#endif
