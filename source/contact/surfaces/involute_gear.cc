#include <ausroll/contact/surfaces/chain_surface.h>
#include <ausroll/contact/surfaces/involute_gear.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/gear_entries.h>
#include <ausroll/geometry/involute_gear.h>
#include <ausroll/geometry/plane_vectors.h>

#include <deal.II/base/numbers.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;
  using namespace geometry::plane;

  geometry::CurveChain involute_flank_chain(const Point<2> &base_center,
                                            const double    base_radius,
                                            const double    origin_angle,
                                            const int       unwind_sense,
                                            const double    roll_start,
                                            const double    roll_end)
  {
    return geometry::CurveChain(
        {geometry::CurveSegment::involute(
            base_center, base_radius, origin_angle, unwind_sense, roll_start, roll_end)},
        false);
  }

  geometry::CurveChain involute_gear_chain(const geometry::InvoluteGear &gear,
                                           const double                  tooth_axis_angle,
                                           const unsigned int            n_teeth,
                                           const double                  tip_round)
  {
    using geometry::FlankSide;
    const geometry::ToothGeometry &tooth = gear.tooth_geometry();
    const unsigned int             z = gear.n_teeth();
    if (n_teeth > z)
      throw EntryError("Teeth in sector",
                       std::to_string(n_teeth) + " is more than the gear's " + std::to_string(z)
                           + " teeth");
    const bool     full = (n_teeth == 0 || n_teeth == z);
    const unsigned n = full ? z : n_teeth;
    const double   rb = gear.base_radius();
    const double   rr = gear.root_radius();
    const double   rt = gear.tip_radius();
    const double   rho = gear.root_fillet_radius();
    const double   r_fl = tooth.flank_start_radius;
    const double   psi = tooth.root_land_angle;
    const double   pitch = gear.angular_pitch();
    const double   u_low = gear.roll_angle_at(std::max(r_fl, rb));
    const Point<2> o;
    const double   land_tol = 1e-12;

    // Tip round (tooth axis along +x, positive flank): centre c at radius r_c = r_a - rho_t and
    // at the normal distance rho_t inside the involute. The normal of an involute through a point
    // is the tangent from it to the base circle, and the distance between two rotated copies of
    // the involute along it is r_b times the rotation: phi_c = theta_h(r_c) - rho_t / r_b. The
    // tangent point Q on the flank lies on that base tangent at r_b u_Q = rho_t +
    // sqrt(r_c^2 - r_b^2) from the tangency point; the tangent point on the outside circle lies
    // on the ray through c.
    if (tip_round < 0.0)
      throw EntryError("Tip radius", "the tip round radius must not be negative");
    double   u_tip = gear.roll_angle_at(rt);
    double   tip_angle = tooth.tip_half_angle;
    Point<2> round_center;
    double   round_from = 0.0;
    if (tip_round > 0.0)
    {
      const double r_c = rt - tip_round;
      if (!(r_c > rb))
        throw EntryError("Tip radius", "the tip round must end above the base circle");
      tip_angle = gear.half_thickness_angle(r_c) - tip_round / rb;
      if (!(tip_angle > 0.0))
        throw EntryError("Tip radius", "the tip round is too large: no tip land remains");
      u_tip = (tip_round + std::sqrt(r_c * r_c - rb * rb)) / rb;
      require(u_tip > u_low, curve_entry, "the tip round reaches below the involute flank");
      round_center = Point<2>(r_c * unit(tip_angle));
      const Point<2> q = gear.flank_point(rb * std::sqrt(1.0 + u_tip * u_tip), FlankSide::positive);
      round_from = polar_angle(q - round_center);
    }

    std::vector<geometry::CurveSegment> segments;
    // One tooth with axis at polar angle a, travelled clockwise (root land side at a + psi first).
    const auto add_tooth = [&](const double a)
    {
      const auto fillet = [&](const Point<2> &center, const Point<2> &from, const Point<2> &to)
      {
        // The fillet is concave (centre in the tooth space): travelled counter-clockwise.
        const double phi_from = polar_angle(from - center);
        const double sweep = positive_modulo(polar_angle(to - center) - phi_from, 2.0 * M_PI);
        segments.push_back(geometry::CurveSegment::arc(center, rho, phi_from, sweep));
      };
      const Point<2> p_pos = rotate(gear.flank_point(r_fl, FlankSide::positive), a);
      const Point<2> p_neg = rotate(gear.flank_point(r_fl, FlankSide::negative), a);
      if (rho > 0.0)
        fillet(rotate(tooth.fillet_center, a), o + rr * unit(a + psi), p_pos);
      if (tooth.has_radial_flank)
        segments.push_back(geometry::CurveSegment::line(
            p_pos, rotate(gear.flank_point(rb, FlankSide::positive), a)));
      segments.push_back(
          geometry::CurveSegment::involute(o, rb, a + tooth.base_half_angle, -1, u_low, u_tip));
      // convex tip rounds travelled clockwise: from the flank to the outside circle
      const double round_sweep = -positive_modulo(round_from - tip_angle, 2.0 * M_PI);
      if (tip_round > 0.0)
        segments.push_back(geometry::CurveSegment::arc(
            rotate(round_center, a), tip_round, a + round_from, round_sweep));
      segments.push_back(geometry::CurveSegment::arc(o, rt, a + tip_angle, -2.0 * tip_angle));
      if (tip_round > 0.0)
        segments.push_back(
            geometry::CurveSegment::arc(rotate(Point<2>(round_center[0], -round_center[1]), a),
                                        tip_round,
                                        a - tip_angle,
                                        round_sweep));
      segments.push_back(
          geometry::CurveSegment::involute(o, rb, a - tooth.base_half_angle, +1, u_tip, u_low));
      if (tooth.has_radial_flank)
        segments.push_back(geometry::CurveSegment::line(
            rotate(gear.flank_point(rb, FlankSide::negative), a), p_neg));
      if (rho > 0.0)
      {
        const Point<2> c(tooth.fillet_center[0], -tooth.fillet_center[1]);
        fillet(rotate(c, a), p_neg, o + rr * unit(a - psi));
      }
    };
    const auto add_root_land = [&](const double from, const double to)
    {
      if (from - to > land_tol)
        segments.push_back(geometry::CurveSegment::arc(o, rr, from, to - from));
    };

    if (full)
      for (unsigned int k = 0; k < n; ++k)
      {
        const double a = tooth_axis_angle - k * pitch;
        add_tooth(a);
        add_root_land(a - psi, a - pitch + psi);
      }
    else
    {
      const double a0 = tooth_axis_angle + 0.5 * (n - 1.0) * pitch;
      add_root_land(a0 + 0.5 * pitch, a0 + psi);
      for (unsigned int k = 0; k < n; ++k)
      {
        const double a = a0 - k * pitch;
        add_tooth(a);
        add_root_land(a - psi, k + 1 < n ? a - pitch + psi : a - 0.5 * pitch);
      }
    }
    return geometry::CurveChain(std::move(segments), full);
  }

  void InvoluteGearParameters::declare_parameters(ParameterHandler &prm)
  {
    geometry::declare_gear_size_entries(prm, "57", "Teeth z.");
    prm.declare_entry(
        "Tooth thickness",
        "-1",
        Patterns::Double(),
        "Tooth thickness at the pitch circle (mm); negative: half the circular pitch.");
    prm.declare_entry("Root fillet radius", "0", Patterns::Double(0.), "Root fillet radius (mm).");
    prm.declare_entry("Tip radius",
                      "0",
                      Patterns::Double(0.),
                      "Radius of the tip rounds, arcs tangent to the flank and the outside "
                      "circle (mm; 0: sharp tip corners).");
    prm.declare_entry("Tooth axis angle",
                      "0",
                      Patterns::Double(),
                      "Direction of the axis of tooth 0 (degrees from +x).");
    prm.declare_entry("Teeth in sector",
                      "0",
                      Patterns::Integer(0),
                      "Build only this many teeth around tooth 0 (0: whole gear).");
  }

  void
  InvoluteGearParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    size.parse(prm);
    tooth_thickness = prm.get_double("Tooth thickness");
    fillet_radius = prm.get_double("Root fillet radius");
    tip_radius = prm.get_double("Tip radius");
    tooth_axis_angle = prm.get_double("Tooth axis angle");
    sector_teeth = prm.get_integer("Teeth in sector");
    require(size.diametral_pitch > 0. || size.module > 0.,
            path + "Module",
            "set Diametral pitch or Module");
  }

  std::unique_ptr<const RigidSurface<2>>
  InvoluteGearParameters::create(const std::string &path) const
  {
    constexpr double                 degree = numbers::PI / 180.;
    const geometry::ToothProportions proportions
        = geometry::tooth_proportions(size.addendum, size.dedendum, tooth_thickness, fillet_radius);
    try
    {
      const auto gear = geometry::InvoluteGear::from_pitch_or_module(
          size.teeth, size.diametral_pitch, size.module, size.pressure_angle * degree, proportions);
      return std::make_unique<ChainSurface>(
          "involute gear",
          involute_gear_chain(gear, tooth_axis_angle * degree, sector_teeth, tip_radius));
    }
    catch (const EntryError &e)
    {
      // the gear and the die-surface factory name the entry that failed
      throw InputError(path + e.entry() + ": " + e.what_is_wrong());
    }
    catch (const std::exception &e)
    {
      throw InputError(path.substr(0, path.size() - 1) + ": invalid gear (" + std::string(e.what())
                       + ")");
    }
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(
    2,
    ausroll::contact::surfaces::InvoluteGearParameters,
    "involute gear",
    "Involute gear",
    "an external involute spur gear (tooth flanks, root fillets, tip circle)")
