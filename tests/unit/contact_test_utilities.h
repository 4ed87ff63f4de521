/**
 * @file contact_test_utilities.h
 * Helpers shared by the contact unit tests.
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace ausroll::testing
{
  /** Die 0 of the `Contact` text @p die (the inside of `subsection Die 0`). */
  inline contact::DieParameters parse_die(const std::string &die)
  {
    dealii::ParameterHandler prm;
    contact::ContactParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection Contact\nset Number of dies = 1\nsubsection Die 0\n"
                                + die + "end\nend\n");
    contact::ContactParameters p;
    p.parse_parameters(prm, "");
    return p.dies[0];
  }
} // namespace ausroll::testing
