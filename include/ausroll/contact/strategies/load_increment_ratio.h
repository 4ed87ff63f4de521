/**
 * @file load_increment_ratio.h
 * Contact strategy `load increment ratio` (subsection `Contact/Load increment ratio`): steps
 * scaled to the next status change (NOFEAP).
 */
#pragma once

#include <ausroll/contact/contact_strategy.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /**
   * Load-increment ratio (`Strategy = load increment ratio`, NOFEAP Appendix A): statuses are
   * fixed during a sub-step; after each converged sub-step the fraction alpha of it at which the
   * first node changes status is found by linear interpolation from the committed state, and the
   * sub-step is shortened to alpha (the change then lies at its end) until alpha >= 1 - tolerance;
   * the changes at the end are then applied. Nodes touching a die at the start of a step close
   * before it; a change at the very start of a sub-step is applied and the sub-step solved again.
   */
  class LoadIncrementRatio : public StatusStrategy
  {
  public:
    /** @p tolerance: `Load increment ratio/Ratio tolerance`, the fraction of a sub-step within
        which an event counts as at its end (or start). */
    LoadIncrementRatio(ContactStatusSet &nodes, const double tolerance);

    /** Sub-steps per load step after which the step is accepted whatever alpha. */
    static constexpr unsigned int max_substeps = 200;

    void begin_step(const ContactStatusSet::Vector &u, const double t_start) override;
    StepDecision
    end_of_step(const double dt, const double end_time, dealii::ConditionalOStream &log) override;

  private:
    double       tolerance;
    unsigned int substeps = 0; ///< sub-steps of the current load step
  };

  /** Subsection `Load increment ratio`. */
  struct LoadIncrementRatioParameters : public StrategyParameters
  {
    double tolerance = 1e-3; ///< `Ratio tolerance`

    /** Declare `Ratio tolerance` (the caller has entered the subsection). */
    static void                     declare_parameters(dealii::ParameterHandler &prm);
    void                            parse(dealii::ParameterHandler &prm,
                                          const std::string        &path,
                                          const std::string        &input_directory) override;
    std::unique_ptr<StatusStrategy> create(ContactStatusSet &nodes) const override;
  };
} // namespace ausroll::contact
