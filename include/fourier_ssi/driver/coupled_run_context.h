/**
 * What a coupled scene run and its postprocessors work on: the run's
 * parameters, the current mesh and plan, the harmonic set of the last load
 * path, and the results and files the run writes. References into the
 * Simulator that owns them, so that a run is handed only these, not the
 * whole simulator.
 */
#ifndef fourier_ssi_coupled_run_context_h
#define fourier_ssi_coupled_run_context_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/driver/result_files.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/postprocess/field_reconstruction.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <memory>

namespace FourierSSI
{
  struct CoupledRunContext
  {
    const AllParameters    &parameters;
    const MPI_Comm          communicator;
    const Triangulation<2> &triangulation;
    /** Its harmonics change where a target studies the truncation. */
    const ScenePlan &plan;
    /** The set of the last load path (null once released). */
    std::unique_ptr<HarmonicSet> &harmonic_set;
    ResultsTable                 &results;
    ResultFiles                  &result_files;
    /** The last converged step summed in 3D. */
    FieldReconstruction &reconstruction;
    /** This rank writes the CSV files (rank 0 of a run that writes). */
    const bool writes_csv;
  };
} // namespace FourierSSI

#endif
