/**
 * @file parameter_documentation.h
 * `ausroll --print-parameters`: every parameter with default and documentation.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace ausroll::io
{
  /**
   * Print every entry declared in @p prm to @p out, as a commented .prm file (@p format = "prm")
   * or as the Markdown reference doc/parameters.md (@p format = "markdown"). The caller declares
   * the parameters (`ausroll --print-parameters` passes scene::SceneParameters::
   * declare_parameters()): io/ formats any ParameterHandler and needs to know no scene.
   */
  void print_parameters(std::ostream                   &out,
                        const std::string              &format,
                        const dealii::ParameterHandler &prm);
} // namespace ausroll::io
