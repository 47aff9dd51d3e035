/**
 * The driver: .prm parameters -> mesh -> scene plan (the harmonics the loads
 * need, the effects to simulate) -> for each refinement cycle, the harmonics
 * as independent HarmonicProblems solved concurrently -> results (CSV, VTU,
 * 3D reconstruction of the last cycle). Files are
 * written only for a run that succeeded; a failure removes what this run
 * wrote, so nothing partial is left looking like a result.
 */
#ifndef fourier_ssi_simulator_h
#define fourier_ssi_simulator_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/field_reconstruction.h>
#include <fourier_ssi/parameters.h>
#include <fourier_ssi/results_table.h>
#include <ostream>

namespace FourierSSI
{
  class Simulator
  {
  public:
    /**
     * On a communicator of more than one rank each harmonic's linear system
     * is distributed (the mesh and postprocessing are replicated); only rank
     * 0 writes the CSV files, every rank its piece of the VTU output.
     */
    explicit Simulator(const AllParameters &parameters,
                       const MPI_Comm       communicator = MPI_COMM_SELF);

    /** Run everything; returns the scalar results (also written as CSV). */
    ResultsTable
    run(std::ostream &log, const bool write_files = true);

    /** The harmonics of the last cycle, summed in 3D (after run()). */
    const FieldReconstruction &
    get_reconstruction() const
    {
      return reconstruction;
    }

    /** The mesh of the last cycle (after run()). */
    const Triangulation<2> &
    get_triangulation() const
    {
      return triangulation;
    }

  private:
    const AllParameters &parameters;
    const MPI_Comm       communicator;
    /** Owned here: the reconstruction's DoF handlers live on it. */
    Triangulation<2>    triangulation;
    FieldReconstruction reconstruction;
  };
} // namespace FourierSSI

#endif
