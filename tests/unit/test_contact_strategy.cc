/**
 * The contact strategies (contact_strategy.h) on problems without a mesh: one node with a normal
 * and a tangential degree of freedom (u_n, u_t), each on a linear spring (stiffness k = 1, at
 * rest at 0), loaded by forces f_n(t), f_t(t) and pressed against a rigid stop u_n <= g with
 * Coulomb friction mu. The node is driven by the real NewtonSolver and by a load-step loop that
 * makes the same calls as Scene::assemble() and Scene::solve_step(); four steps of 1/4 to t = 1.
 *
 * Exact answer: open, u = f / k; closed, u_n = g with the compressive reaction R_n = f_n - k g;
 * sticking, u_t stays where the node closed (R_t = f_t - k u_t carried by friction) until
 * |R_t| = mu R_n; slipping, R_t = mu R_n and u_t = (f_t - mu R_n) / k. The problems are linear,
 * so every converged state is exact to round-off (tolerance 1e-12), and so is the load-increment
 * ratio's linear interpolation within a step: its sub-steps end exactly at the events (1e-12).
 *
 * The node (StopNode) implements ContactStatusSet with the criteria of ContactOperator on this
 * one node: penetration closes (stick), tension opens, |R_t| > mu R_n slips, reversed slip
 * sticks, events interpolated linearly from the committed state.
 */
#include <ausroll/contact/contact_strategy.h>
#include <ausroll/contact/strategies/load_increment_ratio.h>
#include <ausroll/contact/strategies/nested_active_set.h>
#include <ausroll/solver/newton_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace
{
  using namespace ausroll;
  using contact::ContactStatusSet;

  /** Status of the node (as contact::ContactStatus). */
  enum class Status
  {
    open,
    stick,
    slip
  };

  constexpr double k = 1.;      // spring stiffness (both directions)
  constexpr double tol = 1e-12; // round-off of a linear problem

  /** The loads and the stop of one problem. */
  struct StopProblem
  {
    std::function<double(double)> f_n, f_t;
    double                        g = 1.;  // position of the stop
    double                        mu = 0.; // friction coefficient
  };

  /** One contact node against the stop u_n <= g (both DoFs in one vector, u = (u_n, u_t)). */
  class StopNode : public ContactStatusSet
  {
  public:
    explicit StopNode(const StopProblem &problem)
        : p(problem)
    {
    }

    // ---- ContactStatusSet
    void set_time(const double t) override { time = t; }
    void start_iterate() override { fresh = false; }
    void hold_changed_nodes(const bool hold) override { hold_changed = hold; }
    unsigned int
    update_geometry(const Vector &u, const bool allow_closing, const bool only_unchanged) override
    {
      u_t = u[1];
      gap = p.g - u[0];
      if (status == Status::open && allow_closing && !fresh && (!only_unchanged || changes == 0)
          && gap < (changes == 0 ? gap_tolerance : -gap_tolerance))
        switch_status(Status::stick);
      return status == Status::open ? 0 : 1;
    }
    unsigned int close_penetrating_nodes(const Vector &u) override
    {
      update_geometry(u, true, false);
      return fresh && status != Status::open ? 1 : 0;
    }
    unsigned int update_statuses(const unsigned int change_limit) override
    {
      if (status == Status::open || fresh || changes >= std::min(max_changes, change_limit))
        return 0;
      Status target = status;
      if (Rn < -force_tolerance)
        target = Status::open;
      else if (status == Status::stick && std::abs(Rt) > p.mu * Rn + force_tolerance)
        target = Status::slip;
      else if (status == Status::slip && sign * (u_t - slip_start) < -gap_tolerance)
        target = Status::stick;
      if (target == status)
        return 0;
      switch_status(target);
      return 1;
    }
    double       event_ratio() const override { return std::min(1., event().first); }
    unsigned int apply_events(const double alpha_limit) override
    {
      const auto [alpha, target] = event();
      if (alpha > alpha_limit)
        return 0;
      switch_status(target);
      return 1;
    }
    unsigned int close_touching_nodes() override
    {
      if (status != Status::open || gap >= gap_tolerance)
        return 0;
      switch_status(Status::stick);
      return 1;
    }
    void promote_statuses() override { committed_status = status; }
    /** As ContactOperator: a node that closed in the last step and sticks slips, with the slip
        sign of its tangential reaction (switch_status()). Unlike ContactOperator, R_t = 0 is
        not excluded: on these linear springs a node sticks where its first free iterate put it,
        so R_t = 0 at the end of the step in which it closes, and the slip sign of R_t >= 0 (+)
        is that of the tangential loads of the problems below. */
    unsigned int release_fresh_sticks() override
    {
      ++releases;
      if (!closed_in_last_step || status != Status::stick || Rn <= 0. || changes >= max_changes)
        return 0;
      switch_status(Status::slip);
      return 1;
    }
    void reset() override
    {
      status = committed_status;
      stick_point = committed_stick_point;
      sign = committed_sign;
      slip_start = committed_slip_start;
      Rn = committed_Rn;
      Rt = committed_Rt;
      changes = 0;
    }

    // ---- the mechanics of the node at time t (what the assembler would give)
    /** Residuals k u - f and the forces the stop carries, R = f - k u (at u_n = g when closed). */
    void assemble(const Vector &u)
    {
      r_n = k * u[0] - p.f_n(time);
      r_t = k * u[1] - p.f_t(time);
      Rn = -r_n;
      Rt = -r_t;
    }
    /** The out-of-balance force of the free equations (the slip equation R_t = s mu R_n). */
    double free_residual() const
    {
      if (status == Status::open)
        return std::hypot(r_n, r_t);
      return status == Status::slip ? std::abs(slip_residual()) : 0.;
    }
    double reference_force() const
    {
      const double loads = std::hypot(p.f_n(time), p.f_t(time));
      return status == Status::open ? loads : std::max(loads, std::hypot(Rn, Rt));
    }
    double constraint_violation(const Vector &u) const
    {
      if (status == Status::open)
        return 0.;
      return std::max(std::abs(p.g - u[0]),
                      status == Status::stick ? std::abs(stick_point - u[1]) : 0.);
    }
    /** Newton increment (the system is linear: exact in one step). */
    std::array<double, 2> increment(const Vector &u) const
    {
      if (status == Status::open)
        return {{-r_n / k, -r_t / k}};
      if (status == Status::stick)
        return {{p.g - u[0], stick_point - u[1]}};
      // slip: k u_t - f_t + s mu R_n(u_n = g) = 0
      return {{p.g - u[0], -(k * u[1] - p.f_t(time) + sign * p.mu * (p.f_n(time) - k * p.g)) / k}};
    }
    /** d . r of the free equations. */
    double increment_residual_product(const std::array<double, 2> &d) const
    {
      if (status == Status::open)
        return d[0] * r_n + d[1] * r_t;
      return status == Status::slip ? d[1] * slip_residual() : 0.;
    }
    void commit()
    {
      closed_in_last_step = committed_status == Status::open && status != Status::open;
      committed_status = status;
      committed_stick_point = stick_point;
      committed_sign = sign;
      if (status == Status::slip)
        slip_start = u_t;
      committed_slip_start = slip_start;
      committed_gap = gap;
      committed_Rn = status == Status::open ? 0. : Rn;
      committed_Rt = status == Status::open ? 0. : Rt;
      changes = 0;
    }

    Status       status = Status::open;
    double       Rn = 0., Rt = 0.;
    unsigned int releases = 0; ///< calls of release_fresh_sticks()

  private:
    double slip_residual() const { return r_t + sign * p.mu * Rn; }

    /** Fraction of the step and target status of the next change (as ContactOperator). */
    std::pair<double, Status> event() const
    {
      const double infinity = std::numeric_limits<double>::infinity();
      if (changes >= max_changes)
        return {infinity, status};
      if (status == Status::open)
      {
        if (committed_gap >= 0. && gap < committed_gap)
          return {committed_gap / (committed_gap - gap), Status::stick};
        return {gap < -gap_tolerance ? 0. : infinity, Status::stick};
      }
      std::pair<double, Status> e{infinity, Status::open};
      const double              dRn = Rn - committed_Rn;
      if (dRn < 0. && committed_Rn >= 0.)
        e = {committed_Rn / -dRn, Status::open};
      else if (Rn < -force_tolerance)
        e = {0., Status::open};
      if (status == Status::stick)
      {
        // s R_t reaches mu R_n
        const double s = Rt >= 0. ? 1. : -1.;
        const double f0 = s * committed_Rt - p.mu * committed_Rn;
        const double df = s * (Rt - committed_Rt) - p.mu * dRn;
        if (df > 0.)
        {
          const double alpha = f0 >= 0. ? 0. : -f0 / df;
          if (alpha < e.first)
            e = {alpha, Status::slip};
        }
      }
      else if (sign * (u_t - slip_start) < -gap_tolerance)
        e = {0., Status::stick};
      return e;
    }
    void switch_status(const Status target)
    {
      if (target == status)
        return;
      ++changes;
      fresh = hold_changed;
      if (target == Status::stick)
        stick_point = status == Status::slip ? slip_start : u_t;
      if (target == Status::slip)
      {
        sign = Rt >= 0. ? 1 : -1; // the node moves with the load the stop can no longer hold
        slip_start = status == Status::stick ? stick_point : u_t;
      }
      if (target == Status::open)
        sign = 0;
      status = target;
    }

    static constexpr unsigned int max_changes = 6;
    static constexpr double       gap_tolerance = 1e-9;
    static constexpr double       force_tolerance = 1e-10;

    StopProblem  p;
    double       time = 0., u_t = 0., gap = 0., r_n = 0., r_t = 0.;
    double       stick_point = 0., slip_start = 0.;
    int          sign = 0;
    unsigned int changes = 0;
    bool         fresh = false, hold_changed = false, closed_in_last_step = false;
    Status       committed_status = Status::open;
    double       committed_stick_point = 0., committed_slip_start = 0., committed_gap = 1.;
    int          committed_sign = 0;
    double       committed_Rn = 0., committed_Rt = 0.;
  };

  /** The converged state at the end of a (sub-)step. */
  struct Record
  {
    double       t;
    Status       status;
    double       u_n, u_t, Rn, Rt;
    unsigned int outer_passes;
  };

  /** The node on its springs as the Newton solver sees it, with the scene's calls into the
      strategy (Scene::assemble(), Scene::solve_step(), Scene::run()). */
  class StopScene : public solver::NonlinearProblem
  {
  public:
    StopScene(const StopProblem                                 &problem,
              const std::string                                 &strategy,
              std::shared_ptr<const contact::StrategyParameters> strategy_parameters = nullptr)
        : node(problem)
        , u(dealii::complete_index_set(2), MPI_COMM_SELF)
        , u_committed(u)
        , start(u)
    {
      contact::ContactParameters parameters;
      parameters.strategy = strategy; // the registered defaults (Ratio tolerance 1e-3)
      parameters.strategy_parameters = strategy_parameters;
      status_strategy = contact::make_status_strategy(parameters, node, true);
    }

    bool assemble(const bool, std::string &) override
    {
      status_strategy->begin_iterate(time);
      for (;;)
      {
        status_strategy->update_geometry(u);
        node.assemble(u);
        if (status_strategy->update_at_iterate() == 0)
          break;
      }
      return true;
    }
    double residual_norm() const override { return node.free_residual(); }
    double reference_force() const override { return node.reference_force(); }
    double constraint_violation() const override { return node.constraint_violation(u); }
    solver::LinearSolveInfo solve_for_increment() override
    {
      start = u;
      d = node.increment(u);
      return {};
    }
    void apply_increment(const double step) override
    {
      for (unsigned int i = 0; i < 2; ++i)
        u[i] = start[i] + step * d[i];
      u.compress(dealii::VectorOperation::insert);
    }
    double length_scale() const override { return 1.; }
    double increment_residual_product() const override
    {
      return node.increment_residual_product(d);
    }
    unsigned int update_constraints_at_convergence(dealii::ConditionalOStream &log) override
    {
      return status_strategy->update_at_convergence(u, log);
    }
    bool backtrack_with_small_constraint_gaps() const override
    {
      return status_strategy->backtrack_with_small_constraint_gaps();
    }

    /** Steps of 1/4 to t = 1 (ending on the grid of nominal steps, as Scene::run()). */
    std::vector<Record> run()
    {
      dealii::ConditionalOStream log(std::cout, false);
      std::string                message;
      time = 0.;
      assemble(false, message);
      node.commit();
      std::vector<Record> records;
      const double        nominal_dt = 0.25, end_time = 1.;
      double              t_done = 0.;
      while (t_done < end_time * (1. - 1e-12) && records.size() < 100)
      {
        double dt = std::min(nominal_dt,
                             nominal_dt * (std::floor(t_done / nominal_dt + 1e-9) + 1.) - t_done);
        status_strategy->begin_step(u_committed, t_done);
        unsigned int passes = 0;
        for (;;)
        {
          time = t_done + dt;
          u = u_committed;
          const solver::NewtonResult result
              = solver::NewtonSolver(solver_parameters()).solve(*this, log);
          EXPECT_TRUE(result.converged) << result.reason;
          if (!result.converged)
            return records;
          passes += result.outer_passes;
          const contact::StepDecision decision = status_strategy->end_of_step(dt, end_time, log);
          if (decision.accept)
            break;
          dt *= decision.step_factor;
        }
        node.commit();
        u_committed = u;
        t_done = time;
        records.push_back({time, node.status, u[0], u[1], node.Rn, node.Rt, passes});
      }
      return records;
    }

    StopNode node;

  private:
    static solver::SolverParameters solver_parameters()
    {
      solver::SolverParameters p;
      p.residual_tolerance = 1e-12;
      p.absolute_tolerance = 1e-14;
      return p;
    }

    std::unique_ptr<contact::StatusStrategy> status_strategy;
    dealii::TrilinosWrappers::MPI::Vector    u, u_committed, start;
    std::array<double, 2>                    d{{0., 0.}};
    double                                   time = 0.;
  };

  /** An expected state: time, status, displacements and the stop's forces. */
  struct Expected
  {
    double t;
    Status status;
    double u_n, u_t, Rn, Rt;
  };

  void expect_states(const std::vector<Record> &records, const std::vector<Expected> &expected)
  {
    ASSERT_EQ(records.size(), expected.size());
    for (unsigned int i = 0; i < expected.size(); ++i)
    {
      const Expected &e = expected[i];
      SCOPED_TRACE("state " + std::to_string(i) + " at t = " + std::to_string(e.t));
      EXPECT_NEAR(records[i].t, e.t, tol);
      EXPECT_EQ(records[i].status, e.status);
      EXPECT_NEAR(records[i].u_n, e.u_n, tol);
      EXPECT_NEAR(records[i].u_t, e.u_t, tol);
      if (e.status != Status::open)
      {
        EXPECT_NEAR(records[i].Rn, e.Rn, tol);
        EXPECT_NEAR(records[i].Rt, e.Rt, tol);
      }
    }
  }

  /** Outer passes (nested active set) of each load step. */
  void expect_outer_passes(const std::vector<Record>       &records,
                           const std::vector<unsigned int> &passes)
  {
    ASSERT_EQ(records.size(), passes.size());
    for (unsigned int i = 0; i < passes.size(); ++i)
      EXPECT_EQ(records[i].outer_passes, passes[i]) << "step " << i + 1;
  }

  // ---------------------------------------------------------------- problem 1: press and release
  // f_n = 3.2 t up to t = 1/2, 3.2 (1 - t) after, g = 1, no tangential load: the node reaches the
  // stop at t_c = 1 / 3.2 = 0.3125 and leaves it at t_o = 1 - t_c = 0.6875. At t = 1/4, 1/2, 3/4,
  // 1: open u_n = 0.8, closed (stick) u_n = 1 with R_n = 0.6, open 0.8, open 0.
  constexpr double t_c = 1. / 3.2;
  constexpr double t_o = 1. - t_c;

  StopProblem press_and_release()
  {
    StopProblem p;
    p.f_n = [](const double t) { return t <= 0.5 ? 3.2 * t : 3.2 * (1. - t); };
    p.f_t = [](const double) { return 0.; };
    p.g = 1.;
    p.mu = 0.; // with friction, stick -> slip would coincide with the opening (R_t = 0)
    return p;
  }

  const std::vector<Expected> press_and_release_states = {{0.25, Status::open, 0.8, 0., 0., 0.},
                                                          {0.5, Status::stick, 1., 0., 0.6, 0.},
                                                          {0.75, Status::open, 0.8, 0., 0., 0.},
                                                          {1., Status::open, 0., 0., 0., 0.}};

  // ---------------------------------------------------------------- problem 2: press and slide
  // f_n = 2 t, g = 0.6: the node reaches the stop at t = 0.3 (R_n = 2 t - 0.6); a tangential load
  // f_t = 3 (t - 1/2) from t = 1/2 on, mu = 0.5: it sticks (R_t = f_t, u_t = 0) until
  // f_t = mu R_n at t_s = 0.6, then slips with u_t = f_t - mu R_n = 2 t - 1.2.
  constexpr double t_touch = 0.3;
  constexpr double t_s = 0.6;

  StopProblem press_and_slide()
  {
    StopProblem p;
    p.f_n = [](const double t) { return 2. * t; };
    p.f_t = [](const double t) { return t <= 0.5 ? 0. : 3. * (t - 0.5); };
    p.g = 0.6;
    p.mu = 0.5;
    return p;
  }

  const std::vector<Expected> press_and_slide_states = {{0.25, Status::open, 0.5, 0., 0., 0.},
                                                        {0.5, Status::stick, 0.6, 0., 0.4, 0.},
                                                        {0.75, Status::slip, 0.6, 0.3, 0.9, 0.45},
                                                        {1., Status::slip, 0.6, 0.8, 1.4, 0.7}};

  // ---------------------------------------------------------------- problem 3: press and hold
  // As press and slide, but the tangential load f_t = 0.5 (t - 1/2) stays below mu R_n
  // (0.125 < 0.45 at t = 3/4, 0.25 < 0.7 at t = 1): the node sticks at u_t = 0 from t = 0.3 on.
  StopProblem press_and_hold()
  {
    StopProblem p = press_and_slide();
    p.f_t = [](const double t) { return t <= 0.5 ? 0. : 0.5 * (t - 0.5); };
    return p;
  }

  const std::vector<Expected> press_and_hold_states = {{0.25, Status::open, 0.5, 0., 0., 0.},
                                                       {0.5, Status::stick, 0.6, 0., 0.4, 0.},
                                                       {0.75, Status::stick, 0.6, 0., 0.9, 0.125},
                                                       {1., Status::stick, 0.6, 0., 1.4, 0.25}};

  /** `Nested active set/Fresh sticks slip = true`. */
  std::shared_ptr<const contact::StrategyParameters> fresh_sticks_slip()
  {
    auto parameters = std::make_shared<contact::NestedActiveSetParameters>();
    parameters->fresh_sticks_slip = true;
    return parameters;
  }

  /** `Nested active set/Status changes inside Newton = changes` (with `Fresh sticks slip` if
      @p fresh). */
  std::shared_ptr<const contact::StrategyParameters>
  changes_inside_newton(const unsigned int changes, const bool fresh = false)
  {
    auto parameters = std::make_shared<contact::NestedActiveSetParameters>();
    parameters->changes_inside_newton = changes;
    parameters->fresh_sticks_slip = fresh;
    return parameters;
  }
} // namespace

// Active set: the node closes inside Newton when the free iterate passes the stop (step 2) and
// opens at the first assembly of step 3 by its tensile reaction (a re-assembly, no outer pass).
TEST(ContactStrategy, ActiveSetPressAndRelease)
{
  StopScene                 scene(press_and_release(), "active set");
  const std::vector<Record> records = scene.run();
  expect_states(records, press_and_release_states);
  expect_outer_passes(records, std::vector<unsigned int>(records.size(), 0));
}

// Active set with friction: open, stick, slip (switched at the first assembly of step 3), slip.
TEST(ContactStrategy, ActiveSetPressAndSlide)
{
  StopScene                 scene(press_and_slide(), "active set");
  const std::vector<Record> records = scene.run();
  expect_states(records, press_and_slide_states);
  expect_outer_passes(records, std::vector<unsigned int>(records.size(), 0));
}

// Nested active set: closing inside Newton as with the active set (the node has not changed in
// the step), but the tensile reaction of step 3 is judged at the converged state: one outer pass
// in step 3, none elsewhere.
TEST(ContactStrategy, NestedActiveSetPressAndRelease)
{
  StopScene                 scene(press_and_release(), "nested active set");
  const std::vector<Record> records = scene.run();
  expect_states(records, press_and_release_states);
  expect_outer_passes(records, {0, 0, 1, 0});
}

// Nested active set with friction: stick -> slip is found at the converged sticking state of
// step 3 (one outer pass).
TEST(ContactStrategy, NestedActiveSetPressAndSlide)
{
  StopScene                 scene(press_and_slide(), "nested active set");
  const std::vector<Record> records = scene.run();
  expect_states(records, press_and_slide_states);
  expect_outer_passes(records, {0, 0, 1, 0});
}

// Fresh sticks slip: the node that closed in stick in step 2 starts step 3 slipping, which is
// the converged status there: the same exact states as without the option, without the outer
// pass of step 3 (the pass the option saves on the gear's flank). begin_step() asks for the
// release once per step, and no more.
TEST(ContactStrategy, NestedActiveSetFreshSticksSlipSavesThePass)
{
  StopScene                 scene(press_and_slide(), "nested active set", fresh_sticks_slip());
  const std::vector<Record> records = scene.run();
  expect_states(records, press_and_slide_states);
  expect_outer_passes(records, {0, 0, 0, 0});
  EXPECT_EQ(scene.node.releases, 4u);
}

// Fresh sticks slip where the node really sticks: released at the start of step 3, its slip
// reverses (u_t would run back from its stick point) and it sticks again at the converged state,
// where it stuck: the exact states, at the price of one outer pass. Without the option it sticks
// throughout and is never released.
TEST(ContactStrategy, NestedActiveSetFreshSticksSlipKeepsATrueStick)
{
  StopScene                 with(press_and_hold(), "nested active set", fresh_sticks_slip());
  const std::vector<Record> records = with.run();
  expect_states(records, press_and_hold_states);
  expect_outer_passes(records, {0, 0, 1, 0});

  StopScene                 without(press_and_hold(), "nested active set");
  const std::vector<Record> plain = without.run();
  expect_states(plain, press_and_hold_states);
  expect_outer_passes(plain, {0, 0, 0, 0});
  EXPECT_EQ(without.node.releases, 0u);
}

// After a failed solve: with the option the committed statuses are restored with the fresh
// sticks released again (restart_step()), and release_after_failure() has nothing left to do
// (the load stepper then retries only to drop the predictor); without it, restart_step() restores
// the sticks and release_after_failure() releases them.
TEST(ContactStrategy, NestedActiveSetFreshSticksSlipAfterAFailure)
{
  for (const bool option : {true, false})
  {
    SCOPED_TRACE(option ? "Fresh sticks slip" : "default");
    StopNode node(press_and_slide());
    // the node closed in the last step and sticks, pressed (R_n = 0.4)
    dealii::TrilinosWrappers::MPI::Vector u(dealii::complete_index_set(2), MPI_COMM_SELF);
    node.commit();
    node.status = Status::stick;
    node.Rn = 0.4;
    node.commit();
    contact::ContactParameters parameters;
    parameters.strategy = "nested active set";
    if (option)
      parameters.strategy_parameters = fresh_sticks_slip();
    const auto strategy = contact::make_status_strategy(parameters, node, true);
    strategy->begin_step(u, 0.5);
    EXPECT_EQ(node.status, option ? Status::slip : Status::stick);
    strategy->restart_step();
    EXPECT_EQ(node.status, option ? Status::slip : Status::stick);
    EXPECT_EQ(strategy->release_after_failure(), option ? 0u : 1u);
    EXPECT_EQ(node.status, Status::slip);
  }
}

// Status changes inside Newton: the tensile reaction of step 3 (press and release) and the
// friction limit of step 3 (press and slide) are judged at the first assembly of the step, as by
// the active set: the same exact states without the outer pass of step 3.
TEST(ContactStrategy, NestedActiveSetChangesInsideNewtonSaveThePass)
{
  for (const unsigned int changes : {1u, 2u})
  {
    SCOPED_TRACE("Status changes inside Newton = " + std::to_string(changes));
    StopScene release(press_and_release(), "nested active set", changes_inside_newton(changes));
    const std::vector<Record> released = release.run();
    expect_states(released, press_and_release_states);
    expect_outer_passes(released, {0, 0, 0, 0});

    StopScene slide(press_and_slide(), "nested active set", changes_inside_newton(changes));
    const std::vector<Record> slid = slide.run();
    expect_states(slid, press_and_slide_states);
    expect_outer_passes(slid, {0, 0, 0, 0});
  }
}

// The hysteresis of Status changes inside Newton: with Fresh sticks slip, the node that closed in
// step 2 (press and hold) starts step 3 slipping (its first change of the step) and its slip
// reverses. With N = 1 it has used its change and is held: the reversal is judged at the converged
// state (one outer pass, as without the entry); with N = 2 it sticks again inside Newton (no outer
// pass). Both end in the exact sticking states.
TEST(ContactStrategy, NestedActiveSetChangesInsideNewtonHoldANodeAfterN)
{
  StopScene once(press_and_hold(), "nested active set", changes_inside_newton(1, true));
  const std::vector<Record> held = once.run();
  expect_states(held, press_and_hold_states);
  expect_outer_passes(held, {0, 0, 1, 0});

  StopScene twice(press_and_hold(), "nested active set", changes_inside_newton(2, true));
  const std::vector<Record> judged = twice.run();
  expect_states(judged, press_and_hold_states);
  expect_outer_passes(judged, {0, 0, 0, 0});
}

// The change limit of ContactStatusSet::update_statuses() on the node alone: a sticking node
// beyond its friction limit that has changed once in the step (it closed) is not judged with a
// limit of 1, and slips with a limit of 2 or without a limit.
TEST(ContactStrategy, UpdateStatusesHonoursTheChangeLimit)
{
  for (const unsigned int limit : {1u, 2u, ContactStatusSet::no_change_limit})
  {
    SCOPED_TRACE("change limit " + std::to_string(limit));
    StopNode                              node(press_and_slide());
    dealii::TrilinosWrappers::MPI::Vector u(dealii::complete_index_set(2), MPI_COMM_SELF);
    node.set_time(0.75);
    u[0] = 0.7; // penetrates the stop at g = 0.6
    u.compress(dealii::VectorOperation::insert);
    ASSERT_EQ(node.update_geometry(u, true, false), 1u); // closes in stick: one change
    u[0] = 0.6;
    u.compress(dealii::VectorOperation::insert);
    node.update_geometry(u, false, false);
    node.assemble(u); // R_n = 0.9, R_t = 0.75 > mu R_n = 0.45
    node.start_iterate();
    EXPECT_EQ(node.update_statuses(limit), limit == 1u ? 0u : 1u);
    EXPECT_EQ(node.status, limit == 1u ? Status::stick : Status::slip);
  }
}

/** The load-increment ratio on @p problem: the states of the nominal steps @p nominal with the
    sub-steps that end at @p events (after the first and the second nominal step) in between. */
static void expect_ratio_states(const StopProblem             &problem,
                                const std::vector<Expected>   &nominal,
                                const std::array<Expected, 2> &events)
{
  StopScene                 scene(problem, "load increment ratio");
  const std::vector<Record> records = scene.run();
  std::vector<Expected>     expected = nominal;
  expected.insert(expected.begin() + 1, events[0]);
  expected.insert(expected.begin() + 3, events[1]);
  expect_states(records, expected);
  expect_outer_passes(records, std::vector<unsigned int>(records.size(), 0));
}

// Load-increment ratio: statuses fixed within a sub-step; steps 2 and 3 are cut at the events,
// which the sub-steps hit exactly (t_c = 0.3125, t_o = 0.6875), the status switching at their
// end; the grid of nominal steps is resumed afterwards.
TEST(ContactStrategy, LoadIncrementRatioHitsTheEventsOfPressAndRelease)
{
  expect_ratio_states(
      press_and_release(),
      press_and_release_states,
      {{{t_c, Status::stick, 1., 0., 0., 0.}, {t_o, Status::open, 1., 0., 0., 0.}}});
}

// Load-increment ratio with friction: sub-steps end exactly where the node touches (t = 0.3) and
// where it starts to slip (t_s = 0.6, R_t = mu R_n = 0.3, u_t still 0).
TEST(ContactStrategy, LoadIncrementRatioHitsTheEventsOfPressAndSlide)
{
  expect_ratio_states(
      press_and_slide(),
      press_and_slide_states,
      {{{t_touch, Status::stick, 0.6, 0., 0., 0.}, {t_s, Status::slip, 0.6, 0., 0.6, 0.3}}});
}

// The fixed-status base strategy (no dies): the node never closes and passes the stop.
TEST(ContactStrategy, FixedStatusesNeverChange)
{
  StopNode                   node(press_and_release());
  contact::ContactParameters parameters;
  const auto                 strategy = contact::make_status_strategy(parameters, node, false);
  dealii::TrilinosWrappers::MPI::Vector u(dealii::complete_index_set(2), MPI_COMM_SELF);
  u[0] = 2.;
  u.compress(dealii::VectorOperation::insert);
  strategy->begin_iterate(0.5);
  strategy->update_geometry(u);
  node.assemble(u);
  EXPECT_EQ(strategy->update_at_iterate(), 0u);
  EXPECT_EQ(node.status, Status::open);
  EXPECT_NEAR(node.constraint_violation(u), 0., tol);
  EXPECT_FALSE(strategy->backtrack_with_small_constraint_gaps());
  dealii::ConditionalOStream quiet(std::cout, false);
  EXPECT_TRUE(strategy->end_of_step(0.25, 1., quiet).accept);
}

// The strategies are registered (contact/strategies/, one file each): the `Strategy` selection
// lists them in name order, `Load increment ratio/Ratio tolerance` reaches the strategy's
// parameters, and the old `Contact/Ratio tolerance` names its new place.
TEST(ContactStrategy, RegisteredWithTheirSubsections)
{
  EXPECT_EQ(contact::StrategyRegistry::instance().names(),
            (std::vector<std::string>{"active set", "load increment ratio", "nested active set"}));
  dealii::ParameterHandler prm;
  contact::ContactParameters::declare_parameters(prm);
  prm.parse_input_from_string("subsection Contact\n"
                              "  set Strategy = load increment ratio\n"
                              "  subsection Load increment ratio\n"
                              "    set Ratio tolerance = 0.01\n"
                              "  end\n"
                              "end\n");
  contact::ContactParameters parameters;
  parameters.parse_parameters(prm, "");
  EXPECT_EQ(parameters.strategy, "load increment ratio");
  const auto *ratio = dynamic_cast<const contact::LoadIncrementRatioParameters *>(
      parameters.strategy_parameters.get());
  ASSERT_NE(ratio, nullptr);
  EXPECT_EQ(ratio->tolerance, 0.01);
  EXPECT_EQ(contact::ContactParameters::moved_entries().at("Contact/Ratio tolerance"),
            "`Contact/Load increment ratio/Ratio tolerance`");

  // `Nested active set/Fresh sticks slip`: false unless set; `Status changes inside Newton`: 0
  // unless set
  for (const bool value : {false, true})
  {
    dealii::ParameterHandler nested;
    contact::ContactParameters::declare_parameters(nested);
    nested.parse_input_from_string(std::string("subsection Contact\n"
                                               "  set Strategy = nested active set\n")
                                   + (value ? "  subsection Nested active set\n"
                                              "    set Fresh sticks slip = true\n"
                                              "    set Status changes inside Newton = 3\n"
                                              "  end\n"
                                            : "")
                                   + "end\n");
    contact::ContactParameters nested_parameters;
    nested_parameters.parse_parameters(nested, "");
    const auto *parsed = dynamic_cast<const contact::NestedActiveSetParameters *>(
        nested_parameters.strategy_parameters.get());
    ASSERT_NE(parsed, nullptr);
    EXPECT_EQ(parsed->fresh_sticks_slip, value);
    EXPECT_EQ(parsed->changes_inside_newton, value ? 3u : 0u);
  }
}
