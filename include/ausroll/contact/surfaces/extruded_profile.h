/**
 * @file extruded_profile.h
 * 3D rigid surface: a 2D curve chain (geometry::CurveChain) in the canonical (x, y) plane extruded
 * along z, over z in [z0, z1] (finite, optionally with flat end caps) or infinitely (a spur-gear
 * die from involute_gear_chain(), a straight-knurl roll, a flat die of finite width).
 *
 * Conventions (in addition to rigid_surface.h), canonical frame (e1, e2, e3 = extrusion axis):
 * - Mantle: x_proj = (p, z) with p the chain's projection of (x, y); n = (n_2D, 0);
 *   t_1 = e3, t_2 = (t_2D, 0) (the chain's direction of travel), so t_1 x t_2 = n;
 *   surface coordinates (z, s) with s the chain's curvilinear coordinate; curvatures
 *   (0, kappa_2D).
 * - Caps (with caps): the die material is the prism {2D material side} x [z0, z1] (for an open
 *   chain the material side is that of the nearest segment, as in 2D). On the cap z = z1 the
 *   normal is +e3 with t_1 = e1, t_2 = e2; on z = z0 it is -e3 with t_1 = e2, t_2 = e1;
 *   coordinates (z_cap, s of the chain point nearest to (x, y)); curvatures 0. The cap edges are
 *   convex edges (at_edge, normal (x - x_proj)/|x - x_proj|, t_2 = t_2D along the edge).
 *   Inside the prism the nearer of the mantle and the cap wins. The projection is exact (the
 *   distance to a product set splits into its 2D and axial parts).
 * - Without caps and finite: the surface is open at z0 and z1; a point beyond projects onto the
 *   end line (at_end, at_edge), normal +-(x - x_proj)/|x - x_proj| with the sign of the 2D gap.
 * - Chain corners are edges (at_edge), chain ends rims (at_end), as in 2D.
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/contact/surfaces/profile_parameters.h>
#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/geometry/curve_chain.h>

#include <limits>

namespace ausroll::contact::surfaces
{
  /** A 2D chain extruded along z (see the file documentation). */
  class ExtrudedProfile : public RigidSurface<3>
  {
  public:
    /**
     * Extrude @p profile (canonical (x, y)) over z in [@p z0, @p z1] (z0 < z1; infinite bounds
     * allowed: -inf, +inf gives an infinite extrusion); @p caps closes the finite ends with flat
     * faces. @p origin, @p axis (e3) and @p reference (e1, the profile's x direction; zero: chosen)
     * place the canonical frame. Throws EntryError for z0 >= z1 or caps on an infinite end.
     */
    ExtrudedProfile(const geometry::CurveChain &profile,
                    double                      z0 = -std::numeric_limits<double>::infinity(),
                    double                      z1 = std::numeric_limits<double>::infinity(),
                    bool                        caps = false,
                    const dealii::Point<3>     &origin = dealii::Point<3>(),
                    const dealii::Tensor<1, 3> &axis = dealii::Tensor<1, 3>({0., 0., 1.}),
                    const dealii::Tensor<1, 3> &reference = dealii::Tensor<1, 3>({1., 0., 0.}));

    std::string name() const override { return "extruded profile"; }

    SurfaceProjection<3> project(const dealii::Point<3> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    /** The mantle point with coordinates (z, s): the profile point at s (wrapped or clamped as
     * CurveChain::point_at()) at z clamped to [z0, z1]. The end caps are not reached (their
     * coordinates are not unique). */
    dealii::Point<3> point_at(const std::array<double, 2> &coordinates) const override;

    /** z is not periodic; s has the period of a closed profile (0 for an open one). */
    std::array<double, 2> coordinate_periods() const override;

    /** The profile chain. */
    const geometry::CurveChain &profile() const { return chain; }

  private:
    geometry::CurveChain chain;
    double               z_lo, z_hi;
    bool                 with_caps;
    Frame3D              frame;
  };

  /** Subsection `Extruded profile`. */
  struct ExtrudedProfileParameters : public ShapeParameters<3>
  {
    /** `Extent` along the axis. */
    enum class Extent
    {
      infinite,        ///< z unbounded
      finite,          ///< [Start z, End z], open ends
      finite_with_caps ///< [Start z, End z] closed by flat end caps
    };
    dealii::Point<3>     origin;                    ///< `Origin`
    dealii::Tensor<1, 3> axis;                      ///< `Axis` (extrusion direction)
    dealii::Tensor<1, 3> reference;                 ///< `Reference direction` (profile x)
    Extent               extent = Extent::infinite; ///< `Extent`
    double               z0 = 0.;                   ///< `Start z`
    double               z1 = 1.;                   ///< `End z`
    ProfileParameters    profile;                   ///< subsection `Profile`, coordinates (x, y)

    /** Declare the entries of the subsection (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<3>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
