#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/batch_runner.h>
#include <fourier_ssi/command_line.h>
#include <fourier_ssi/interface_integrator.h>
#include <fourier_ssi/parameters.h>
#include <fourier_ssi/simulator.h>
#include <iostream>
#include <memory>
#include <sstream>

namespace FourierSSI
{
  std::string
  one_line_message(const std::exception &e)
  {
    // deal.II exceptions carry file/line boilerplate; the user needs only the
    // message, which ExcMessage prints after "Additional information:".
    const std::string text = e.what();
    const auto        info = text.find("Additional information:");
    std::string       body =
      info == std::string::npos ? text : text.substr(info + 23);
    const auto stack = body.find("Stacktrace:");
    if (stack != std::string::npos)
      body = body.substr(0, stack);
    std::istringstream in(body);
    std::string        line, result;
    while (std::getline(in, line))
      {
        line = Utilities::trim(line);
        if (line.empty() || line.rfind("----", 0) == 0)
          continue;
        result += (result.empty() ? "" : " ") + line;
      }
    return result;
  }

  namespace
  {
    /** True if an MPI launcher (mpirun, mpiexec, srun) started the process. */
    bool
    launched_by_mpi()
    {
      for (const char *variable :
           {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(variable) != nullptr)
          return true;
      return false;
    }
  } // namespace

  int
  run_command_line(int argc, char **argv)
  {
    // MPI is started only where it is used: under an MPI launcher, for
    // --batch, and for the Trilinos solvers (cg-amg, Distributed = always).
    // A serial run skips it: OpenMPI's singleton start-up costs about
    // 0.3 s, a third of a small run (doc/accuracy-vs-time.md).
    std::unique_ptr<Utilities::MPI::MPI_InitFinalize> mpi;
    const auto                                        start_mpi = [&]() {
      if (!mpi)
        mpi = std::make_unique<Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
    };
    const bool batch = argc > 1 && std::string(argv[1]) == "--batch";
    if (launched_by_mpi() || batch)
      start_mpi();
    else
      MultithreadInfo::set_thread_limit(1); // as MPI_InitFinalize(.., 1)
    std::string prm_file = std::string(FSSI_SOURCE_DIR) + "/prm/default.prm";
    // Under mpirun every rank runs this; only rank 0 talks (a stream without
    // a buffer swallows the output of the others).
    const MPI_Comm communicator = MPI_COMM_WORLD;
    std::ostream   silent(nullptr);
    const bool     root = !Utilities::MPI::job_supports_mpi() ||
                      Utilities::MPI::this_mpi_process(communicator) == 0;
    std::ostream &out = root ? std::cout : silent;
    std::ostream &err = root ? std::cerr : silent;
    try
      {
        if (argc > 1 && std::string(argv[1]) == "--print-parameters")
          {
            ParameterHandler prm;
            AllParameters::declare_parameters(prm);
            prm.print_parameters(out, ParameterHandler::PRM);
            return 0;
          }
        if (argc > 1 &&
            (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
          {
            out << "usage: fourier-ssi [PARAMS.prm]\n"
                   "       fourier-ssi --print-parameters\n"
                   "       mpirun -np N fourier-ssi PARAMS.prm   (distributed "
                   "solve)\n"
                   "       mpirun -np N fourier-ssi --batch [--csv FILE] "
                   "CASE.prm... | LIST...\n"
                   "       fourier-ssi --interface-matrix p=2 n=1 family=sym "
                   "r=0.5,0.5,0.5 z=0,0.5,1 kn=1e10 ks=1e10\n"
                   "         (closed-form interface element matrix; n defaults "
                   "to 0, family to sym)\n";
            return 0;
          }
        if (argc > 1 && std::string(argv[1]) == "--interface-matrix")
          {
            interface_matrix_command(std::vector<std::string>(argv + 2,
                                                              argv + argc),
                                     out);
            return 0;
          }
        if (batch)
          return run_batch(std::vector<std::string>(argv + 2, argv + argc),
                           communicator,
                           out,
                           err);
        if (argc > 2)
          {
            err << "fourier-ssi: error: expected at most one argument "
                   "(the .prm file), got "
                << argc - 1 << std::endl;
            return 1;
          }
        if (argc == 2)
          prm_file = argv[1];

        AllParameters parameters;
        parameters.read_file(prm_file);
        if (!parameters.solver.is_direct() ||
            parameters.solver.distributed_always)
          start_mpi();
        out << "fourier-ssi: " << prm_file << std::endl;
        Simulator simulator(parameters, communicator);
        simulator.run(out);
      }
    catch (const std::exception &e)
      {
        err << "fourier-ssi: error: " << one_line_message(e) << std::endl;
        return 1;
      }
    return 0;
  }
} // namespace FourierSSI
