#include <ausroll/core/exceptions.h>
#include <ausroll/solver/load_stepper.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <tuple>

namespace ausroll::solver
{
  unsigned long long SolveCount::accepted() const
  {
    return std::accumulate(per_step.begin(), per_step.end(), 0ull);
  }

  double SolveCount::median() const
  {
    if (per_step.empty())
      return 0.;
    std::vector<unsigned int> sorted = per_step;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  }

  LoadStepper::LoadStepper(const LoadingParameters    &loading,
                           const std::string          &output_directory,
                           dealii::ConditionalOStream &log,
                           dealii::ConditionalOStream &detail_log)
      : loading(loading)
      , output_directory(output_directory)
      , log(log)
      , detail_log(detail_log)
  {
  }

  double LoadStepper::nominal_step_size() const
  {
    return loading.end_time / loading.number_of_steps;
  }

  void LoadStepper::set_stages(const StageParameters *stage_parameters)
  {
    stages = stage_parameters;
  }

  double LoadStepper::current_nominal_step() const
  {
    return stage_step > 0. ? stage_step : nominal_step_size();
  }

  std::pair<double, double> LoadStepper::stage_targets(const double t_done, double &dt)
  {
    const unsigned int k = stages->stage_at(t_done);
    const Stage       &stage = stages->stages[k];
    const double       start = stages->start_time(k);
    const double       nominal_dt = nominal_step_size();
    const double       h = stages->step_size(k, nominal_dt);
    if (static_cast<int>(k) != current_stage)
    {
      current_stage = k;
      stage_step = h;
      if (std::abs(t_done - start) <= 1e-10 * std::abs(stages->stages.back().end_time))
      {
        // a stage switches conditions: its first step starts from the converged state, without
        // extrapolating the last stage's increment
        dt = h;
        last_step_size = 0.;
        log << "Stage " << k << " (" << stage.name << "): t = " << start << " to " << stage.end_time
            << ", step " << h << std::endl;
      }
      else
        log << "resuming in stage " << k << " (" << stage.name << ") at t = " << t_done
            << std::endl;
    }
    // the stage's own grid from its start, or the run's grid of Loading
    const double grid = stage.step_size > 0.
                            ? start + h * (std::floor((t_done - start) / h + 1e-9) + 1.)
                            : nominal_dt * (std::floor(t_done / nominal_dt + 1e-9) + 1.);
    return {std::min(stage.end_time, grid), stage.end_time};
  }

  LoadStep LoadStepper::solve_step(SteppedProblem    &problem,
                                   const unsigned int number,
                                   const double       t_start,
                                   double             dt)
  {
    LoadStep step;
    step.number = number;
    step.t_start = t_start;
    problem.begin_step(t_start);
    // A step that fails with the predictor is first tried again from the converged state (the
    // extrapolation overshoots where the path turns: a fold-over corner, a node reaching a die).
    bool predict = loading.predictor == Predictor::linear_extrapolation && last_step_size > 0.;
    // Before the first cutback, the step is tried once more with the nodes that closed in stick
    // in the last step slipping (contact::NestedActiveSet::release_after_failure()).
    bool released = false;
    for (;;)
    {
      const double time = t_start + dt;
      detail_log << "  step " << number << ", t = " << time << std::endl;
      step.result = problem.solve(time, predict ? dt / last_step_size : 0.);
      const NewtonResult &result = step.result;

      if (!result.converged)
      {
        step.discarded_solves += result.iterations;
        problem.restart_step();
        const unsigned int n_released = released ? 0 : problem.release_after_failure();
        released = true;
        if (predict || n_released > 0)
        {
          log << "  step " << number << " (t = " << time << "): " << result.reason
              << "; trying again";
          if (predict)
            log << " without the predictor";
          if (n_released > 0)
            log << (predict ? " and" : "") << " with " << n_released
                << " freshly closed node(s) slipping";
          log << std::endl;
          predict = false;
          continue;
        }
        ++step.cutbacks;
        log << "  step " << number << " (t = " << time << "): " << result.reason;
        const bool too_small = 0.5 * dt < minimum_step_size();
        if (step.cutbacks > loading.max_cutbacks || too_small)
        {
          log << std::endl;
          // Keep the last converged state in memory and on disk.
          const std::string  note = problem.keep_last_converged(t_start);
          std::ostringstream msg;
          msg << "load step " << number << " (t = " << t_start + dt << ") did not converge ";
          if (step.cutbacks > loading.max_cutbacks)
            msg << "after " << loading.max_cutbacks << " cutbacks";
          else
            msg << "with dt = " << dt << ", and half of it is below Loading/Minimum step "
                << "fraction = " << loading.minimum_step_fraction << " of the nominal step ("
                << minimum_step_size() << ")";
          msg << ": " << result.reason << ". The last converged state (step " << number - 1
              << ", t = " << t_start << ") is in " << output_directory << "/";
          if (!note.empty())
            msg << ". Earlier, " << note;
          throw RunFailure(msg.str());
        }
        dt *= 0.5;
        log << "; cutting back to dt = " << dt << std::endl;
        continue;
      }
      // The contact strategy may end the step earlier, where a contact status changes.
      const contact::StepDecision decision = problem.end_of_step(dt);
      if (decision.accept)
      {
        step.time = time;
        return step;
      }
      step.discarded_solves += result.iterations;
      dt *= decision.step_factor;
    }
  }

  double LoadStepper::minimum_step_size() const
  {
    return loading.minimum_step_fraction * current_nominal_step();
  }

  double LoadStepper::next_step_size(const double       dt,
                                     const double       dt_taken,
                                     const LoadStep    &step,
                                     const unsigned int status_changes) const
  {
    const double nominal_dt = current_nominal_step();
    if (loading.step_control == StepControl::adaptive)
    {
      // From the step actually taken after a cutback, else from the size asked for (a step
      // shortened to end on the nominal grid says nothing about the size that works).
      double factor = loading.step_factor(step.result.iterations, status_changes);
      if (step.cutbacks > 0)
        factor = std::min(factor, 1.);
      const double next = std::clamp(
          (step.cutbacks > 0 ? dt_taken : dt) * factor, minimum_step_size(), nominal_dt);
      detail_log << "  step control: " << step.result.iterations << " Newton iterations, "
                 << status_changes << " contact status changes, " << step.cutbacks
                 << " cutbacks: next dt = " << next << std::endl;
      return next;
    }
    return step.cutbacks > 0 ? dt_taken : std::min(nominal_dt, dt * loading.step_growth_factor);
  }

  void LoadStepper::run(SteppedProblem &problem, double t_done, double dt, unsigned int steps_done)
  {
    const double nominal_dt = nominal_step_size();
    const double t_end = loading.end_time;
    while (t_done < t_end * (1. - 1e-12))
    {
      // Steps end on the grid of nominal steps (also after cutbacks and load-increment-ratio
      // sub-steps), so that outputs and histories of different runs share their times.
      double next_grid
          = std::min(t_end, nominal_dt * (std::floor(t_done / nominal_dt + 1e-9) + 1.));
      double step_end = t_end; // the end of the run, or of its stage
      if (stages != nullptr)
        std::tie(next_grid, step_end) = stage_targets(t_done, dt);
      double dt_try = std::min(dt, next_grid - t_done);
      if (step_end - (t_done + dt_try) < 1e-6 * current_nominal_step())
        dt_try = step_end - t_done;

      LoadStep step = solve_step(problem, steps_done + 1, t_done, dt_try);
      dt_try = step.time - step.t_start;
      last_step_size = dt_try;
      step.step_size = dt;
      solve_count.per_step.push_back(step.result.iterations);
      solve_count.discarded += step.discarded_solves;
      const unsigned int status_changes = problem.accept_step(step);
      ++steps_done;
      t_done = step.time;
      dt = next_step_size(dt, dt_try, step, status_changes);
    }
  }
} // namespace ausroll::solver
