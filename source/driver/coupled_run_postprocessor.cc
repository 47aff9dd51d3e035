#include <fourier_ssi/driver/coupled_run_postprocessor.h>
#include <utility>

namespace FourierSSI
{
  void
  CoupledRunPostprocessor::observe(CoupledSolver &, const CoupledRunContext &)
  {}

  void
  CoupledRunPostprocessor::add_rows(const CoupledSolver &,
                                    const CoupledRunContext &,
                                    std::ostream &)
  {}

  void
  CoupledRunPostprocessor::check(const CoupledSolver &,
                                 const CoupledRunContext &) const
  {}

  void
  CoupledRunPostprocessor::write_files(const CoupledSolver &,
                                       const CoupledRunContext &,
                                       std::ostream &)
  {}

  void
  CoupledRunPostprocessor::release()
  {}

  void
  CoupledRunPostprocessors::add(
    std::unique_ptr<CoupledRunPostprocessor> postprocessor)
  {
    postprocessors.push_back(std::move(postprocessor));
  }

  void
  CoupledRunPostprocessors::observe(CoupledSolver           &solver,
                                    const CoupledRunContext &context)
  {
    for (const auto &p : postprocessors)
      p->observe(solver, context);
  }

  void
  CoupledRunPostprocessors::add_rows(const CoupledSolver     &solver,
                                     const CoupledRunContext &context,
                                     std::ostream            &log)
  {
    for (const auto &p : postprocessors)
      p->add_rows(solver, context, log);
  }

  void
  CoupledRunPostprocessors::write_files(const CoupledSolver     &solver,
                                        const CoupledRunContext &context,
                                        std::ostream            &log)
  {
    for (const auto &p : postprocessors)
      p->check(solver, context);
    for (const auto &p : postprocessors)
      p->write_files(solver, context, log);
  }

  void
  CoupledRunPostprocessors::release()
  {
    for (const auto &p : postprocessors)
      p->release();
  }
} // namespace FourierSSI
