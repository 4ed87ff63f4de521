/**
 * @file main.cc
 * The ausroll executable: parse the command line and dispatch.
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/io/parameter_documentation.h>
#include <ausroll/scene/scene.h>
#include <ausroll/scene/scene_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <iostream>
#include <string>

namespace
{
  void print_usage(std::ostream &out)
  {
    out << "Usage: ausroll FILE.prm              run the scene described by FILE.prm\n"
           "       ausroll FILE.prm --resume     continue FILE.prm from its latest checkpoint\n"
           "       ausroll --print-parameters[=prm|markdown]\n"
           "                                     print every parameter with its default and\n"
           "                                     documentation (default format: prm)\n"
           "       ausroll --help                this text\n"
           "       ausroll --version             version\n"
           "Run in parallel with: mpirun -np N ausroll FILE.prm\n"
           "Exit status: 0 success, 1 usage error, 2 input error, 3 run failure, 4 internal "
           "error.\n";
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  // Threads of the assembly (WorkStream): DEAL_II_NUM_THREADS if set, else the cores shared
  // among the ranks (one thread per rank when ranks fill the cores).
  dealii::MultithreadInfo::set_thread_limit(
      std::max(1u,
               dealii::MultithreadInfo::n_cores()
                   / dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)));

  // Keep deal.II from printing long developer messages; errors are reported below.
  dealii::deal_II_exceptions::disable_abort_on_exception();

  try
  {
    const bool resume = argc == 3 && std::string(argv[2]) == "--resume";
    if (argc != 2 && !resume)
    {
      if (root)
        print_usage(std::cerr);
      return 1;
    }
    const std::string arg = argv[1];
    if (arg == "--help" || arg == "-h")
    {
      if (root)
        print_usage(std::cout);
      return 0;
    }
    if (arg == "--version")
    {
      if (root)
        std::cout << "ausroll 0.1.0 (deal.II " << DEAL_II_PACKAGE_VERSION << ")\n";
      return 0;
    }
    if (arg.rfind("--print-parameters", 0) == 0)
    {
      const std::string format = arg.size() > 19 && arg[18] == '=' ? arg.substr(19) : "prm";
      if (root)
      {
        dealii::ParameterHandler prm;
        ausroll::scene::SceneParameters::declare_parameters(prm);
        ausroll::io::print_parameters(std::cout, format, prm);
      }
      return 0;
    }
    if (arg.rfind("-", 0) == 0)
    {
      if (root)
      {
        std::cerr << "ausroll: unknown option '" << arg << "'\n";
        print_usage(std::cerr);
      }
      return 1;
    }
    ausroll::scene::run_scene(arg, MPI_COMM_WORLD, resume);
  }
  catch (const ausroll::InputError &e)
  {
    if (root)
      std::cerr << "ausroll: input error: " << e.what() << std::endl;
    return 2;
  }
  catch (const ausroll::RunFailure &e)
  {
    if (root)
      std::cerr << "ausroll: run failed: " << e.what() << std::endl;
    return 3;
  }
  catch (const std::exception &e)
  {
    std::cerr << "ausroll: internal error: " << e.what() << std::endl;
    return 4;
  }
  return 0;
}
