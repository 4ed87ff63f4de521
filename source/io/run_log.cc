#include <ausroll/contact/contact_operator.h>
#include <ausroll/io/run_log.h>

#include <deal.II/base/mpi.h>

#include <sys/resource.h>

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

  void write_step_line(dealii::ConditionalOStream &log, const StepSummary &s, const double eta)
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
        << format_seconds(eta) << std::endl;
  }

  void EtaEstimator::start(const double start_fraction, const double elapsed)
  {
    progress.assign(1, {start_fraction, elapsed});
  }

  void EtaEstimator::add(const double fraction, const double elapsed)
  {
    if (progress.empty())
      progress.emplace_back(0., 0.);
    progress.emplace_back(fraction, elapsed);
  }

  double EtaEstimator::eta() const
  {
    if (progress.size() < 2)
      return 0.;
    const auto [f0, t0] = progress.front();
    const auto [f, t] = progress.back();
    const double remaining = std::max(0., 1. - f);
    const double overall = (t - t0) / std::max(f - f0, 1e-12);
    // the recent steps: back to a third of the load done in this process, at least 3 steps
    std::size_t i = progress.size() - 1;
    while (i > 0 && (f - progress[i].first < (f - f0) / 3. || progress.size() - 1 - i < 3))
      --i;
    const double recent = (t - progress[i].second) / std::max(f - progress[i].first, 1e-12);
    return remaining * std::max(overall, recent);
  }

  void RunTotals::record_force(const unsigned int k,
                               const std::string &name,
                               const double       force,
                               const double       time)
  {
    if (k >= peak_force.size())
    {
      die_names.resize(k + 1);
      peak_force.resize(k + 1, -1.);
      peak_time.resize(k + 1, 0.);
    }
    die_names[k] = name;
    if (force > peak_force[k])
    {
      peak_force[k] = force;
      peak_time[k] = time;
    }
  }

  double process_cpu_seconds()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_utime.tv_sec + 1e-6 * usage.ru_utime.tv_usec + usage.ru_stime.tv_sec
           + 1e-6 * usage.ru_stime.tv_usec;
  }

  void write_run_summary(dealii::ConditionalOStream &log,
                         const RunTotals            &totals,
                         const std::size_t           steps,
                         const unsigned long long    solves,
                         const double                median,
                         const unsigned long long    discarded,
                         const double                wall_seconds,
                         const MPI_Comm              comm)
  {
    const double       cpu = dealii::Utilities::MPI::sum(process_cpu_seconds(), comm);
    const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    write_solve_summary(log, steps, solves, median, discarded);
    log << "steps: " << steps << " converged, " << totals.cutbacks << " cutback"
        << (totals.cutbacks == 1 ? "" : "s") << std::endl;
    for (std::size_t k = 0; k < totals.peak_force.size(); ++k)
      if (totals.peak_force[k] >= 0.)
        log << "peak die force: " << totals.die_names[k] << "  |F|max = " << std::setprecision(6)
            << totals.peak_force[k] << " N at t = " << totals.peak_time[k] << std::endl;
    log << "time: " << format_seconds(wall_seconds) << " wall, " << format_seconds(cpu) << " CPU"
        << (ranks > 1 ? " (all " + std::to_string(ranks) + " ranks)" : "") << std::endl;
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
  void write_run_end(const OutputParameters     &output,
                     const unsigned int          rank,
                     const RunTotals            &totals,
                     const solver::SolveCount   &solve_count,
                     const unsigned int          steps,
                     const double                wall_seconds,
                     dealii::TimerOutput        &timer,
                     dealii::ConditionalOStream &regression_log,
                     const MPI_Comm              comm)
  {
    // the summary: also at Verbosity = quiet
    dealii::ConditionalOStream summary_log(
        std::cout,
        prints(output.verbosity, {Verbosity::quiet, Verbosity::normal, Verbosity::verbose}, rank));
    write_run_summary(summary_log,
                      totals,
                      solve_count.per_step.size(),
                      solve_count.accepted(),
                      solve_count.median(),
                      solve_count.discarded,
                      wall_seconds,
                      comm);
    const solver::AssemblyCount &a = solve_count.assemblies;
    if (a.total() > 0)
    {
      const auto cpu
          = [&](const unsigned int k) { return " (" + format_seconds(a.cpu_seconds[k]) + " CPU)"; };
      summary_log << "assemblies: " << a.total() << ": " << a.first << " at the start of a solve"
                  << cpu(0) << ", " << a.after_solve << " after a linear solve" << cpu(1) << ", "
                  << a.line_search << " line-search trials" << cpu(2) << ", " << a.status_pass
                  << " after status changes" << cpu(3) << "; " << solve_count.reused_assemblies
                  << " of all re-used the cell matrices of the same state" << std::endl;
    }
    write_run_footer(summary_log, steps, wall_seconds, output.directory, output.write_vtu);
    if (output.verbosity != Verbosity::regression && output.verbosity != Verbosity::quiet)
      timer.print_summary();
    regression_log << "finished: " << steps << " steps" << std::endl;
  }

  template <int dim>
  void RunTotals::record_die_forces(const contact::ContactOperator<dim> &contact, const double time)
  {
    for (unsigned int k = 0; k < contact.n_dies(); ++k)
      record_force(k, contact.die(k).name, contact.die_contact(k).force.norm(), time);
  }

  template void RunTotals::record_die_forces(const contact::ContactOperator<2> &, double);
  template void RunTotals::record_die_forces(const contact::ContactOperator<3> &, double);
} // namespace ausroll::io
