/**
 * The contact strategies (contact_strategy.h) on a problem without a mesh: one node on a linear
 * spring (stiffness k = 1, at rest at u = 0) loaded by a force f(t) towards a rigid stop at u = g
 * = 1, driven by the real NewtonSolver and by a load-step loop that makes the same calls as
 * Scene::assemble() and Scene::solve_step(). The load rises and falls, f(t) = 3.2 t for t <= 1/2
 * and 3.2 (1 - t) after, in four steps of 1/4.
 *
 * Exact answer: free, u = f / k; the node reaches the stop when f = k g, at t_c = 1 / 3.2 =
 * 0.3125, rests on it with the compressive reaction R_n = f - k g, and leaves it when R_n
 * becomes tensile, at t_o = 1 - t_c = 0.6875. So at t = 1/4, 1/2, 3/4, 1: open u = 0.8, closed
 * u = 1 (R_n = 0.6), open u = 0.8, open u = 0. The problem is linear, so every converged state is
 * exact to round-off (tolerance 1e-12), and so is the load-increment ratio's interpolation: its
 * sub-steps end exactly at t_c and t_o (1e-12).
 *
 * The contact node (StopNode) implements ContactStatusSet with the criteria of ContactOperator
 * in one dimension: penetration closes, tension opens, events interpolated linearly from the
 * committed state.
 */
#include <ausroll/contact/contact_strategy.h>
#include <ausroll/solver/newton_solver.h>

#include <deal.II/base/index_set.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace
{
  using namespace ausroll;
  using contact::ContactStatusSet;

  constexpr double k = 1.; // spring stiffness
  constexpr double g = 1.; // position of the stop
  constexpr double tol = 1e-12;
  constexpr double t_c = 1. / 3.2; // the node reaches the stop
  constexpr double t_o = 1. - t_c; // the node leaves it

  double load(const double t)
  {
    return t <= 0.5 ? 3.2 * t : 3.2 * (1. - t);
  }

  /** One contact node against the stop u <= g (normal pointing back, -e). */
  class StopNode : public ContactStatusSet
  {
  public:
    void set_time(const double) override {}
    void start_iterate() override { fresh = false; }
    void hold_changed_nodes(const bool hold) override { hold_changed = hold; }

    unsigned int
    update_geometry(const Vector &u, const bool allow_closing, const bool only_unchanged) override
    {
      gap = g - u[0];
      if (!closed && allow_closing && !fresh && (!only_unchanged || changes == 0)
          && gap < (changes == 0 ? gap_tolerance : -gap_tolerance))
        switch_status(true);
      return closed ? 1 : 0;
    }
    unsigned int close_penetrating_nodes(const Vector &u) override
    {
      update_geometry(u, true, false);
      return fresh && closed ? 1 : 0;
    }
    unsigned int update_statuses() override
    {
      if (!closed || fresh || changes >= max_changes || Rn >= -force_tolerance)
        return 0;
      switch_status(false);
      return 1;
    }
    double       event_ratio() const override { return std::min(1., event().first); }
    unsigned int apply_events(const double alpha_limit) override
    {
      const auto [alpha, close] = event();
      if (alpha > alpha_limit)
        return 0;
      switch_status(close);
      return 1;
    }
    unsigned int close_touching_nodes() override
    {
      if (closed || gap >= gap_tolerance)
        return 0;
      switch_status(true);
      return 1;
    }
    void promote_statuses() override { committed_closed = closed; }
    void reset() override
    {
      closed = committed_closed;
      Rn = committed_Rn;
      changes = 0;
    }

    /** Reaction from the residual r = k u - f at the node (compression positive). */
    void compute_reactions(const double residual) { Rn = -residual; }
    void commit()
    {
      committed_closed = closed;
      committed_gap = gap;
      committed_Rn = closed ? Rn : 0.;
      changes = 0;
    }

    bool         closed = false;
    double       gap = g, Rn = 0.;
    unsigned int changes = 0;

  private:
    /** Fraction of the step and target status of the next change (as ContactOperator). */
    std::pair<double, bool> event() const
    {
      const double infinity = std::numeric_limits<double>::infinity();
      if (changes >= max_changes)
        return {infinity, closed};
      if (!closed)
      {
        if (committed_gap >= 0. && gap < committed_gap)
          return {committed_gap / (committed_gap - gap), true};
        return {gap < -gap_tolerance ? 0. : infinity, true};
      }
      const double dRn = Rn - committed_Rn;
      if (dRn < 0. && committed_Rn >= 0.)
        return {committed_Rn / -dRn, false};
      return {Rn < -force_tolerance ? 0. : infinity, false};
    }
    void switch_status(const bool close)
    {
      if (close == closed)
        return;
      ++changes;
      fresh = hold_changed;
      closed = close;
    }

    static constexpr unsigned int max_changes = 6;
    static constexpr double       gap_tolerance = 1e-9;
    static constexpr double       force_tolerance = 1e-10;
    bool                          fresh = false, hold_changed = false, committed_closed = false;
    double                        committed_gap = g, committed_Rn = 0.;
  };

  /** The converged state at the end of a (sub-)step. */
  struct Record
  {
    double       t;
    bool         closed;
    double       u;
    double       Rn;
    unsigned int outer_passes;
  };

  /** The node on its spring as the Newton solver sees it, with the scene's calls into the
      strategy (Scene::assemble(), Scene::solve_step()). */
  class StopScene : public solver::NonlinearProblem
  {
  public:
    explicit StopScene(const contact::ContactStrategy strategy)
        : u(dealii::complete_index_set(1), MPI_COMM_SELF)
        , u_committed(u)
    {
      contact::ContactParameters parameters;
      parameters.strategy = strategy;
      parameters.ratio_tolerance = 1e-3;
      status_strategy = contact::make_status_strategy(parameters, node, true);
    }

    bool assemble(const bool, std::string &) override
    {
      status_strategy->begin_iterate(time);
      for (;;)
      {
        status_strategy->update_geometry(u);
        residual = k * u[0] - load(time);
        node.compute_reactions(residual);
        if (status_strategy->update_at_iterate() == 0)
          break;
      }
      return true;
    }
    double residual_norm() const override { return node.closed ? 0. : std::abs(residual); }
    double reference_force() const override
    {
      return std::max(std::abs(load(time)), node.closed ? std::abs(residual) : 0.);
    }
    double constraint_violation() const override { return node.closed ? std::abs(g - u[0]) : 0.; }
    solver::LinearSolveInfo solve_for_increment() override
    {
      start = u[0];
      increment = node.closed ? g - u[0] : -residual / k;
      return {};
    }
    void apply_increment(const double step) override
    {
      u[0] = start + step * increment;
      u.compress(dealii::VectorOperation::insert);
    }
    double length_scale() const override { return 1.; }
    double increment_residual_product() const override
    {
      return node.closed ? 0. : increment * residual;
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
        solver::NewtonResult result;
        unsigned int         passes = 0;
        for (;;)
        {
          time = t_done + dt;
          u = u_committed;
          result = solver::NewtonSolver(solver_parameters()).solve(*this, log);
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
        records.push_back({time, node.closed, u[0], node.Rn, passes});
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
    dealii::TrilinosWrappers::MPI::Vector    u, u_committed;
    double                                   time = 0., start = 0., increment = 0., residual = 0.;
  };

  /** Check @p records against the exact states at @p times (closed, u = min(f / k, g)). */
  void expect_exact(const std::vector<Record> &records,
                    const std::vector<double> &times,
                    const std::vector<bool>   &closed)
  {
    ASSERT_EQ(records.size(), times.size());
    for (unsigned int i = 0; i < times.size(); ++i)
    {
      SCOPED_TRACE("state " + std::to_string(i) + " at t = " + std::to_string(times[i]));
      EXPECT_NEAR(records[i].t, times[i], tol);
      EXPECT_EQ(records[i].closed, closed[i]);
      const double f = load(times[i]);
      EXPECT_NEAR(records[i].u, std::min(f / k, g), tol);
      if (closed[i])
      {
        EXPECT_NEAR(records[i].Rn, f - k * g, tol); // compressive reaction of the stop
      }
    }
  }
} // namespace

// Active set: the node closes inside Newton when the free iterate passes the stop (step 2) and
// opens at the first assembly of step 3 by its tensile reaction; no outer passes.
TEST(ContactStrategy, ActiveSetStatusSequenceAndExactStates)
{
  StopScene                 scene(contact::ContactStrategy::active_set);
  const std::vector<Record> records = scene.run();
  expect_exact(records, {0.25, 0.5, 0.75, 1.}, {false, true, false, false});
  for (const Record &r : records)
    EXPECT_EQ(r.outer_passes, 0u);
}

// Nested active set: closing inside Newton as with the active set (the node has not changed in
// the step), but the tensile reaction of step 3 is judged at the converged state: one outer pass
// in step 3, none elsewhere.
TEST(ContactStrategy, NestedActiveSetStatusSequenceAndExactStates)
{
  StopScene                 scene(contact::ContactStrategy::nested_active_set);
  const std::vector<Record> records = scene.run();
  expect_exact(records, {0.25, 0.5, 0.75, 1.}, {false, true, false, false});
  ASSERT_EQ(records.size(), 4u);
  EXPECT_EQ(records[0].outer_passes, 0u);
  EXPECT_EQ(records[1].outer_passes, 0u);
  EXPECT_EQ(records[2].outer_passes, 1u);
  EXPECT_EQ(records[3].outer_passes, 0u);
}

// Load-increment ratio: statuses fixed within a sub-step; steps 2 and 3 are cut at the events,
// which the sub-steps hit exactly (t_c = 0.3125, t_o = 0.6875), the status switching at their
// end; the grid of nominal steps is resumed afterwards.
TEST(ContactStrategy, LoadIncrementRatioHitsTheEventsExactly)
{
  StopScene                 scene(contact::ContactStrategy::load_increment_ratio);
  const std::vector<Record> records = scene.run();
  expect_exact(records, {0.25, t_c, 0.5, t_o, 0.75, 1.}, {false, true, true, false, false, false});
  for (const Record &r : records)
    EXPECT_EQ(r.outer_passes, 0u);
}

// The fixed-status base strategy (no dies): the node never closes and passes the stop.
TEST(ContactStrategy, FixedStatusesNeverChange)
{
  StopNode                   node;
  contact::ContactParameters parameters;
  const auto                 strategy = contact::make_status_strategy(parameters, node, false);
  dealii::TrilinosWrappers::MPI::Vector u(dealii::complete_index_set(1), MPI_COMM_SELF);
  u[0] = 2.;
  strategy->begin_iterate(0.5);
  strategy->update_geometry(u);
  EXPECT_FALSE(node.closed);
  EXPECT_NEAR(node.gap, -1., tol);
  EXPECT_EQ(strategy->update_at_iterate(), 0u);
  EXPECT_FALSE(strategy->backtrack_with_small_constraint_gaps());
}
