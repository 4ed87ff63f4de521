// clang-format off
/**
 * @file contact_strategy.h
 * The contact strategies of `Contact/Strategy` as objects: each owns its loop logic (when nodes
 * close, when statuses are judged, how a load step ends), so that the scene makes the same calls
 * whatever the strategy. This file holds the interface (ContactStatusSet, StatusStrategy, the
 * fixed-status base), the parameters of a strategy and their registry; the strategies are in
 * contact/strategies/, one file pair each (active_set, nested_active_set, load_increment_ratio)
 * with its StrategyParameters, registered with AUSROLL_REGISTER_CONTACT_STRATEGY.
 *
 * A load step with contact, as the scene drives it:
 *
 *   begin_step()                   once per load step (before the first Newton solve)
 *   per Newton assembly:
 *     begin_iterate()              time of the iterate; statuses of the last iterate may be judged
 *     repeat:
 *       update_geometry()          project the nodes, close penetrating ones if the strategy
 *                                  says so
 *       (constraints, assembly, ContactOperator::compute_reactions())
 *     while update_at_iterate() > 0   (statuses changed at this iterate: re-assemble)
 *   at a converged iterate:
 *     update_at_convergence()      called by NonlinearProblem::update_constraints_at_convergence();
 *                                  changes: Newton continues with the new constraints
 *   backtrack_with_small_constraint_gaps()
 *                                  the NonlinearProblem hook of the same name (line search)
 *   end_of_step()                  after a converged solve: accept, repeat or shorten the step
 *   restart_step()                 after a failed solve (cutback, no predictor); then
 *   release_after_failure()        changes: one more solve of the same step before the cutback
 */
// clang-format on
#pragma once

#include <ausroll/contact/contact_parameters.h>
#include <ausroll/core/registry.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /**
   * What a contact strategy drives: the contact nodes with their projections, statuses and
   * committed state. ContactOperator<dim> implements it on the mesh; the unit tests implement it
   * on a node against a stop (tests/unit/test_contact_strategy.cc). All counts are global (over
   * the MPI ranks).
   */
  class ContactStatusSet
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    virtual ~ContactStatusSet() = default;

    /** Time of the current iterate (die poses). */
    virtual void set_time(const double t) = 0;

    /** A new displacement iterate begins: statuses changed at the previous iterate may be judged
        again (see hold_changed_nodes()). */
    virtual void start_iterate() = 0;

    /**
     * With @p hold, a node whose status changed at an iterate is judged again (closed, opened,
     * switched) only at the next iterate, after the equations have been solved with its new
     * constraint (nested active set). Without (default), it may change again at once.
     */
    virtual void hold_changed_nodes(const bool hold) = 0;

    /** Project all nodes at @p u; with @p allow_closing open penetrating nodes close (with
        @p only_unchanged_nodes only those that have not changed status in this step). Returns
        the number of closed nodes (local). */
    virtual unsigned int update_geometry(const Vector &u,
                                         const bool    allow_closing,
                                         const bool    only_unchanged_nodes = false)
        = 0;

    /** Project all nodes at @p u and close the open nodes that penetrate a die; returns the
        number of nodes closed. */
    virtual unsigned int close_penetrating_nodes(const Vector &u) = 0;

    /** No limit for update_statuses() beyond `Contact/Maximum status changes`. */
    static constexpr unsigned int no_change_limit = static_cast<unsigned int>(-1);

    /** Change statuses by the force criteria (tension opens, the friction limit slips, reversed
        slip sticks); only nodes that have changed fewer than @p change_limit times in this step
        (and fewer than `Contact/Maximum status changes`) are judged. Returns the number of
        changes. */
    virtual unsigned int update_statuses(const unsigned int change_limit) = 0;

    /** Fraction of the current step in [0, 1] at which the first node changes status (linear
        interpolation from the committed state); 1 if none. */
    virtual double event_ratio() const = 0;

    /** Switch every node whose event lies at or before @p alpha_limit; returns their number. */
    virtual unsigned int apply_events(const double alpha_limit) = 0;

    /** Close the open nodes that touch a die (gap zero within round-off); returns their number. */
    virtual unsigned int close_touching_nodes() = 0;

    /** Make the current statuses the statuses at the start of the step (gaps and forces of the
        committed state are kept). */
    virtual void promote_statuses() = 0;

    /** Return to the committed statuses (a step is solved again). */
    virtual void reset() = 0;

    /**
     * After a failed solve and reset(): let every node that closed in the last converged step
     * and sticks at the start of this one slip instead (friction force of the sign of its
     * committed tangential reaction, at the slip limit); returns the number of switched nodes.
     * Default: none.
     */
    virtual unsigned int release_fresh_sticks() { return 0; }
  };

  /** What the scene does after a converged solve of a (sub-)step (StatusStrategy::end_of_step()).
   */
  struct StepDecision
  {
    bool   accept = true;    ///< the step is done at the time reached
    double step_factor = 1.; ///< otherwise: solve again with dt * step_factor (1: same dt)
  };

  /**
   * A contact strategy (`Contact/Strategy`): the loop logic around the Newton solver that decides
   * when contact statuses change. This base class keeps the statuses fixed: nodes are projected at
   * every iterate but never close or open (the scene without dies uses it). Subclasses override
   * the hooks where their algorithm acts.
   */
  class StatusStrategy
  {
  public:
    /** A strategy acting on @p nodes (which must outlive it). */
    explicit StatusStrategy(ContactStatusSet &nodes);

    virtual ~StatusStrategy() = default;

    /** Start of a load step from the committed state @p u at time @p t_start. Default: nothing. */
    virtual void begin_step(const ContactStatusSet::Vector &u, const double t_start);

    /** A Newton assembly at time @p t begins (die poses of @p t; the previous iterate's changes
        may be judged). */
    virtual void begin_iterate(const double t);

    /** Project the nodes at the iterate @p u before the constraints are built. Default: project
        only, statuses unchanged. */
    virtual void update_geometry(const ContactStatusSet::Vector &u);

    /**
     * After an assembly whose reactions the scene has given to the contact nodes: change statuses
     * judged by them at this iterate. Returns the number of changes (the scene then rebuilds the
     * constraints and assembles again). Default: none.
     */
    virtual unsigned int update_at_iterate();

    /**
     * At a converged (or nearly converged) state @p u: change statuses; returns the number of
     * changes (Newton then continues with the new constraints). Default: none.
     */
    virtual unsigned int update_at_convergence(const ContactStatusSet::Vector &u,
                                               dealii::ConditionalOStream     &log);

    /** Whether the line search may backtrack while the contact constraints are only nearly met
        (see solver::NonlinearProblem). Default: false. */
    virtual bool backtrack_with_small_constraint_gaps() const;

    /**
     * After a converged solve of the step (sub-step) of size @p dt (@p end_time: the run's end,
     * for the round-off scale of a step): accept it, or solve it again (statuses changed) with
     * dt * step_factor. Default: accept.
     */
    virtual StepDecision
    end_of_step(const double dt, const double end_time, dealii::ConditionalOStream &log);

    /** A solve of the step failed: it is tried again from the committed state. Default: the
        committed statuses are restored. */
    virtual void restart_step();

    /**
     * A solve of the step failed and restart_step() has been called: change statuses for one
     * more solve of the same step before it is cut back; returns the number of changes (0: cut
     * back). Default: none.
     */
    virtual unsigned int release_after_failure();

  protected:
    ContactStatusSet &nodes; ///< the contact nodes
    double            time = 0.;
  };

  /**
   * The parameters of one contact strategy: the entries of its own subsection `Contact/<Name>`
   * (none for the active sets), registered in StrategyRegistry with
   * AUSROLL_REGISTER_CONTACT_STRATEGY at the end of the strategy's own `.cc`
   * (contact/strategies/).
   */
  class StrategyParameters : public RegisteredParameters
  {
  public:
    /** The strategy acting on @p nodes (which must outlive it). */
    virtual std::unique_ptr<StatusStrategy> create(ContactStatusSet &nodes) const = 0;
  };

  /** The registry of the contact strategies (`Contact/Strategy`). */
  using StrategyRegistry = Registry<StrategyParameters>;

  /**
   * The strategy `parameters.strategy` acting on @p nodes, made by its parameters
   * (`parameters.strategy_parameters`, or the registered defaults of `parameters.strategy` when
   * they are null); the fixed-status base strategy when @p has_dies is false (nothing to decide).
   */
  std::unique_ptr<StatusStrategy> make_status_strategy(const ContactParameters &parameters,
                                                       ContactStatusSet        &nodes,
                                                       const bool               has_dies);
} // namespace ausroll::contact

/** Register the contact-strategy parameters @p Class (see AUSROLL_REGISTER). */
#define AUSROLL_REGISTER_CONTACT_STRATEGY(Class, name, subsection, description) \
  AUSROLL_REGISTER(::ausroll::contact::StrategyParameters, Class, name, subsection, description)
