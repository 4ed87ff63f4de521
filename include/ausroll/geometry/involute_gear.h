/**
 * @file involute_gear.h
 * Spur gear geometry with involute flanks: radii, the involute function, tooth thickness at any
 * radius, flank points and normals, and sampled tooth / gear outlines for mesh generation.
 *
 * Units: all lengths are in mm, all angles in radians. Inputs given in inches (diametral pitch in
 * teeth per inch) are converted with mm_per_inch = 25.4 by InvoluteGear::from_diametral_pitch().
 *
 * Tooth-centred frame (used by every function that returns points): the gear centre is the
 * origin, the centre line of the reference tooth is the +x axis, and polar angles are measured
 * counter-clockwise from +x. The tooth is symmetric about +x; its @em positive flank is the one at
 * positive polar angles (+theta_h(r)), its @em negative flank the mirror image at -theta_h(r).
 * Functions taking an @p axis_angle rotate this frame so that the tooth axis points at that polar
 * angle.
 */
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <optional>
#include <vector>

namespace ausroll::geometry
{
  /** Millimetres per inch, used to convert diametral pitch and inch dimensions. */
  constexpr double mm_per_inch = 25.4;

  /**
   * Optional tooth proportions of a spur gear, all in mm. An empty optional means the standard
   * full-depth value of the gear's module m.
   */
  struct ToothProportions
  {
    /** Radial distance from the pitch circle to the tip circle; default 1.0 m. */
    std::optional<double> addendum;
    /** Radial distance from the pitch circle to the root circle; default 1.25 m. */
    std::optional<double> dedendum;
    /** Arc tooth thickness on the pitch circle; default half the circular pitch, pi m / 2. */
    std::optional<double> pitch_tooth_thickness;
    /** Radius of the circular root fillet, tangent to the root circle and the flank; 0 = sharp. */
    double root_fillet_radius = 0.0;
  };

  /** Which flank of a tooth (in the tooth-centred frame, see the file documentation). */
  enum class FlankSide
  {
    positive, ///< flank at positive polar angles (counter-clockwise side of the tooth axis)
    negative  ///< flank at negative polar angles (mirror image about the tooth axis)
  };

  /** The geometric piece of a tooth outline a sampled segment belongs to. */
  enum class OutlinePart
  {
    root_land,      ///< arc of the root circle between two teeth
    root_fillet,    ///< circular fillet between root circle and flank
    radial_flank,   ///< radial straight flank below the base circle (root below base circle)
    involute_flank, ///< involute flank between base (or fillet) and tip circle
    tip_land        ///< arc of the tip (outside) circle
  };

  /**
   * A sampled outline: a chain of points and, for each straight segment, the part of the tooth
   * it approximates. For an open outline parts[i] belongs to the segment points[i] -> points[i+1]
   * (so parts.size() == points.size() - 1); for a closed outline there is one more segment from the
   * last point back to the first (parts.size() == points.size()). All points lie exactly on the
   * analytic curves.
   */
  struct ToothOutline
  {
    /** Outline points, counter-clockwise about the gear centre (gear material on the left). */
    std::vector<dealii::Point<2>> points;
    /** Part of the tooth that each segment samples (see the class documentation). */
    std::vector<OutlinePart> parts;
    /** Whether the last point connects back to the first one. */
    bool closed = false;
  };

  /**
   * The analytic pieces of one tooth in the tooth-centred frame (positive flank; the negative
   * flank is the mirror image about the x axis). Used to build exact die surfaces.
   */
  struct ToothGeometry
  {
    /** Polar angle beta_0 at which the positive-flank involute leaves the base circle. */
    double base_half_angle = 0.0;
    /** Half-thickness angle theta_h at the tip circle (polar angle of the tip corner). */
    double tip_half_angle = 0.0;
    /** Radius at which the working flank starts (fillet tangency point, or root radius). */
    double flank_start_radius = 0.0;
    /** Polar angle where the root land ends at the flank side (fillet tangency on the root). */
    double root_land_angle = 0.0;
    /** Centre of the root fillet of the positive flank (only meaningful for a fillet > 0). */
    dealii::Point<2> fillet_center;
    /** True if the flank starts below the base circle with a radial straight piece. */
    bool has_radial_flank = false;
  };

  /**
   * Geometry of an external spur gear with involute teeth.
   *
   * Standard relations (z teeth, module m = 25.4 mm / P_d, pressure angle alpha):
   * pitch radius r_p = m z / 2, base radius r_b = r_p cos(alpha), tip radius r_p + addendum,
   * root radius r_p - dedendum. The arc tooth thickness at radius r is
   * s(r) = 2 r (s_p / (2 r_p) + inv(alpha) - inv(alpha_r)) with cos(alpha_r) = r_b / r and
   * inv(a) = tan(a) - a; half_thickness_angle() returns s(r) / (2 r).
   *
   * Below the base circle the flank is continued by a radial straight line (the common
   * approximation when the root circle lies inside the base circle), then joined to the root
   * circle by a circular fillet of radius ToothProportions::root_fillet_radius (tangent to both).
   */
  class InvoluteGear
  {
  public:
    /**
     * Gear from @p n_teeth, @p module (mm), @p pressure_angle (rad) and optional @p proportions
     * (mm). Throws ausroll::InputError for inconsistent data: non-positive sizes, a root circle at
     * or below the centre, a tooth that is pointed below the tip circle, a negative space width at
     * the root, or a fillet that does not fit.
     */
    InvoluteGear(unsigned int            n_teeth,
                 double                  module,
                 double                  pressure_angle,
                 const ToothProportions &proportions = ToothProportions());

    /**
     * Gear specified in the inch system: @p diametral_pitch in teeth per inch (module =
     * 25.4 / P_d mm). The @p proportions are still in mm (multiply inch values by mm_per_inch);
     * their defaults (1/P_d, 1.25/P_d, half circular pitch) follow from the module.
     */
    static InvoluteGear from_diametral_pitch(unsigned int            n_teeth,
                                             double                  diametral_pitch,
                                             double                  pressure_angle,
                                             const ToothProportions &proportions
                                             = ToothProportions());

    /**
     * Gear from the entries of a `.prm` gear subsection: from_diametral_pitch() if
     * @p diametral_pitch > 0 (`Diametral pitch`), otherwise the metric constructor with @p module
     * (`Module`); @p pressure_angle in radians.
     */
    static InvoluteGear from_pitch_or_module(unsigned int            n_teeth,
                                             double                  diametral_pitch,
                                             double                  module,
                                             double                  pressure_angle,
                                             const ToothProportions &proportions
                                             = ToothProportions());

    /** The involute function inv(a) = tan(a) - a. */
    static double involute(double angle);

    /** Inverse of the involute function: the angle a in [0, pi/2) with inv(a) = @p value >= 0. */
    static double inverse_involute(double value);

    /**
     * Point of the standard involute of a base circle of radius @p base_radius centred at the
     * origin, starting at (r_b, 0) and unwinding counter-clockwise, at roll angle @p roll_angle:
     * (r_b (cos u + u sin u), r_b (sin u - u cos u)).
     */
    static dealii::Point<2> involute_point(double base_radius, double roll_angle);

    /** Number of teeth z. */
    unsigned int n_teeth() const { return z; }
    /** Module m in mm. */
    double module() const { return m; }
    /** Diametral pitch P_d = 25.4 / m in teeth per inch. */
    double diametral_pitch() const { return mm_per_inch / m; }
    /** Pressure angle alpha at the pitch circle (rad). */
    double pressure_angle() const { return alpha; }
    /** Addendum (mm). */
    double addendum() const { return add; }
    /** Dedendum (mm). */
    double dedendum() const { return ded; }
    /** Arc tooth thickness at the pitch circle (mm). */
    double pitch_tooth_thickness() const { return s_p; }
    /** Root fillet radius (mm). */
    double root_fillet_radius() const { return rho_f; }

    /** Pitch radius r_p = m z / 2 (mm). */
    double pitch_radius() const;
    /** Base radius r_b = r_p cos(alpha) (mm). */
    double base_radius() const;
    /** Tip (outside) radius r_p + addendum (mm). */
    double tip_radius() const;
    /** Root radius r_p - dedendum (mm). */
    double root_radius() const;
    /** Circular pitch pi m (mm). */
    double circular_pitch() const;
    /** Angular pitch 2 pi / z (rad). */
    double angular_pitch() const;

    /** Pressure angle alpha_r = acos(r_b / r) of the involute at radius @p r (0 below r_b). */
    double pressure_angle_at(double r) const;

    /** Roll angle u = tan(alpha_r) = sqrt(r^2 / r_b^2 - 1) of the involute at radius @p r. */
    double roll_angle_at(double r) const;

    /**
     * Half-thickness angle theta_h(r) = s_p / (2 r_p) + inv(alpha) - inv(alpha_r): the polar angle
     * of the positive flank at radius @p r. Below the base circle the (radial) flank has the
     * constant angle theta_h(r_b).
     */
    double half_thickness_angle(double r) const;

    /** Arc tooth thickness s(r) = 2 r theta_h(r) at radius @p r (mm). */
    double tooth_thickness(double r) const;

    /** Point of flank @p side at radius @p r in the tooth-centred frame. */
    dealii::Point<2> flank_point(double r, FlankSide side) const;

    /**
     * Unit normal of flank @p side at radius @p r pointing out of the tooth (into the tooth
     * space). On the involute it is tangent to the base circle (along the line of action).
     */
    dealii::Tensor<1, 2> flank_normal(double r, FlankSide side) const;

    /**
     * @p n_points points (n_points >= 2) of flank @p side from radius @p r_from to @p r_to
     * (both within [root radius, tip radius]) in the tooth-centred frame, equally spaced in radius.
     */
    std::vector<dealii::Point<2>>
    flank(FlankSide side, double r_from, double r_to, unsigned int n_points) const;

    /** The analytic pieces of the reference tooth (computed once in the constructor). */
    const ToothGeometry &tooth_geometry() const { return tooth; }

    /**
     * Open outline of one tooth, counter-clockwise about the gear centre, from the middle of the
     * preceding tooth space (polar angle axis_angle - pi/z on the root circle) to the middle of
     * the following one (axis_angle + pi/z): root land, fillet, flank, tip land, flank, fillet,
     * root land. No segment is longer than @p max_segment_length (mm) and each analytic piece has
     * at least one segment. The tooth axis is at polar angle @p axis_angle.
     */
    ToothOutline tooth_outline(double max_segment_length, double axis_angle = 0.0) const;

    /**
     * Closed outline of the whole gear (z teeth, counter-clockwise), tooth 0 with its axis at polar
     * angle @p axis_angle and tooth k at axis_angle + k 2 pi / z. Segment lengths as in
     * tooth_outline().
     */
    ToothOutline gear_outline(double max_segment_length, double axis_angle = 0.0) const;

  private:
    /** Compute the fillet and the tooth pieces (#tooth); throws if the tooth does not fit. */
    void compute_tooth_geometry();

    /** Number of teeth. */
    unsigned int z;
    /** Module (mm). */
    double m;
    /** Pressure angle (rad). */
    double alpha;
    /** Addendum (mm). */
    double add;
    /** Dedendum (mm). */
    double ded;
    /** Arc tooth thickness on the pitch circle (mm). */
    double s_p;
    /** Root fillet radius (mm). */
    double rho_f;
    /** Analytic pieces of the reference tooth. */
    ToothGeometry tooth;
  };
} // namespace ausroll::geometry
