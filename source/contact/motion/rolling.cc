#include <ausroll/contact/motion/rolling.h>
#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/core/exceptions.h>

#include <deal.II/base/numbers.h>

#include <cmath>

namespace ausroll::contact
{
  using namespace dealii;

  // ------------------------------------------------------------------ RollingMotion

  template <int dim>
  RollingMotion<dim>::RollingMotion(const Data &data)
      : d(data)
      , a0(data.initial_center_distance.value_or(data.workpiece_radius + data.die_radius))
  {
    const std::string where = "Rolling motion";
    require(d.workpiece_radius > 0.0, where, "the workpiece pitch radius must be positive");
    require(d.die_radius > 0.0, where, "the die pitch radius must be positive");
    require(a0 > 0.0, where, "the initial centre distance must be positive");
    require(d.direction == 1 || d.direction == -1, where, "the direction must be +1 or -1");
    require(d.beta >= 0.0 && d.beta <= 1.0, where, "the rolling ratio beta must lie in [0, 1]");
    if constexpr (dim == 3)
    {
      const surfaces::Frame3D frame(
          Point<3>(), d.axis.norm() > 0.0 ? d.axis : Tensor<1, 3>({0., 0., 1.}), d.reference);
      d.axis = frame.basis(2);
      e1 = frame.basis(0);
      e2 = frame.basis(1);
    }
  }

  template <int dim>
  double RollingMotion<dim>::line_angle(const double t) const
  {
    return d.initial_line_angle + d.direction * value_or_zero(d.revolution_angle, t);
  }

  template <int dim>
  double RollingMotion<dim>::center_distance(const double t) const
  {
    return a0 - value_or_zero(d.feed, t);
  }

  template <int dim>
  Point<dim> RollingMotion<dim>::polar_point(const double r, const double psi) const
  {
    if constexpr (dim == 2)
      return d.workpiece_center + Point<2>(r * std::cos(psi), r * std::sin(psi));
    else
      return d.workpiece_center + r * std::cos(psi) * e1 + r * std::sin(psi) * e2;
  }

  template <int dim>
  Point<dim> RollingMotion<dim>::die_center(const double t) const
  {
    return polar_point(center_distance(t), line_angle(t));
  }

  template <int dim>
  double RollingMotion<dim>::spin_angle(const double t) const
  {
    return d.workpiece_radius / d.die_radius * value_or_zero(d.revolution_angle, t)
           + (1.0 - d.beta) * value_or_zero(d.slip_angle, t);
  }

  template <int dim>
  Point<dim> RollingMotion<dim>::pitch_point(const double t) const
  {
    return polar_point(d.workpiece_radius, line_angle(t));
  }

  template <int dim>
  DiePose<dim> RollingMotion<dim>::pose(const double t) const
  {
    const double theta = d.initial_die_angle
                         + d.direction * (value_or_zero(d.revolution_angle, t) + spin_angle(t));
    return DiePose<dim>(die_center(t), theta, Point<dim>(), d.axis);
  }

  void RollingMotionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Workpiece center",
                      "0, 0",
                      Patterns::Anything(),
                      "Centre O_G of the (non-rotating) workpiece (3D: a point of its axis, x, y, "
                      "z; x, y means z = 0).");
    prm.declare_entry("Axis",
                      "0, 0, 1",
                      Patterns::Anything(),
                      "3D only: direction of the workpiece axis through Workpiece center (the die "
                      "axis is parallel), angles measured in the plane orthogonal to it from x "
                      "(Axis = z) or from the coordinate axis least aligned with it.");
    prm.declare_entry("Workpiece rolling radius",
                      "1",
                      Patterns::Double(0.),
                      "R_G, radius of pure rolling on the workpiece (pitch radius).");
    prm.declare_entry("Die rolling radius",
                      "1",
                      Patterns::Double(0.),
                      "R_D, radius of pure rolling on the die; the die spins by theta_D = "
                      "(R_G/R_D) theta_G.");
    prm.declare_entry("Initial center distance",
                      "0",
                      Patterns::Double(0.),
                      "Distance O_G to die centre at t = 0 (0: R_G + R_D).");
    prm.declare_entry("Initial line angle",
                      "90",
                      Patterns::Double(),
                      "Angle of the line of centres at t = 0 (degrees from +x).");
    prm.declare_entry("Direction",
                      "1",
                      Patterns::Integer(-1, 1),
                      "+1 the die revolves counter-clockwise, -1 clockwise.");
    prm.declare_entry(
        "Rolling factor",
        "1",
        Patterns::Double(0., 1.),
        "beta in theta_D = (R_G/R_D) theta_G + (1 - beta) theta_s (1: pure rolling).");
    prm.declare_entry("Revolution angle",
                      "0",
                      Patterns::Anything(),
                      "theta_G(t), revolution of the die centre about O_G (degrees).");
    prm.declare_entry("Slip angle", "0", Patterns::Anything(), "theta_s(t) (degrees).");
    prm.declare_entry(
        "Feed", "0", Patterns::Anything(), "Radial feed f(t) of the die towards O_G (mm).");
  }

  void RollingMotionParameters::parse(ParameterHandler  &prm,
                                      const std::string &path,
                                      const std::string &)
  {
    workpiece_center = prm.get("Workpiece center");
    axis = prm.get("Axis");
    workpiece_radius = prm.get_double("Workpiece rolling radius");
    die_radius = prm.get_double("Die rolling radius");
    center_distance = prm.get_double("Initial center distance");
    line_angle = prm.get_double("Initial line angle");
    direction = prm.get_integer("Direction");
    beta = prm.get_double("Rolling factor");
    revolution = prm.get("Revolution angle");
    slip = prm.get("Slip angle");
    feed = prm.get("Feed");
    require(workpiece_radius > 0., path + "Workpiece rolling radius", "must be positive");
    require(die_radius > 0., path + "Die rolling radius", "must be positive");
    require(direction != 0, path + "Direction", "must be +1 or -1");
  }

  namespace
  {
    template <int dim>
    std::unique_ptr<DieMotion<dim>> make(const RollingMotionParameters &p, const std::string &path)
    {
      constexpr double                  degree = numbers::PI / 180.;
      typename RollingMotion<dim>::Data data;
      if constexpr (dim == 3)
      {
        data.axis = Tensor<1, 3>(parse_die_point<3>(p.axis, path + "Axis"));
        require(data.axis.norm() > 0., path + "Axis", "must be a nonzero vector");
      }
      data.workpiece_center = parse_die_point<dim>(p.workpiece_center, path + "Workpiece center");
      data.workpiece_radius = p.workpiece_radius;
      data.die_radius = p.die_radius;
      if (p.center_distance > 0.)
        data.initial_center_distance = p.center_distance;
      data.initial_line_angle = p.line_angle * degree;
      data.direction = p.direction;
      data.beta = p.beta;
      data.revolution_angle = parse_time_function(p.revolution, path + "Revolution angle", degree);
      data.slip_angle = parse_time_function(p.slip, path + "Slip angle", degree);
      data.feed = parse_time_function(p.feed, path + "Feed");
      try
      {
        return std::make_unique<RollingMotion<dim>>(data);
      }
      catch (const std::exception &e)
      {
        throw InputError(path.substr(0, path.size() - 1) + ": " + e.what());
      }
    }
  } // namespace

  std::unique_ptr<DieMotion<2>> RollingMotionParameters::create_2d(const std::string &path) const
  {
    return make<2>(*this, path);
  }

  std::unique_ptr<DieMotion<3>> RollingMotionParameters::create_3d(const std::string &path) const
  {
    return make<3>(*this, path);
  }

  template class RollingMotion<2>;
  template class RollingMotion<3>;
} // namespace ausroll::contact

AUSROLL_REGISTER_DIE_MOTION(ausroll::contact::RollingMotionParameters,
                            "rolling",
                            "Rolling",
                            "planetary motion about the workpiece centre, NOFEAP section 4.1")
