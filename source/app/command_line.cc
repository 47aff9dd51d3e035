#include <cmath>
#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/app/command_line.h>
#include <fourier_ssi/driver/batch_runner.h>
#include <fourier_ssi/driver/result_files.h>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/input/prm_values.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <fourier_ssi/linear_algebra/huge_page_allocation.h>
#include <fourier_ssi/linear_algebra/serial_blas.h>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace FourierSSI
{
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

    /**
     * The --interface-matrix sub-command: arguments "p=2 n=1 family=sym
     * r=0.5,0.5,0.5 z=0,0.5,1 kn=1e10 ks=1e10" (n defaults to 0, family to
     * sym); prints interface_matrix() with print_interface_matrix(). Throws a
     * one-line message on bad arguments.
     */
    void
    interface_matrix_command(const std::vector<std::string> &arguments,
                             std::ostream                   &out)
    {
      const std::string what = "--interface-matrix: ";
      const auto number = [&](const std::string &key, const std::string &text) {
        return number_in_entry(text, what + key);
      };
      std::map<std::string, std::string> given;
      for (const std::string &argument : arguments)
        {
          const auto eq = argument.find('=');
          AssertThrow(eq != std::string::npos,
                      ExcMessage(what + "'" + argument + "' is not key=value"));
          const std::string                  key  = argument.substr(0, eq);
          static const std::set<std::string> keys = {
            "p", "n", "family", "r", "z", "kn", "ks"};
          AssertThrow(keys.count(key) == 1,
                      ExcMessage(what + "unknown key '" + key +
                                 "' (expected p, n, family, r, z, kn, ks)"));
          AssertThrow(given.count(key) == 0,
                      ExcMessage(what + key + " given twice"));
          given[key] = argument.substr(eq + 1);
        }
      for (const char *key : {"p", "r", "z", "kn", "ks"})
        AssertThrow(given.count(key),
                    ExcMessage(what + "missing " + key +
                               "= (usage: p=2 n=1 family=sym r=0.5,0.5,0.5 "
                               "z=0,0.5,1 kn=1e10 ks=1e10)"));
      const double p = number("p", given["p"]);
      AssertThrow(p == 2. || p == 4., ExcMessage(what + "p must be 2 or 4"));
      Harmonic harmonic;
      if (given.count("n"))
        {
          const double n = number("n", given["n"]);
          AssertThrow(n >= 0. && n == std::floor(n) && n < 1e6,
                      ExcMessage(what + "n must be an integer >= 0"));
          harmonic.n = static_cast<unsigned int>(n);
        }
      if (given.count("family"))
        {
          try
            {
              harmonic.family = family_from_string(given["family"]);
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcMessage(what +
                                     "family must be sym or anti, not '" +
                                     given["family"] + "'"));
            }
        }
      const auto list = [&](const std::string &key) {
        std::vector<double> values;
        for (const std::string &s : Utilities::split_string_list(given[key]))
          values.push_back(number(key, s));
        AssertThrow(values.size() == static_cast<unsigned int>(p) + 1,
                    ExcMessage(what + key + " needs p+1 = " +
                               std::to_string(static_cast<int>(p) + 1) +
                               " values"));
        return values;
      };
      const std::vector<double> r = list("r"), z = list("z");
      std::vector<Point<2>>     nodes;
      for (unsigned int k = 0; k < r.size(); ++k)
        nodes.emplace_back(r[k], z[k]);
      const InterfaceStiffness k{number("kn", given["kn"]),
                                 number("ks", given["ks"])};
      print_interface_matrix(
        out,
        interface_matrix(static_cast<unsigned int>(p), nodes, k, harmonic));
    }

    void
    print_usage(std::ostream &out)
    {
      out << "usage: fourier-ssi [PARAMS.prm]\n"
             "       fourier-ssi --print-parameters [PARAMS.prm]   (every "
             "entry at its default, or at the file's value)\n"
             "       mpirun -np N fourier-ssi PARAMS.prm   (distributed "
             "solve)\n"
             "       mpirun -np N fourier-ssi --batch [--csv FILE] "
             "CASE.prm... | LIST...\n"
             "       fourier-ssi --interface-matrix p=2 n=1 family=sym "
             "r=0.5,0.5,0.5 z=0,0.5,1 kn=1e10 ks=1e10\n"
             "         (closed-form interface element matrix; n defaults "
             "to 0, family to sym)\n";
    }

    /**
     * One scene: fourier-ssi [PARAMS.prm]. Returns the exit code; throws
     * the errors that run_command_line turns into its one error line.
     */
    int
    run_scene(const int                    argc,
              char                       **argv,
              const MPI_Comm               communicator,
              const bool                   root,
              const std::function<void()> &start_mpi,
              std::ostream                &out,
              std::ostream                &err)
    {
      std::string prm_file = std::string(FSSI_SOURCE_DIR) + "/prm/default.prm";
      if (argc > 2)
        {
          err << "fourier-ssi: error: expected at most one argument "
                 "(the .prm file), got "
              << argc - 1 << std::endl;
          return 1;
        }
      if (argc == 2)
        prm_file = argv[1];
      // A misspelt option would otherwise be read as a file name ("cannot
      // open parameter file").
      AssertThrow(prm_file.rfind("-", 0) != 0,
                  ExcMessage("unknown option '" + prm_file +
                             "' (fourier-ssi --help lists the options)"));

      // The output folder's earlier results go as soon as the folder is
      // known, before the input is checked: a refused input must not
      // leave them beside its error line.
      if (root)
        remove_stale_results_of(prm_file);
      AllParameters parameters;
      parameters.read_file(prm_file);
      if (!parameters.solver.is_direct() ||
          parameters.solver.distributed_always)
        start_mpi();
      out << "fourier-ssi: " << prm_file << std::endl;
      Simulator simulator(parameters, communicator);
      try
        {
          simulator.run(out);
        }
      catch (const std::exception &e)
        {
          // Name the scene's file, as the errors found while reading it
          // do.
          AssertThrow(false, ExcMessage(prm_file + ": " + one_line_message(e)));
        }
      // Not reaching the target is never silent: the results are
      // written (and marked), the exit code says it.
      if (!simulator.unmet_target().empty() &&
          !parameters.adaptivity.allow_unconverged)
        {
          err << "fourier-ssi: " << prm_file << ": " << simulator.unmet_target()
              << std::endl;
          return 3;
        }
      return 0;
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
    const std::function<void()>                       start_mpi = [&]() {
      if (!mpi)
        mpi = std::make_unique<Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
    };
    use_serial_blas();
    keep_freed_memory();
    remove_claimed_results_on_interrupt();
    const bool batch = argc > 1 && std::string(argv[1]) == "--batch";
    if (launched_by_mpi() || batch)
      start_mpi();
    else
      MultithreadInfo::set_thread_limit(1); // as MPI_InitFinalize(.., 1)
    // Under mpirun every rank runs this; only rank 0 talks (a stream without
    // a buffer swallows the output of the others).
    const MPI_Comm communicator = MPI_COMM_WORLD;
    std::ostream   silent(nullptr);
    const bool     root = !Utilities::MPI::job_supports_mpi() ||
                      Utilities::MPI::this_mpi_process(communicator) == 0;
    std::ostream     &out    = root ? std::cout : silent;
    std::ostream     &err    = root ? std::cerr : silent;
    const std::string option = argc > 1 ? argv[1] : "";
    try
      {
        if (option == "--print-parameters")
          {
            // With a file: every entry at that file's value (the file read
            // and checked as a run reads it), else at its default.
            AssertThrow(argc <= 3,
                        ExcMessage("--print-parameters takes at most one "
                                   ".prm file"));
            ParameterHandler prm;
            AllParameters::declare_parameters(prm);
            if (argc == 3)
              {
                AllParameters parameters;
                parameters.read_file(argv[2]);
                prm.parse_input(argv[2]);
              }
            prm.print_parameters(out, ParameterHandler::PRM);
            return 0;
          }
        if (option == "--help" || option == "-h")
          {
            print_usage(out);
            return 0;
          }
        if (option == "--interface-matrix")
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
        return run_scene(argc, argv, communicator, root, start_mpi, out, err);
      }
    catch (const std::exception &e)
      {
        err << "fourier-ssi: error: " << one_line_message(e) << std::endl;
        return 1;
      }
  }
} // namespace FourierSSI
