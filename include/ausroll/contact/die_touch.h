/**
 * @file die_touch.h
 * Whether each die touched the workpiece during a run (the die-touch diagnostics at its end).
 */
#pragma once

#include <ausroll/contact/contact_operator.h>

#include <string>
#include <vector>

namespace ausroll::contact
{
  /**
   * Which dies had a node in contact (stick or slip) at the end of some converged step. A die
   * that never touched the workpiece is a set-up error (wrong position, feed or direction):
   * everything is written, but the run must not look like a forming result.
   */
  class DieTouchRecord
  {
  public:
    /** Record the statuses of the converged step of @p contact (nothing without dies). */
    template <int dim>
    void record(const ContactOperator<dim> &contact);

    /**
     * The end of a run of @p n_steps steps with the dies of @p contact: if no die touched, a
     * RunFailure naming the first untouched die; otherwise one warning per untouched die (a
     * shortened run of a scene whose later die comes in later). Nothing if nothing was recorded.
     */
    template <int dim>
    std::vector<std::string> untouched_warnings(const ContactOperator<dim> &contact,
                                                unsigned int                n_steps) const;

  private:
    std::vector<bool> touched; ///< per die
  };
} // namespace ausroll::contact
