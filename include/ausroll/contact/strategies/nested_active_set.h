/**
 * @file nested_active_set.h
 * Contact strategy `nested active set` (subsection `Nested active set`): statuses judged at
 * converged states.
 */
#pragma once

#include <ausroll/contact/contact_strategy.h>

#include <memory>

namespace ausroll::contact
{
  /**
   * Nested active set (`Strategy = nested active set`): penetrating open nodes close at every
   * iterate unless they have changed in this step; all other status changes are judged at
   * converged states (an outer loop around Newton), a changed node only after a solve with its
   * new constraint. A node opened by tension that re-penetrates slightly in the next iterates does
   * not chatter. The line search may backtrack with second-order gaps on curved dies.
   */
  class NestedActiveSet : public StatusStrategy
  {
  public:
    /** With @p fresh_sticks_slip (`Fresh sticks slip`), every step starts with the nodes that
        closed in stick in the last step slipping (begin_step()). With @p changes_inside_newton
        > 0 (`Status changes inside Newton`), statuses are also judged at every iterate, for a
        node only while it has changed fewer times in this step (update_at_iterate()). */
    explicit NestedActiveSet(ContactStatusSet  &nodes,
                             const bool         fresh_sticks_slip = false,
                             const unsigned int changes_inside_newton = 0);

    /** Re-assemblies per Newton iterate after status changes (`Status changes inside Newton`). */
    static constexpr unsigned int max_reassemblies = 4;

    /** `Fresh sticks slip`: the nodes that closed in the last step and stick slip instead
        (ContactStatusSet::release_fresh_sticks()); a reversed slip sticks again at the first
        converged state. Otherwise nothing. */
    void begin_step(const ContactStatusSet::Vector &u, const double t_start) override;
    /** The committed statuses, with `Fresh sticks slip` released again as in begin_step(). */
    void restart_step() override;

    /** Clears the re-assembly count of update_at_iterate(). */
    void begin_iterate(const double t) override;
    void update_geometry(const ContactStatusSet::Vector &u) override;
    /**
     * `Status changes inside Newton` = N > 0: the reactions of each assembly judge the closed
     * nodes that have changed status fewer than N times in this step (every change counted:
     * closing, opening, stick/slip, at iterates or at converged states), as the active set does
     * for all nodes; a node changed here is judged again only at the next iterate. A node that
     * has used its N changes is held and judged only at converged states (update_at_convergence()),
     * so the answer is a converged state with consistent statuses as without the entry. N = 0:
     * none (the nested active set as before).
     */
    unsigned int update_at_iterate() override;
    unsigned int update_at_convergence(const ContactStatusSet::Vector &u,
                                       dealii::ConditionalOStream     &log) override;
    bool         backtrack_with_small_constraint_gaps() const override;
    /** Nodes that closed in the last step and stick slip instead
        (ContactStatusSet::release_fresh_sticks()); none with `Fresh sticks slip` (released from
        the start of the step). */
    unsigned int release_after_failure() override;

  private:
    const bool         fresh_sticks_slip;
    const unsigned int changes_inside_newton;
    unsigned int       passes = 0; ///< assemblies at this iterate (update_at_iterate())
  };

  /** Parameters of `nested active set` (subsection `Nested active set`). */
  struct NestedActiveSetParameters : public StrategyParameters
  {
    bool         fresh_sticks_slip = false; ///< `Fresh sticks slip`
    unsigned int changes_inside_newton = 0; ///< `Status changes inside Newton`

    /** Declare `Fresh sticks slip` and `Status changes inside Newton` (the caller has entered
        the subsection). */
    static void                     declare_parameters(dealii::ParameterHandler &prm);
    void                            parse(dealii::ParameterHandler &prm,
                                          const std::string        &path,
                                          const std::string        &input_directory) override;
    std::unique_ptr<StatusStrategy> create(ContactStatusSet &nodes) const override;
  };
} // namespace ausroll::contact
