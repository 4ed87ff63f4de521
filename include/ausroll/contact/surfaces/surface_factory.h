/**
 * @file surface_factory.h
 * The 2D die shapes: one parameter struct and one `.prm` subsection of `Contact/Die N` per shape
 * (as `Geometry` has one subsection per workpiece type), and the one table that lists them
 * (surface_factory.cc).
 *
 * A new 2D shape: its file pair contact/surfaces/<shape>.{h,cc} with a ShapeParameters subclass
 * (declare_parameters(), parse(), create()) and one line in the table of surface_factory.cc; the
 * `Shape` selection, the subsections and the parsing follow from the table.
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <string>

namespace ausroll::contact::surfaces
{
  /**
   * The parameters of one die shape: the entries of its subsection `Contact/Die N/<Subsection>`.
   * Every entry error is an InputError naming the full path of the entry.
   */
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
    virtual std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const = 0;
  };

  /** The `Shape` selection: "flat|circle|...". */
  std::string shape_selection();

  /** Declare every shape's subsection inside the current `Contact/Die N` subsection. */
  void declare_shape_parameters(dealii::ParameterHandler &prm);

  /**
   * Read the subsection of the shape named @p shape (a `Shape` value) of the current die
   * subsection, whose full path is @p die_path ("Contact/Die 0/").
   */
  std::shared_ptr<const ShapeParameters> parse_shape_parameters(const std::string        &shape,
                                                                dealii::ParameterHandler &prm,
                                                                const std::string        &die_path,
                                                                const std::string &input_directory);

  /** Full path of shape @p shape's subsection in die @p die_path ("Contact/Die 0/Circle/"). */
  std::string shape_path(const std::string &shape, const std::string &die_path);

  /**
   * The die entries that moved into a shape subsection (before: one flat list under
   * `Contact/Die N`): old full path -> new full path(s), for all dies, for the error message
   * an old `.prm` file gets.
   */
  std::map<std::string, std::string> moved_die_entries(unsigned int n_dies);
} // namespace ausroll::contact::surfaces
