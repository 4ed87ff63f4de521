/**
 * @file main.cc
 * The ausroll executable: parse the command line and dispatch.
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parameter_file.h>
#include <ausroll/io/parameter_documentation.h>
#include <ausroll/scene/scene.h>
#include <ausroll/scene/scene_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
  void print_usage(std::ostream &out)
  {
    out << "Usage: ausroll FILE.prm [OPTIONS]     run the scene described by FILE.prm\n"
           "       ausroll --print-parameters[=prm|markdown]\n"
           "                                     print every parameter with its default and\n"
           "                                     documentation (default format: prm)\n"
           "       ausroll --print-parameters FILE.prm [--set ...]\n"
           "                                     print the effective parameters of FILE.prm\n"
           "                                     (includes expanded, overrides applied; PRM)\n"
           "       ausroll --help                this text\n"
           "       ausroll --version             version\n"
           "Options after FILE.prm:\n"
           "  --resume                 continue FILE.prm from its latest checkpoint\n"
           "  --check-input            parse FILE.prm, build the mesh and the dies, run the\n"
           "                           set-up checks, print the sizes (cells, DoFs, estimated\n"
           "                           memory) and exit 0 (or 2) without writing\n"
           "  --overwrite              replace the results of an earlier run in Output/Directory\n"
           "                           (same as --set \"Output/Overwrite=true\")\n"
           "  --set \"Section/Entry=value\"\n"
           "                           override one entry of FILE.prm (may be repeated; checked\n"
           "                           like a line of the file), e.g.\n"
           "                           --set \"Loading/Number of steps=40\"\n"
           "Run in parallel with: mpirun -np N ausroll FILE.prm\n"
           "Exit status: 0 success, 1 usage error, 2 input error, 3 run failure, 4 internal "
           "error.\n";
  }

  /**
   * @p what on one line and without a deal.II developer block (file, function, violated
   * condition, stack trace) that a wrapped deal.II exception brings along: only its "Additional
   * information" is kept, after the text that wrapped it. At most 2000 characters (other
   * messages: 4000).
   */
  std::string concise(std::string what)
  {
    if (what.find("Stacktrace:") == std::string::npos
        && what.find("Additional information:") == std::string::npos)
      return what.size() > 4000 ? what.substr(0, 4000) + " ..." : what;
    const auto trace = what.find("Stacktrace:");
    if (trace != std::string::npos)
      what.erase(trace);
    const auto info = what.find("Additional information:");
    if (info != std::string::npos)
    {
      const auto        banner = what.find("-----");
      const std::string prefix = banner < info ? what.substr(0, banner) : std::string();
      what = prefix + what.substr(info + 23);
    }
    std::string        text, word;
    std::istringstream words(what);
    while (words >> word)
      if (word.find_first_not_of('-') != std::string::npos)
        text += (text.empty() ? "" : " ") + word;
    if (text.size() > 2000)
      text = text.substr(0, 2000) + " ...";
    return text;
  }

  /** What the command line asks for. */
  struct CommandLine
  {
    std::string                             file;
    bool                                    resume = false;
    bool                                    check_only = false;
    std::vector<ausroll::ParameterOverride> overrides;
  };

  CommandLine parse_command_line(const int argc, char **argv)
  {
    CommandLine line;
    line.file = argv[1];
    for (int i = 2; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--resume")
        line.resume = true;
      else if (arg == "--check-input")
        line.check_only = true;
      else if (arg == "--overwrite")
        line.overrides.push_back(ausroll::parse_override("Output/Overwrite=true"));
      else if (arg == "--set")
      {
        if (i + 1 >= argc)
          throw ausroll::UsageError("--set needs an argument \"Section/Entry=value\"");
        line.overrides.push_back(ausroll::parse_override(argv[++i]));
      }
      else if (arg.rfind("--set=", 0) == 0)
        line.overrides.push_back(ausroll::parse_override(arg.substr(6)));
      else
        throw ausroll::UsageError("unknown argument '" + arg + "'");
    }
    return line;
  }
  /**
   * End the process after an error caught on this rank, printed as @p message (with the usage
   * after a usage error). Alone, or when every rank caught an error (an input error all ranks
   * find while reading the same file), rank 0 prints it and each rank returns @p status. An
   * error found on this rank only (e.g. rank 0 cannot write `history.csv`) would leave the other
   * ranks waiting in their next collective call forever: after @ref agreement_wait without the
   * others joining, this rank prints the message and ends every rank with MPI_Abort(@p status).
   * @p error_comm is a duplicate of MPI_COMM_WORLD used for nothing else, so that the agreement
   * never matches a collective call of the computation.
   */
  int end_after_error(const MPI_Comm     error_comm,
                      const int          status,
                      const std::string &message,
                      const bool         usage)
  {
    constexpr std::chrono::seconds agreement_wait(10);
    const unsigned int             rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const auto                     print = [&](const std::string &prefix)
    {
      std::cerr << prefix << message << std::endl;
      if (usage)
        print_usage(std::cerr);
    };
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1)
    {
      print("");
      return status;
    }
    MPI_Request request;
    MPI_Ibarrier(error_comm, &request);
    int        joined = 0;
    const auto start = std::chrono::steady_clock::now();
    while (!joined && std::chrono::steady_clock::now() - start < agreement_wait)
    {
      MPI_Test(&request, &joined, MPI_STATUS_IGNORE);
      if (!joined)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (joined)
    {
      if (rank == 0)
        print("");
      return status;
    }
    print("");
    std::cerr << "ausroll: the error was found on rank " << rank
              << " only; ending all ranks (exit status " << status << ")" << std::endl;
    MPI_Abort(MPI_COMM_WORLD, status);
    return status;
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
  // Only for end_after_error(): ranks agree on an error without touching MPI_COMM_WORLD.
  MPI_Comm error_comm;
  MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);

  // Keep deal.II from printing long developer messages; errors are reported below.
  dealii::deal_II_exceptions::disable_abort_on_exception();

  int         status = 0;
  std::string message;
  try
  {
    if (argc < 2)
      throw ausroll::UsageError("no parameter file given");
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
    if (arg == "--print-parameters" || arg.rfind("--print-parameters=", 0) == 0)
    {
      const std::string format = arg.size() > 19 ? arg.substr(19) : "prm";
      if (format != "prm" && format != "markdown")
        throw ausroll::UsageError("--print-parameters: unknown format '" + format
                                  + "' (prm or markdown)");
      if (argc > 2)
      {
        // the effective parameters of a file (as written to Output/Directory/parameters.prm)
        const CommandLine line = parse_command_line(argc - 1, argv + 1);
        if (line.resume || format != "prm")
          throw ausroll::UsageError("--print-parameters FILE.prm takes only --set options "
                                    "(and the prm format)");
        const auto parameters = ausroll::scene::read_parameter_file(line.file, line.overrides);
        if (root)
          std::cout << parameters.effective_parameters;
        return 0;
      }
      if (root)
      {
        dealii::ParameterHandler prm;
        ausroll::scene::SceneParameters::declare_parameters(prm);
        ausroll::io::print_parameters(std::cout, format, prm);
      }
      return 0;
    }
    if (arg.rfind("-", 0) == 0)
      throw ausroll::UsageError("unknown option '" + arg + "'");
    const CommandLine line = parse_command_line(argc, argv);
    if (line.check_only && line.resume)
      throw ausroll::UsageError("--check-input checks a new run; it cannot be combined with "
                                "--resume");
    ausroll::scene::run_scene(
        line.file, MPI_COMM_WORLD, line.resume, line.overrides, line.check_only);
  }
  catch (const ausroll::UsageError &e)
  {
    status = 1;
    message = std::string("ausroll: ") + e.what();
  }
  catch (const ausroll::InputError &e)
  {
    status = 2;
    message = "ausroll: input error: " + concise(e.what());
  }
  catch (const ausroll::RunFailure &e)
  {
    status = 3;
    message = "ausroll: run failed: " + concise(e.what());
  }
  catch (const std::exception &e)
  {
    status = 4;
    message = "ausroll: internal error: " + concise(e.what());
  }
  if (status != 0)
    return end_after_error(error_comm, status, message, status == 1);
  return 0;
}
