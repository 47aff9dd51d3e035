/**
 * The state of the nonlinear interfaces along a load path, as
 * postprocessors (coupled_run_postprocessor.h): interface-state.csv (point x
 * theta x step) and the revolved interface surfaces of chosen steps.
 */
#ifndef fourier_ssi_interface_state_output_h
#define fourier_ssi_interface_state_output_h

#include <fourier_ssi/driver/coupled_run_postprocessor.h>
#include <string>

namespace FourierSSI
{
  /** interface-state.csv, where the scene has nonlinear interfaces. */
  class InterfaceStateCsv : public CoupledRunPostprocessor
  {
  public:
    /** `description`: what the log line calls the file's content. */
    explicit InterfaceStateCsv(const std::string &description);

    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;

  private:
    const std::string description;
  };

  /**
   * Output/Write 3d vtu: the interface points of the last step in 3D
   * (interface-state-3d.vtu); Output/Interface state 3D: the chosen steps'
   * revolved interface surfaces, their .pvd series and one log line.
   */
  class InterfaceState3d : public CoupledRunPostprocessor
  {
  public:
    /**
     * Output/Interface state steps beyond the path: one line, on every
     * rank, before any result file is written.
     */
    void
    check(const CoupledSolver     &solver,
          const CoupledRunContext &context) const override;

    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log) override;

  private:
    void
    write_surfaces(const CoupledSolver     &solver,
                   const CoupledRunContext &context,
                   std::ostream            &log) const;
  };
} // namespace FourierSSI

#endif
