/**
 * A run's memory, estimated before anything is assembled, against the
 * machine's free memory: a run that cannot fit stops with one line giving
 * the estimate and the entry that drives it, instead of swapping for
 * minutes or ending in std::bad_alloc. The estimate is a model with
 * measured constants (the sources in memory_estimate.cc), meant to be right
 * within a factor of about two, which is enough to tell a typo (Theta
 * samples = 8192 on a fine mesh, terabytes) from a run that fits.
 */
#ifndef fourier_ssi_memory_estimate_h
#define fourier_ssi_memory_estimate_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/input/parameters.h>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  /** The estimated peak memory of a run and what it is made of. */
  struct MemoryEstimate
  {
    /** Bytes in total. */
    double bytes = 0.;
    /** The .prm entry of the largest part, and that part in words. */
    std::string driving_entry;
    std::string largest_part;
  };

  /**
   * The run's peak memory on its first mesh: the program itself, the
   * factorizations held at the same time (every harmonic's in a coupled
   * run), the coupled tangent over all harmonics (plastic soil, Stiffness =
   * tangent), and the coupled state, theta samples times the soil's
   * quadrature points.
   */
  MemoryEstimate
  estimate_run_memory(const AllParameters    &parameters,
                      const Triangulation<2> &triangulation,
                      const ScenePlan        &plan);

  /**
   * MemAvailable of /proc/meminfo in bytes (what can be allocated without
   * swapping); 0 where it cannot be read (no check then).
   */
  double
  available_memory();

  /**
   * The smallest available_memory() over the ranks of `communicator` (the
   * value itself without MPI): every rank takes the same decision with it.
   * Collective.
   */
  double
  available_memory_on_all_ranks(const MPI_Comm communicator);

  /**
   * Why a run of `estimate` cannot fit in `available` (> 0), on one line
   * naming the driving entry; empty if it fits or `available` is unknown.
   */
  std::string
  memory_shortfall(const MemoryEstimate &estimate, const double available);

  /**
   * The log line of a large estimate (1 GB or more), with its largest part
   * and the free memory `available` (unknown if 0): a legal run that will
   * take much memory says so before it starts. Empty below 1 GB.
   */
  std::string
  describe_large_estimate(const MemoryEstimate &estimate,
                          const double          available);

  /**
   * Throw one line naming the estimate, the free memory and the driving
   * entry if `estimate` exceeds `available` (> 0).
   */
  void
  check_memory_fits(const MemoryEstimate &estimate, const double available);
} // namespace FourierSSI

#endif
