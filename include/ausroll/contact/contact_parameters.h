/**
 * @file contact_parameters.h
 * The `Contact` subsection: rigid dies, their motion and friction, and the contact strategy.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace ausroll::contact
{
  /** How contact statuses are found (`Contact/Strategy`). */
  enum class ContactStrategy
  {
    active_set,          ///< statuses updated inside the Newton loop (semi-smooth Newton)
    nested_active_set,   ///< Newton converges with fixed statuses, then they are updated and
                         ///< Newton continues (outer loop; robust for rolling with friction)
    load_increment_ratio ///< statuses fixed per sub-step; steps scaled to the next status change
                         ///< (NOFEAP)
  };

  /** Friction law of a die (`Friction`); the laws themselves are in friction_law.h. */
  enum class FrictionLawType
  {
    frictionless,           ///< no tangential force: closed nodes slip freely
    coulomb,                ///< |t_t| <= mu p_n
    sticking,               ///< no slip (mu = infinity): closed nodes stick
    tresca,                 ///< constant shear |t_t| <= m k
    coulomb_capped_by_shear ///< |t_t| <= min(mu p_n, m k)
  };

  /** Shape of a die (`Shape`). */
  enum class DieShape
  {
    flat,         ///< straight line through `Point` with outward `Normal`
    circle,       ///< circle (`Center`, `Radius`); a roll or a cylindrical punch
    polyline,     ///< open chain through `Points` (inline) or `Points file`
    arc_line,     ///< polyline whose interior corners are rounded with `Fillet radii`
    involute_gear ///< spur gear (or a sector of it) with involute flanks
  };

  /** Motion of a die (`Motion/Type`). */
  enum class MotionType
  {
    fixed,      ///< the die does not move
    prescribed, ///< translation and rotation as functions of t
    rolling     ///< planetary rolling about the workpiece centre (NOFEAP section 4.1)
  };

  /** One `Contact/Die N` subsection. */
  struct DieParameters
  {
    std::string     name = "die";           ///< `Name` (history columns die_<name>_...)
    DieShape        shape = DieShape::flat; ///< `Shape`
    FrictionLawType friction = FrictionLawType::coulomb; ///< `Friction`
    double friction_coefficient = 0.; ///< `Friction coefficient` mu (Coulomb, capped Coulomb)
    double friction_factor = 0.;      ///< `Friction factor` m (Tresca, capped Coulomb)
    /** Shear yield stress k = sigma_0 / sqrt(3) of the workpiece (initial yield stress
        `Material/Yield stress`), set by ContactParameters::set_workpiece_yield_stress(). */
    double                    shear_yield_stress = 0.;
    std::vector<unsigned int> candidate_boundaries; ///< `Candidate boundaries` of the workpiece
    double                    search_distance = 0.; ///< `Search distance` (0: unlimited)

    // shapes (die-local coordinates, at t = 0 when the motion is the identity)
    dealii::Point<2> point{0., 0.};  ///< flat: `Point`
    dealii::Point<2> normal{0., 1.}; ///< flat: `Normal` (out of the die, towards the workpiece)
    dealii::Point<2> center{0., 0.}; ///< circle: `Center`
    double           radius = 1.;    ///< circle: `Radius`
    bool             material_inside = true; ///< circle: `Material inside` (roll/punch) or a hole
    std::string      points;                 ///< polyline/arc line: `Points` "x, y; x, y; ..."
    std::string      points_file;            ///< polyline/arc line: `Points file`
    std::vector<double> fillet_radii;        ///< arc line: `Fillet radii`
    // involute gear
    unsigned int teeth = 57;            ///< `Number of teeth`
    double       diametral_pitch = 8.5; ///< `Diametral pitch` (1/inch; 0: use Module)
    double       module = 0.;           ///< `Module` (mm)
    double       pressure_angle = 22.;  ///< `Pressure angle` (degrees)
    double       addendum = -1.;        ///< `Addendum` (mm; <0: 1 module)
    double       dedendum = -1.;        ///< `Dedendum` (mm; <0: 1.25 module)
    double tooth_thickness = -1.;  ///< `Tooth thickness` at the pitch circle (mm; <0: half pitch)
    double fillet_radius = 0.;     ///< `Root fillet radius` (mm)
    double tip_radius = 0.;        ///< `Tip radius` (mm; 0: sharp tip corners)
    double tooth_axis_angle = 0.;  ///< `Tooth axis angle` (degrees)
    unsigned int sector_teeth = 0; ///< `Teeth in sector` (0: whole gear)

    // motion
    MotionType       motion = MotionType::fixed; ///< `Motion/Type`
    std::string      translation = "0; 0";       ///< `Motion/Translation` u(t) (mm)
    std::string      rotation = "0";             ///< `Motion/Rotation` phi(t) (degrees)
    dealii::Point<2> pivot{0., 0.};              ///< `Motion/Pivot` (die-local rotation centre)
    dealii::Point<2> workpiece_center{0., 0.};   ///< rolling: `Workpiece center`
    double           workpiece_radius = 1.;      ///< rolling: `Workpiece rolling radius` R_G
    double           die_radius = 1.;            ///< rolling: `Die rolling radius` R_D
    double           center_distance = 0.; ///< rolling: `Initial center distance` (0: R_G + R_D)
    double           line_angle = 90.;     ///< rolling: `Initial line angle` (degrees)
    int              direction = 1;        ///< rolling: `Direction` (+1 counter-clockwise, -1)
    double           beta = 1.;            ///< rolling: `Rolling factor` beta (1 pure rolling)
    std::string      revolution = "0";     ///< rolling: `Revolution angle` theta_G(t) (degrees)
    std::string      slip = "0";           ///< rolling: `Slip angle` theta_s(t) (degrees)
    std::string      feed = "0";           ///< rolling: `Feed` f(t) (mm)
  };

  /** Parameters of subsection `Contact`. */
  struct ContactParameters
  {
    static constexpr unsigned int max_dies = 4;                           ///< `Die 0` .. `Die 3`
    ContactStrategy               strategy = ContactStrategy::active_set; ///< `Strategy`
    std::vector<DieParameters>    dies;  ///< the first `Number of dies`
    unsigned int max_status_changes = 6; ///< `Maximum status changes` per node and step
    double       ratio_tolerance = 1e-3; ///< `Ratio tolerance` of the load-increment ratio

    /** Declare subsection `Contact`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Contact`. Files are resolved relative to @p input_directory. */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &input_directory);

    /**
     * The workpiece's initial uniaxial yield stress sigma_0 (`Material/Yield stress`; 0 for an
     * elastic workpiece) gives k = sigma_0 / sqrt(3) of the shear friction laws (Tresca, Coulomb
     * capped by shear). Call after parse_parameters(); throws InputError naming the die's
     * `Friction` if such a law meets an elastic workpiece.
     */
    void set_workpiece_yield_stress(const double sigma_0);
  };
} // namespace ausroll::contact
