/**
 * @file contact_parameters.h
 * The `Contact` subsection: rigid dies, their motion and friction, and the contact strategy.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ausroll::contact
{
  class FrictionParameters;
  class MotionParameters;
  class StrategyParameters;

  /** True if @p shape (a `Shape` value) names a 3D die shape. */
  bool is_3d_shape(const std::string &shape);

  /** One `Contact/Die N` subsection. */
  struct DieParameters
  {
    std::string name = "die";             ///< `Name` (history columns die_<name>_...)
    std::string friction_law = "Coulomb"; ///< `Friction`: the name of a registered law
    /** The entries of the law's own subsection `Contact/Die N/<Friction>` (friction_law.h); null:
        frictionless. */
    std::shared_ptr<const FrictionParameters> friction;
    std::vector<unsigned int> candidate_boundaries; ///< `Candidate boundaries` of the workpiece
    double                    search_distance = 0.; ///< `Search distance` (0: unlimited)

    /** `Shape`: the name of a registered 2D or 3D die shape (contact/surfaces/
        surface_factory.h); RigidDie<dim> checks the dimension. */
    std::string shape = "flat";
    /** The entries of a 2D shape's own subsection `Contact/Die N/<Shape>` (die-local
        coordinates, at t = 0 when the motion is the identity); set by parse_parameters(); null
        for a 3D shape. */
    std::shared_ptr<const surfaces::ShapeParameters<2>> surface;
    /** The entries of a 3D shape's own subsection (`Plane`, `Cylinder`, ...); null for a 2D
        shape. */
    std::shared_ptr<const surfaces::ShapeParameters<3>> surface_3d;
    /** Full path of that subsection ("Contact/Die 0/Circle/") for error messages. */
    std::string surface_path;

    /** `Motion/Type`: the name of a registered die motion (contact/die_motion.h). */
    std::string motion_type = "fixed";
    /** The entries of the motion's own subsection `Contact/Die N/Motion/<Type>` (none for
        `fixed`); set by parse_parameters(). */
    std::shared_ptr<const MotionParameters> motion;
    /** Full path of that subsection ("Contact/Die 0/Motion/Rolling/") for error messages. */
    std::string motion_path;
  };

  /** Parameters of subsection `Contact`. */
  struct ContactParameters
  {
    static constexpr unsigned int max_dies = 4; ///< `Die 0` .. `Die 3`
    /** `Strategy`: the name of a registered contact strategy (contact/contact_strategy.h). */
    std::string strategy = "active set";
    /** The entries of the strategy's own subsection `Contact/<Strategy>` (`Load increment
        ratio`); set by parse_parameters(); null: the registered defaults of `strategy`. */
    std::shared_ptr<const StrategyParameters> strategy_parameters;
    std::vector<DieParameters>                dies; ///< the first `Number of dies`
    unsigned int max_status_changes = 6;            ///< `Maximum status changes` per node and step
    /** `Curvature tangent`: the turning of the die normal in the tangent of slipping nodes
        (contact/curved_die_tangent.h). */
    bool curvature_tangent = false;
    /** `Penetrating boundaries = add`: a workpiece boundary that is not a candidate of a die
        but passes through it becomes one, and the step is solved again; false (`warn`): only
        warn. */
    bool add_penetrating_boundaries = true;

    /** Declare subsection `Contact`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /**
     * The entries an old `.prm` file may still set and where they are now: old full path ->
     * new full path(s) (the shape entries moved from `Contact/Die N` into one subsection per
     * shape, the friction entries into one subsection per law, the motion entries into one
     * subsection of `Motion` per motion, `Ratio tolerance` into `Load increment ratio`). Reading
     * the file turns such an unknown entry into this message.
     */
    static std::map<std::string, std::string> moved_entries();
    /** Read subsection `Contact`. Files are resolved relative to @p input_directory. */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &input_directory);
  };
} // namespace ausroll::contact
