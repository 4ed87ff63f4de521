/**
 * @file flank_manifold.h
 * Manifold of one flank of an involute gear tooth: refined boundary vertices lie exactly on the
 * involute (and on the radial continuation below the base circle).
 */
#pragma once

#include <ausroll/geometry/involute_gear.h>

#include <deal.II/grid/manifold.h>

#include <memory>

namespace ausroll::geometry
{
  /**
   * Chart manifold of the flank @p side of the tooth whose axis points at polar angle
   * `axis_angle` about the gear centre (the origin). The chart coordinate is the radius r: a
   * point maps to r = |x|, and r maps back to InvoluteGear::flank_point(r, side) rotated by the
   * axis angle. New points (midpoints of refined faces) are therefore on the exact involute for
   * r >= r_b and on the radial flank for r < r_b.
   *
   * Used by create_gear_tooth_mesh() for the faces of `Geometry/Type = gear tooth` on the tooth
   * flanks (the gear data come from `Geometry/Gear tooth`).
   */
  class FlankManifold : public dealii::ChartManifold<2, 2, 1>
  {
  public:
    /** Flank @p side of @p gear, tooth axis at polar angle @p axis_angle (rad). */
    FlankManifold(const InvoluteGear &gear, FlankSide side, double axis_angle);

    /** A copy of this manifold. */
    std::unique_ptr<dealii::Manifold<2, 2>> clone() const override;

    /** Chart coordinate of @p space_point: its distance from the gear centre. */
    dealii::Point<1> pull_back(const dealii::Point<2> &space_point) const override;

    /** Flank point at radius @p chart_point[0]. */
    dealii::Point<2> push_forward(const dealii::Point<1> &chart_point) const override;

    /** Derivative of the flank point with respect to r: e_r -/+ u e_theta (u the roll angle). */
    dealii::DerivativeForm<1, 1, 2>
    push_forward_gradient(const dealii::Point<1> &chart_point) const override;

    /**
     * Distance of @p p from the flank measured along the circle of radius |p|: |p| times the
     * difference of the polar angle of @p p and that of the flank at |p| (used in tests).
     */
    double angular_distance(const dealii::Point<2> &p) const;

  private:
    /** The gear (from `Geometry/Gear tooth`). */
    InvoluteGear gear;
    /** Which flank of the tooth. */
    FlankSide side;
    /** Polar angle of the tooth axis (rad). */
    double axis_angle;
  };

  /**
   * The flank surface of FlankManifold extruded along z (the tooth of `Geometry/Type = extruded
   * gear tooth`): chart coordinates (r, z), a point maps to (|(x, y)|, z) and (r, z) back to the
   * 2D flank point at radius r with the same z. Refined points on the lateral flank faces are on
   * the exact involute in every plane z = const, and linear in z.
   */
  class ExtrudedFlankManifold : public dealii::ChartManifold<3, 3, 2>
  {
  public:
    /** Flank @p side of @p gear, tooth axis at polar angle @p axis_angle (rad) in the x-y plane. */
    ExtrudedFlankManifold(const InvoluteGear &gear, FlankSide side, double axis_angle);

    /** A copy of this manifold. */
    std::unique_ptr<dealii::Manifold<3, 3>> clone() const override;

    /** Chart coordinates (r, z) of @p space_point, r its distance from the z axis. */
    dealii::Point<2> pull_back(const dealii::Point<3> &space_point) const override;

    /** Flank point at radius @p chart_point[0] and height @p chart_point[1]. */
    dealii::Point<3> push_forward(const dealii::Point<2> &chart_point) const override;

    /** Derivative: the 2D flank derivative in x-y for r, e_z for z. */
    dealii::DerivativeForm<1, 2, 3>
    push_forward_gradient(const dealii::Point<2> &chart_point) const override;

    /** FlankManifold::angular_distance() of the projection of @p p on the x-y plane. */
    double angular_distance(const dealii::Point<3> &p) const;

  private:
    /** The 2D flank. */
    FlankManifold flank;
    /** Gear, side and axis: kept for clone(). */
    InvoluteGear gear;
    FlankSide    side;
    double       axis_angle;
  };
} // namespace ausroll::geometry
