/**
 * @file surface_factory.h
 * The die shapes, 2D and 3D in one scheme: one parameters class and one `.prm` subsection of
 * `Contact/Die N` per shape (as `Geometry` has one subsection per workpiece type), registered in
 * the registry of its dimension (core/registry.h).
 *
 * A new shape: its file pair contact/surfaces/<shape>.{h,cc} with a ShapeParameters<dim> subclass
 * (static declare_parameters(), parse(), create()) and AUSROLL_REGISTER_DIE_SHAPE at the end of
 * its `.cc`; the `Shape` selection, the subsections, the parsing and doc/parameters.md follow
 * from the registry.
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/core/registry.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <string>

namespace ausroll::contact::surfaces
{
  /**
   * The parameters of one die shape of dimension @p dim: the entries of its subsection
   * `Contact/Die N/<Subsection>`. Every entry error is an InputError naming the full path of the
   * entry.
   */
  template <int dim>
  class ShapeParameters
  {
  public:
    virtual ~ShapeParameters() = default;

    /**
     * Read the shape's subsection (the caller has entered it). @p path is its full path with a
     * trailing slash ("Contact/Die 0/Circle/"); file names are resolved relative to
     * @p input_directory.
     */
    virtual void parse(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       const std::string        &input_directory)
        = 0;

    /** The shape in die coordinates; InputError naming the entries under @p path. */
    virtual std::unique_ptr<const RigidSurface<dim>> create(const std::string &path) const = 0;
  };

  /** The registry of the die shapes of dimension @p dim. */
  template <int dim>
  using ShapeRegistry = Registry<ShapeParameters<dim>>;

  /** The `Shape` selection: the 2D names, then the 3D names ("arc line|circle|...|torus"). */
  std::string shape_selection();

  /** Declare every shape's subsection (2D and 3D) inside the current `Contact/Die N`. */
  void declare_shape_parameters(dealii::ParameterHandler &prm);

  /**
   * The shape entries that moved into a shape subsection (before: one flat list under
   * @p parent_path, e.g. "Contact/Die 0/" or the `Profile` of a 3D shape): old full path -> new
   * full path(s), added to @p moved, for the error message an old `.prm` file gets.
   */
  void add_moved_shape_entries(const std::string                  &parent_path,
                               std::map<std::string, std::string> &moved);

  /** add_moved_shape_entries() for `Contact/Die N/` and the `Profile` of its revolved and
      extruded profile, for all @p n_dies dies. */
  std::map<std::string, std::string> moved_die_entries(unsigned int n_dies);
} // namespace ausroll::contact::surfaces

/** Register the die shape parameters @p Class of dimension @p dim (see AUSROLL_REGISTER). */
#define AUSROLL_REGISTER_DIE_SHAPE(dim, Class, name, subsection, description) \
  AUSROLL_REGISTER(                                                           \
      ::ausroll::contact::surfaces::ShapeParameters<dim>, Class, name, subsection, description)
