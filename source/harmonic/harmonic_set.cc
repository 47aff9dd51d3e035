#include <atomic>
#include <chrono>
#include <deal.II/base/multithread_info.h>
#include <dlfcn.h>
#include <exception>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/linear_algebra/serial_blas.h>
#include <thread>

namespace FourierSSI
{
  namespace
  {
    /**
     * While harmonics run concurrently, each one's BLAS calls (inside the
     * direct solver) must stay on its own thread: OpenBLAS's thread pool
     * serializes concurrent callers (measured on prm/wind-pressure.prm, 14
     * harmonics on 2 cores: 0.61 s with it vs 0.30 s without, against
     * 0.52 s on one thread). Found at run time, so a different BLAS simply
     * leaves this out.
     */
    class SingleThreadedBlas
    {
    public:
      SingleThreadedBlas()
      {
        set = reinterpret_cast<void (*)(int)>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
        const auto get = reinterpret_cast<int (*)()>(
          dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
        if (set && get)
          {
            previous = get();
            set(1);
          }
        else
          set = nullptr;
      }

      ~SingleThreadedBlas()
      {
        if (set)
          set(previous);
      }

    private:
      void (*set)(int) = nullptr;
      int previous     = 1;
    };
  } // namespace

  unsigned int
  HarmonicSet::cores_per_rank()
  {
    const unsigned int n_world =
      Utilities::MPI::job_supports_mpi() ?
        Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) :
        1;
    return std::max(1u, MultithreadInfo::n_cores() / n_world);
  }

  unsigned int
  HarmonicSet::concurrent_harmonics(const AllParameters &parameters,
                                    const unsigned int   n_harmonics,
                                    const MPI_Comm       communicator,
                                    const unsigned int   max_threads,
                                    const unsigned int   cores)
  {
    if (uses_distributed_solve(parameters.solver, communicator))
      return 1;
    const unsigned int wanted =
      max_threads > 0 ? max_threads : MultithreadInfo::n_cores();
    const unsigned int at_once = std::min(wanted, n_harmonics);
    return std::max(1u, cores > 0 ? std::min(at_once, cores) : at_once);
  }

  HarmonicSet::HarmonicSet(const AllParameters         &parameters,
                           const std::vector<Harmonic> &harmonics,
                           const Triangulation<2>      &triangulation,
                           const LoadDecomposition     &loads,
                           const MPI_Comm               communicator,
                           const unsigned int           max_threads,
                           const unsigned int           cores)
    : parameters(parameters)
    , triangulation(triangulation)
    , loads(loads)
    , communicator(communicator)
    , harmonics(harmonics)
  {
    for (const Harmonic &harmonic : harmonics)
      problems.push_back(std::make_shared<HarmonicProblem>(
        parameters, harmonic, triangulation, &loads, communicator));
    const unsigned int share = cores > 0 ? cores : cores_per_rank();
    threads                  = concurrent_harmonics(
      parameters, harmonics.size(), communicator, max_threads, cores);
    // Cores the harmonics leave idle (fewer harmonics than cores: a lone
    // stiffness harmonic) serve the cell loops of their assembly.
    const bool distributed =
      uses_distributed_solve(parameters.solver, communicator);
    for (const auto &problem : problems)
      problem->set_assembly_threads(distributed ? 1 : share / threads);
    point_threads = distributed ? 1 : std::max(threads, share);
  }

  void
  HarmonicSet::for_each(
    const std::function<void(const unsigned int)> &task) const
  {
    for_each_from(0, task);
  }

  void
  HarmonicSet::for_each_from(
    const unsigned int                             first,
    const std::function<void(const unsigned int)> &task) const
  {
    std::vector<std::exception_ptr> errors(size());
    std::atomic<unsigned int>       next(first);
    const auto                      work = [&]() {
      for (unsigned int i = next++; i < size(); i = next++)
        try
          {
            task(i);
          }
        catch (...)
          {
            errors[i] = std::current_exception();
          }
    };
    if (threads <= 1)
      work();
    else
      {
        const SingleThreadedBlas single_threaded_blas;
        std::vector<std::thread> workers;
        for (unsigned int t = 0; t < threads; ++t)
          workers.push_back(serial_thread(work));
        for (auto &worker : workers)
          worker.join();
      }
    if (n_ranks > 1)
      agree_on_failure(errors, first);
    for (unsigned int i = first; i < size(); ++i)
      if (errors[i])
        try
          {
            std::rethrow_exception(errors[i]);
          }
        catch (const std::exception &e)
          {
            AssertThrow(false,
                        ExcMessage(harmonics[i].name() + ": " +
                                   one_line_message(e)));
          }
  }

  void
  HarmonicSet::agree_on_failure(const std::vector<std::exception_ptr> &errors,
                                const unsigned int first) const
  {
    // The first failure in (harmonic, rank) order, found by one minimum;
    // its rank sends the message. No failure: key = size() * n_ranks.
    unsigned int key = size() * n_ranks;
    for (unsigned int i = first; i < size() && key == size() * n_ranks; ++i)
      if (errors[i])
        key = i * n_ranks + rank;
    key = Utilities::MPI::min(key, ranks);
    if (key == size() * n_ranks)
      return;
    const unsigned int failed = key / n_ranks, sender = key % n_ranks;
    std::string        message;
    if (rank == sender)
      try
        {
          std::rethrow_exception(errors[failed]);
        }
      catch (const std::exception &e)
        {
          message = one_line_message(e);
        }
    message = Utilities::MPI::broadcast(ranks, message, sender);
    AssertThrow(false, ExcMessage(harmonics[failed].name() + ": " + message));
  }

  void
  HarmonicSet::broadcast_from_owner(const unsigned int i,
                                    double            *values,
                                    const std::size_t  n) const
  {
    if (n_ranks == 1)
      return;
    const int ierr = MPI_Bcast(values, n, MPI_DOUBLE, owner(i), ranks);
    AssertThrowMPI(ierr);
  }

  void
  HarmonicSet::sum_over_ranks(std::vector<double> &values) const
  {
    if (n_ranks == 1)
      return;
    const auto start = std::chrono::steady_clock::now();
    const int  ierr  = MPI_Allreduce(
      MPI_IN_PLACE, values.data(), values.size(), MPI_DOUBLE, MPI_SUM, ranks);
    AssertThrowMPI(ierr);
    ++rank_sums;
    rank_sum_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
  }

  void
  HarmonicSet::distribute_over(const MPI_Comm communicator_of_ranks)
  {
    AssertThrow(!uses_distributed_solve(parameters.solver, communicator),
                ExcMessage("HarmonicSet::distribute_over: the harmonics' "
                           "systems must be serial (MPI_COMM_SELF)"));
    if (!Utilities::MPI::job_supports_mpi())
      return; // a serial run: one rank, every harmonic its own
    ranks   = communicator_of_ranks;
    n_ranks = Utilities::MPI::n_mpi_processes(ranks);
    rank    = Utilities::MPI::this_mpi_process(ranks);
  }

  void
  HarmonicSet::setup_and_assemble()
  {
    for_each([this](const unsigned int i) {
      problems[i]->setup_system();
      if (owns(i))
        problems[i]->assemble_system();
    });
  }

  void
  HarmonicSet::factorize()
  {
    for_each([this](const unsigned int i) {
      if (owns(i))
        problems[i]->factorize();
    });
  }

  void
  HarmonicSet::solve_increments(
    std::vector<std::vector<Vector<double>>> &b_to_x) const
  {
    AssertThrow(b_to_x.size() == size(),
                ExcMessage("HarmonicSet::solve_increments: one list of "
                           "loads per harmonic expected"));
    for_each([&](const unsigned int i) {
      if (owns(i))
        problems[i]->solve_increments(b_to_x[i]);
    });
  }

  void
  HarmonicSet::add(const std::vector<Harmonic> &new_harmonics)
  {
    const unsigned int first = size();
    for (const Harmonic &harmonic : new_harmonics)
      {
        harmonics.push_back(harmonic);
        problems.push_back(std::make_shared<HarmonicProblem>(
          parameters, harmonic, triangulation, &loads, communicator));
      }
    for_each_from(first, [this](const unsigned int i) {
      problems[i]->setup_system();
      if (owns(i))
        {
          problems[i]->assemble_system();
          problems[i]->factorize();
        }
    });
  }

  unsigned int
  HarmonicSet::n_factorizations() const
  {
    unsigned int n = 0;
    for (const auto &problem : problems)
      n += problem->n_factorizations();
    return n;
  }
} // namespace FourierSSI
