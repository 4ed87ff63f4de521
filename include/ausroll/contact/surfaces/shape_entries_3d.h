/**
 * @file shape_entries_3d.h
 * Entry helpers shared by the 3D die shapes' subsections (plane.h, finite_cylinder.h, torus.h,
 * cone.h, revolved_profile.h, extruded_profile.h): 3D vectors and directions, the placement of an
 * axisymmetric shape (Center or Origin, Axis, Reference direction), and the translation of an
 * EntryError of a shape's constructor into an InputError naming the full entry path.
 */
#pragma once

#include <ausroll/core/exceptions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace ausroll::contact::surfaces
{
  /** Read a 3D vector entry @p name; InputError naming @p entry. */
  dealii::Tensor<1, 3>
  get_vector(dealii::ParameterHandler &prm, const std::string &name, const std::string &entry);

  /** Read a nonzero 3D direction entry @p name; InputError naming @p entry. */
  dealii::Tensor<1, 3>
  get_direction(dealii::ParameterHandler &prm, const std::string &name, const std::string &entry);

  /** Declare Center (or Origin)/Axis/Reference direction of an axisymmetric shape. */
  void declare_placement(dealii::ParameterHandler &prm,
                         const std::string        &center_name,
                         const std::string        &center_help,
                         const std::string        &axis_help,
                         const std::string        &reference_help);

  /** Read Center (or Origin)/Axis/Reference direction of a shape under @p path. */
  void parse_placement(dealii::ParameterHandler &prm,
                       const std::string        &center_name,
                       const std::string        &path,
                       dealii::Point<3>         &center,
                       dealii::Tensor<1, 3>     &axis,
                       dealii::Tensor<1, 3>     &reference);

  /** Run a constructor; an EntryError it throws becomes an InputError under @p path. */
  template <typename Make>
  auto with_path(const std::string &path, Make make)
  {
    try
    {
      return make();
    }
    catch (const EntryError &e)
    {
      throw InputError(path + e.entry() + ": " + e.what_is_wrong());
    }
  }
} // namespace ausroll::contact::surfaces
