#include <ausroll/io/run_log.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace ausroll::io
{
  bool prints(const Verbosity v, std::initializer_list<Verbosity> set, const unsigned int rank)
  {
    if (rank != 0)
      return false;
    for (const Verbosity s : set)
      if (s == v)
        return true;
    return false;
  }

  std::string format_seconds(const double s)
  {
    std::ostringstream out;
    out << std::fixed << std::setprecision(s < 10 ? 1 : 0) << s << " s";
    return out.str();
  }

  void write_run_header(dealii::ConditionalOStream &log,
                        dealii::ConditionalOStream &regression_log,
                        const std::string          &name,
                        const unsigned int          n_ranks,
                        const unsigned long long    n_cells,
                        const unsigned long long    n_dofs,
                        const std::string          &element,
                        const std::string          &kinematics,
                        const std::string          &directory)
  {
    log << "ausroll: " << name << "  (" << n_ranks << " MPI rank" << (n_ranks > 1 ? "s" : "")
        << ")\n"
        << "  mesh: " << n_cells << " cells, " << n_dofs << " DoFs (" << element << ")\n"
        << "  kinematics: " << kinematics << "\n"
        << "  output: " << directory << "/" << std::endl;
    regression_log << "scene: " << name << "\ncells: " << n_cells << "  dofs: " << n_dofs
                   << std::endl;
  }

  void write_run_footer(dealii::ConditionalOStream &log,
                        const unsigned int          steps,
                        const double                seconds,
                        const std::string          &directory,
                        const bool                  with_vtu)
  {
    log << "finished: " << steps << " steps in " << format_seconds(seconds)
        << "; history: " << directory << "/history.csv";
    if (with_vtu)
      log << ", ParaView: " << directory << "/solution.pvd";
    log << std::endl;
  }

  void write_solve_summary(dealii::ConditionalOStream &log,
                           const std::size_t           steps,
                           const unsigned long long    solves,
                           const double                median,
                           const unsigned long long    discarded)
  {
    log << "Newton: " << solves << " solves in " << steps << " steps (median " << median
        << " per step)";
    if (discarded > 0)
      log << ", " << discarded << " more in discarded attempts (failed and solved again, or "
          << "shortened)";
    log << std::endl;
  }

  void write_step_line(dealii::ConditionalOStream &log, const StepSummary &s)
  {
    std::ostringstream percent;
    percent << std::fixed << std::setprecision(1) << std::setw(5) << 100. * s.fraction;
    log << "step " << std::setw(4) << s.step << "  t = " << std::setw(9) << s.time << "  ("
        << percent.str() << "%)  Newton " << std::setw(2) << s.result.iterations;
    if (s.result.outer_passes > 0) // iterations summed over the passes (each within the maximum)
      log << " in " << s.result.outer_passes + 1 << " passes";
    log << "  cutbacks " << s.cutbacks;
    if (s.contact)
      log << "  stick/slip " << s.n_stick << "/" << s.n_slip;
    log << "  DoFs " << s.n_dofs << "  elapsed " << format_seconds(s.elapsed) << "  ETA "
        << format_seconds(s.elapsed * (1. - s.fraction)
                          / std::max(s.fraction - s.start_fraction, 1e-12))
        << std::endl;
  }

  void write_regression_line(dealii::ConditionalOStream &log,
                             const unsigned int          step,
                             const HistoryRow           &row)
  {
    std::ostringstream line;
    line << "step " << step << std::setprecision(5);
    for (const auto &entry : row)
      if (entry.first != "wall_seconds" && entry.first != "step")
        line << " " << entry.first << "=" << (std::abs(entry.second) < 1e-12 ? 0. : entry.second);
    log << line.str() << std::endl;
  }

  bool warn_large_displacement(const unsigned int step,
                               const double       max_u,
                               const double       extent,
                               const unsigned int rank)
  {
    if (!(max_u > 0.1 * extent))
      return false;
    if (rank == 0)
      std::cerr << "ausroll: warning: step " << step << ": displacements of " << max_u
                << " mm exceed 10 % of the workpiece's smallest extent (" << extent
                << " mm) with Model/Kinematics = small strain; its results are not meaningful "
                   "at this size: use a finite-strain kinematics"
                << std::endl;
    return true;
  }
} // namespace ausroll::io
