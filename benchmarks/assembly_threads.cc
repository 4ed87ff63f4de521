/**
 * @file assembly_threads.cc
 * Assembly time of mechanics::Assembler (WorkStream cell loop) on a given number of threads:
 * a 64 x 32 Q2 rectangle (2048 cells, 16770 DoFs), finite-strain plastic material with F-bar and
 * a follower pressure, tangent and residual, repeated.
 *
 * Usage: assembly_threads N_THREADS [N_ASSEMBLIES = 20]
 *
 * Prints per assembly: wall time, process CPU time (user + sys), and the CPU time of every
 * thread of the process over the timed loop (from /proc/self/task): on a loaded machine the wall
 * time says little about threads, but sum / max of the thread CPU times is the speed-up the
 * cell loop would reach with the cores to itself (the work divided by the longest thread). The
 * norms of residual and matrix are printed with 17 digits: equal for any number of threads (the
 * copier adds the cells in order).
 */
#include "support/assembler_test_problem.h"

#include <deal.II/base/multithread_info.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace dealii;
using namespace ausroll;

namespace
{
  /** CPU seconds (user + sys) of every thread of this process, by thread id. */
  std::map<int, double> thread_cpu_times()
  {
    std::map<int, double> times;
    const double          tick = static_cast<double>(sysconf(_SC_CLK_TCK));
    for (const auto &entry : std::filesystem::directory_iterator("/proc/self/task"))
    {
      std::ifstream in(entry.path() / "stat");
      std::string   text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const auto    close = text.rfind(')');
      if (close == std::string::npos)
        continue;
      std::istringstream fields(text.substr(close + 2));
      std::string        field;
      double             utime = 0., stime = 0.;
      for (unsigned int k = 3; fields >> field; ++k)
      {
        if (k == 14)
          utime = std::stod(field);
        if (k == 15)
        {
          stime = std::stod(field);
          break;
        }
      }
      times[std::stoi(entry.path().filename().string())] = (utime + stime) / tick;
    }
    return times;
  }

  double process_cpu_seconds()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_utime.tv_sec + 1e-6 * usage.ru_utime.tv_usec + usage.ru_stime.tv_sec
           + 1e-6 * usage.ru_stime.tv_usec;
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  const unsigned int               n_threads = argc > 1 ? std::atoi(argv[1]) : 1;
  const unsigned int               n_assemblies = argc > 2 ? std::atoi(argv[2]) : 20;
  MultithreadInfo::set_thread_limit(n_threads);

  test_support::AssemblerTestProblem<2> problem(
      test_support::plastic_block_under_pressure("300 * (1 + 0.01 * x)"),
      test_support::rectangle({64, 32}, Point<2>(0., 0.), Point<2>(20., 10.)));
  const unsigned int n = problem.n_dofs();
  for (unsigned int i = 0; i < n; ++i)
    problem.u[i] = 0.02 * std::sin(0.37 * i); // a plastic, distorted state

  auto assemble = [&]()
  {
    const auto status = problem.assemble(problem.u, true);
    if (!status.ok)
    {
      std::printf("assembly failed: %s\n", status.message.c_str());
      std::exit(1);
    }
  };

  assemble(); // warm-up (TBB threads start, memory touched)
  const auto   threads_before = thread_cpu_times();
  const double cpu_before = process_cpu_seconds();
  const auto   wall_start = std::chrono::steady_clock::now();
  for (unsigned int k = 0; k < n_assemblies; ++k)
    assemble();
  const double wall
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const double cpu = process_cpu_seconds() - cpu_before;
  const auto   threads_after = thread_cpu_times();

  double sum = 0., longest = 0.;
  for (const auto &[id, t] : threads_after)
  {
    const auto   it = threads_before.find(id);
    const double used = t - (it == threads_before.end() ? 0. : it->second);
    sum += used;
    longest = std::max(longest, used);
  }
  std::printf("threads %u (MultithreadInfo::n_threads() = %u), %u cells, %u DoFs, %u assemblies\n",
              n_threads,
              MultithreadInfo::n_threads(),
              problem.tria.n_active_cells(),
              n,
              n_assemblies);
  std::printf("per assembly: wall %.1f ms, process CPU %.1f ms\n",
              1e3 * wall / n_assemblies,
              1e3 * cpu / n_assemblies);
  std::printf("thread CPU: sum %.2f s, longest thread %.2f s, sum / longest %.2f\n",
              sum,
              longest,
              longest > 0. ? sum / longest : 0.);
  std::printf("|residual| = %.17g, |matrix|_F = %.17g\n",
              problem.residual.l2_norm(),
              problem.matrix.frobenius_norm());
  return 0;
}
