#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>
#include <fourier_ssi/driver/memory_estimate.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fstream>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    /**
     * Resident size of a small run (the program, deal.II, UMFPACK, MPI
     * libraries): 173 MB measured for a 24-cell linear scene.
     */
    constexpr double program_bytes = 180e6;

    /**
     * A sparse LU of one harmonic, per DoF: 4 kB (doc/scaling.md, the
     * figure Mesh/Maximum DoFs is documented with).
     */
    constexpr double factorization_bytes_per_dof = 4e3;

    /**
     * The coupled tangent over all harmonics (plastic soil, Stiffness =
     * tangent) couples every pair of harmonics at the plastic points: its
     * LU grows like H^2 N. Measured on prm/pile-capacity.prm (N = 312 DoFs
     * per harmonic counted as below, 3 p^2 per cell) with 9 and 17
     * harmonics: peak resident 311 and 538 MB, 138 and 365 MB above the
     * program. A fit a H^2 N + b H N to the two gives a = 2.4 kB (b = 27
     * kB, the small-problem overhead of each harmonic); with the 4 kB of
     * large factorizations for b the model gives 0.52 and 0.65 of the
     * measured growth, low on purpose: a run that fits must not be refused.
     */
    constexpr double tangent_bytes_per_dof_and_pair = 2.4e3;

    /**
     * One theta sample of one soil quadrature point: strain, committed and
     * trial plastic strain and the iteration's working copies. Measured:
     * prm/pile-capacity.prm with n <= 1 and Theta samples = 4096 (384 x
     * 4096 samples) peaked at 1.43 GB, 1.25 GB above the same run with 36
     * samples (0.18 GB): 800 bytes per sample.
     */
    constexpr double bytes_per_theta_sample = 800.;

    /**
     * One element's plastic strain (48 bytes) of an iwan sample's history,
     * in the copies a step holds (committed, the step before, the trial,
     * the iteration's evaluation and its working copies). Measured:
     * prm/disc-torsion-cyclic.prm with Theta samples = 2048 (384 x 2048
     * samples x 20 elements) peaked at 5.60 GB, 4.98 GB above the same run
     * with tresca: 317 bytes per element; 300 here, low on purpose as
     * above.
     */
    constexpr double bytes_per_hardening_element = 300.;

    /**
     * One sector of one cell of the revolved 3D VTU (Write 3D vtu): its
     * vertices, fields and the text buffers of the writer. Measured on
     * prm/default.prm (3072 cells) with Theta divisions = 36, 180, 360:
     * peak resident 0.47, 1.15, 1.88 GB, 1.42 kB per cell and sector; 1.2
     * kB here, low on purpose as above.
     */
    constexpr double bytes_per_revolved_cell = 1.2e3;

    /**
     * One sector of one plastic soil cell of the revolved plastic field
     * (Output/Plastic field 3D): its hexahedron's vertices and 17 fields,
     * and the writer's buffers. Measured on prm/footing-capacity.prm (480
     * soil cells) with Theta divisions = 180, 720: peak resident 166 MB,
     * 700 MB above the same run without the file, 1.93 and 2.03 kB per cell
     * and sector; 1.8 kB here, low on purpose as above.
     */
    constexpr double bytes_per_revolved_plastic_cell = 1.8e3;

    std::string
    gigabytes(const double bytes)
    {
      std::ostringstream s;
      s.precision(bytes < 1e10 ? 2 : 3);
      s << bytes / 1e9 << " GB";
      return s.str();
    }

    /** DoFs per harmonic, estimated as Mesh/Maximum DoFs does: 3 p^2. */
    double
    dofs_per_harmonic(const AllParameters    &parameters,
                      const Triangulation<2> &triangulation)
    {
      const double p = parameters.discretization.degree;
      return 3. * p * p * triangulation.n_active_cells();
    }

    /** Soil quadrature points with a plastic law: (p + 2)^2 per cell. */
    double
    plastic_points(const AllParameters    &parameters,
                   const Triangulation<2> &triangulation)
    {
      const double p     = parameters.discretization.degree;
      double       cells = 0.;
      for (const auto &cell : triangulation.active_cell_iterators())
        cells += parameters.soil_plasticity.laws.count(cell->material_id());
      return cells * (p + 2.) * (p + 2.);
    }

    /** Soil cells with a plastic law. */
    double
    plastic_cells(const AllParameters    &parameters,
                  const Triangulation<2> &triangulation)
    {
      const double p = parameters.discretization.degree;
      return plastic_points(parameters, triangulation) / ((p + 2.) * (p + 2.));
    }

    /**
     * The elements of the iwan soil points: sum over their cells of
     * (p + 2)^2 points times the law's surfaces.
     */
    double
    hardening_elements(const AllParameters    &parameters,
                       const Triangulation<2> &triangulation)
    {
      const double p        = parameters.discretization.degree;
      double       elements = 0.;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          const auto law =
            parameters.soil_plasticity.laws.find(cell->material_id());
          if (law != parameters.soil_plasticity.laws.end() &&
              law->second.hardening())
            elements += law->second.n_surfaces;
        }
      return elements * (p + 2.) * (p + 2.);
    }

    /** Factorizations held at the same time in a linear run. */
    double
    concurrent_factorizations(const AllParameters &parameters,
                              const unsigned int   n_harmonics)
    {
      const unsigned int threads =
        parameters.discretization.concurrent_harmonics > 0 ?
          parameters.discretization.concurrent_harmonics :
          MultithreadInfo::n_cores();
      return std::min(n_harmonics, std::max(threads, 1u));
    }
  } // namespace

  MemoryEstimate
  estimate_run_memory(const AllParameters    &parameters,
                      const Triangulation<2> &triangulation,
                      const ScenePlan        &plan)
  {
    const double n_dofs      = dofs_per_harmonic(parameters, triangulation);
    const double n_harmonics = plan.harmonics.size();
    const bool   coupled     = parameters.coupled();
    // Every harmonic's factorization is kept along a coupled load path; a
    // linear run holds one per harmonic solved at the same time.
    const double held =
      coupled ? n_harmonics :
                concurrent_factorizations(parameters, plan.harmonics.size());
    const double factorizations = held * n_dofs * factorization_bytes_per_dof;
    const bool   tangent        = parameters.linearises_on_coupled_tangent() &&
                         parameters.newton_on_load_path();
    const double coupled_tangent =
      tangent ?
        tangent_bytes_per_dof_and_pair * n_harmonics * n_harmonics * n_dofs :
        0.;
    const unsigned int samples =
      parameters.soil_plasticity.any() ?
        theta_samples_for(highest_harmonic(plan.harmonics),
                          parameters.load_path.theta_samples) :
        0;
    const double theta_state =
      samples *
      (plastic_points(parameters, triangulation) * bytes_per_theta_sample +
       hardening_elements(parameters, triangulation) *
         bytes_per_hardening_element);

    const double revolved_vtu = parameters.output.write_3d_vtu ?
                                  bytes_per_revolved_cell *
                                    triangulation.n_active_cells() *
                                    parameters.output.theta_divisions :
                                  0.;
    // Written once per chosen step, one file at a time: one file's patches.
    const bool revolves_plastic_field = parameters.soil_plasticity.any() &&
                                        parameters.output.write_vtu &&
                                        parameters.output.plastic_field_3d;
    const double revolved_plastic_field =
      revolves_plastic_field ? bytes_per_revolved_plastic_cell *
                                 plastic_cells(parameters, triangulation) *
                                 parameters.output.theta_divisions :
                               0.;

    MemoryEstimate estimate;
    estimate.bytes = program_bytes + factorizations + coupled_tangent +
                     theta_state + revolved_vtu + revolved_plastic_field;
    std::ostringstream dofs;
    dofs << static_cast<long long>(n_dofs) << " DoFs per harmonic";
    if (revolved_plastic_field >=
        std::max({factorizations, coupled_tangent, theta_state, revolved_vtu}))
      {
        estimate.driving_entry = "Output/Theta divisions";
        estimate.largest_part =
          gigabytes(revolved_plastic_field) +
          " for the revolved plastic field (Plastic field 3D), " +
          std::to_string(
            static_cast<long long>(plastic_cells(parameters, triangulation))) +
          " plastic soil cells x " +
          std::to_string(parameters.output.theta_divisions) + " sectors";
      }
    else if (revolved_vtu >=
             std::max({factorizations, coupled_tangent, theta_state}))
      {
        estimate.driving_entry = "Output/Theta divisions";
        estimate.largest_part =
          gigabytes(revolved_vtu) + " for the revolved 3D VTU, " +
          std::to_string(triangulation.n_active_cells()) + " cells x " +
          std::to_string(parameters.output.theta_divisions) + " sectors";
      }
    else if (theta_state >= std::max(factorizations, coupled_tangent))
      {
        estimate.driving_entry = "Load path/Theta samples";
        estimate.largest_part =
          gigabytes(theta_state) + " for the plastic state, " +
          std::to_string(samples) + " theta samples x " +
          std::to_string(
            static_cast<long long>(plastic_points(parameters, triangulation))) +
          " soil points" +
          (hardening_elements(parameters, triangulation) > 0. ?
             " with the iwan elements' history" :
             "");
      }
    else if (coupled_tangent >= factorizations)
      {
        estimate.driving_entry = "Discretization/Harmonics";
        estimate.largest_part =
          gigabytes(coupled_tangent) + " for the coupled tangent of " +
          std::to_string(plan.harmonics.size()) + " harmonics x " + dofs.str();
      }
    else
      {
        estimate.driving_entry = held > 1. ? "Discretization/Harmonics" :
                                 parameters.mesh.type == MeshType::gmsh ?
                                             "Mesh/Mesh file" :
                                             "Mesh/R cells, Z cells";
        estimate.largest_part  = gigabytes(factorizations) + " for " +
                                std::to_string(static_cast<long long>(held)) +
                                " factorizations held together x " + dofs.str();
      }
    return estimate;
  }

  double
  available_memory()
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string   key;
    double        kilobytes = 0.;
    std::string   unit;
    while (meminfo >> key >> kilobytes >> unit)
      if (key == "MemAvailable:")
        return kilobytes * 1024.;
    return 0.;
  }

  double
  available_memory_on_all_ranks(const MPI_Comm communicator)
  {
    const double here = available_memory();
    return Utilities::MPI::job_supports_mpi() ?
             Utilities::MPI::min(here, communicator) :
             here;
  }

  std::string
  memory_shortfall(const MemoryEstimate &estimate, const double available)
  {
    if (available <= 0. || estimate.bytes <= available)
      return "";
    return estimate.driving_entry + ": the run needs about " +
           gigabytes(estimate.bytes) + " (" + estimate.largest_part +
           "), more than the free memory, " + gigabytes(available) +
           " (MemAvailable in /proc/meminfo)";
  }

  std::string
  describe_large_estimate(const MemoryEstimate &estimate,
                          const double          available)
  {
    // Below this a run needs no word about its memory on any machine of
    // the project's kind (24 GB).
    constexpr double large_run_bytes = 1e9;
    if (estimate.bytes < large_run_bytes)
      return "";
    return "memory: about " + gigabytes(estimate.bytes) + " estimated (" +
           estimate.largest_part + ", set by " + estimate.driving_entry +
           "), free " +
           (available > 0. ? gigabytes(available) : std::string("unknown"));
  }

  void
  check_memory_fits(const MemoryEstimate &estimate, const double available)
  {
    const std::string shortfall = memory_shortfall(estimate, available);
    AssertThrow(shortfall.empty(), ExcMessage(shortfall));
  }
} // namespace FourierSSI
