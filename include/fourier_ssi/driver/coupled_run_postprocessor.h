/**
 * The output of a coupled load path as postprocessors (in the manner of
 * ASPECT's Postprocess::Interface and its manager): each one is a small
 * class for one group of rows or one file, asked in turn by the scene run.
 * The phases keep the order of the output: every postprocessor's rows
 * first, then the checks every rank makes before any file is written, then
 * the files.
 */
#ifndef fourier_ssi_coupled_run_postprocessor_h
#define fourier_ssi_coupled_run_postprocessor_h

#include <fourier_ssi/driver/coupled_run_context.h>
#include <memory>
#include <ostream>
#include <vector>

namespace FourierSSI
{
  class CoupledSolver;

  class CoupledRunPostprocessor
  {
  public:
    virtual ~CoupledRunPostprocessor() = default;

    /**
     * Before the load path on the scene's one mesh: observe its converged
     * steps (curves and fields recorded step by step). Not called on
     * nested meshes, whose paths only give the goal value.
     */
    virtual void
    observe(CoupledSolver &solver, const CoupledRunContext &context);

    /** After the path: rows of results.csv, log lines, what is completed. */
    virtual void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log);

    /** On every rank, before any result file: refusals of the output. */
    virtual void
    check(const CoupledSolver &solver, const CoupledRunContext &context) const;

    /** The files (CSV on rank 0 only) and their log lines. */
    virtual void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log);

    /** The solver and the set are released: drop what refers to them. */
    virtual void
    release();
  };

  /** The postprocessors of a run, asked in their order in each phase. */
  class CoupledRunPostprocessors
  {
  public:
    void
    add(std::unique_ptr<CoupledRunPostprocessor> postprocessor);

    void
    observe(CoupledSolver &solver, const CoupledRunContext &context);

    void
    add_rows(const CoupledSolver     &solver,
             const CoupledRunContext &context,
             std::ostream            &log);

    /** check() of each, then write_files() of each. */
    void
    write_files(const CoupledSolver     &solver,
                const CoupledRunContext &context,
                std::ostream            &log);

    void
    release();

  private:
    std::vector<std::unique_ptr<CoupledRunPostprocessor>> postprocessors;
  };
} // namespace FourierSSI

#endif
