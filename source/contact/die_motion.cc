/**
 * @file die_motion.cc
 * Implementation of die poses and die motions (see die_motion.h for the conventions).
 */
#include <ausroll/contact/die_motion.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace ausroll::contact
{
  using dealii::Point;
  using dealii::Tensor;

  // ------------------------------------------------------------------ DiePose

  DiePose<2>::DiePose(const Point<2> &reference_position,
                      const double    angle,
                      const Point<2> &local_reference,
                      const Tensor<1, 2> &)
      : c(reference_position)
      , theta(angle)
      , cos_theta(std::cos(angle))
      , sin_theta(std::sin(angle))
      , X_ref(local_reference)
  {
  }

  Point<2> DiePose<2>::to_global(const Point<2> &X) const
  {
    return c + rotate_vector_to_global(X - X_ref);
  }

  Point<2> DiePose<2>::to_local(const Point<2> &x) const
  {
    return X_ref + rotate_vector_to_local(x - c);
  }

  Tensor<1, 2> DiePose<2>::rotate_vector_to_global(const Tensor<1, 2> &v) const
  {
    Tensor<1, 2> r;
    r[0] = cos_theta * v[0] - sin_theta * v[1];
    r[1] = sin_theta * v[0] + cos_theta * v[1];
    return r;
  }

  Tensor<1, 2> DiePose<2>::rotate_vector_to_local(const Tensor<1, 2> &v) const
  {
    Tensor<1, 2> r;
    r[0] = cos_theta * v[0] + sin_theta * v[1];
    r[1] = -sin_theta * v[0] + cos_theta * v[1];
    return r;
  }

  DiePose<3>::DiePose()
      : DiePose(Point<3>(), 0.0)
  {
  }

  DiePose<3>::DiePose(const Point<3>     &reference_position,
                      const double        angle,
                      const Point<3>     &local_reference,
                      const Tensor<1, 3> &axis)
      : c(reference_position)
      , theta(angle)
      , X_ref(local_reference)
  {
    const double length = axis.norm();
    a = length > 0.0 ? axis / length : Tensor<1, 3>({0.0, 0.0, 1.0});
    const double cs = std::cos(angle), sn = std::sin(angle);
    // Rodrigues: R = cos I + sin [a]x + (1 - cos) a (x) a
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = (i == j ? cs : 0.0) + (1.0 - cs) * a[i] * a[j];
    R[0][1] -= sn * a[2];
    R[0][2] += sn * a[1];
    R[1][0] += sn * a[2];
    R[1][2] -= sn * a[0];
    R[2][0] -= sn * a[1];
    R[2][1] += sn * a[0];
  }

  Point<3> DiePose<3>::to_global(const Point<3> &X) const
  {
    return c + rotate_vector_to_global(X - X_ref);
  }

  Point<3> DiePose<3>::to_local(const Point<3> &x) const
  {
    return X_ref + rotate_vector_to_local(x - c);
  }

  Tensor<1, 3> DiePose<3>::rotate_vector_to_global(const Tensor<1, 3> &v) const
  {
    return R * v;
  }

  Tensor<1, 3> DiePose<3>::rotate_vector_to_local(const Tensor<1, 3> &v) const
  {
    return v * R; // R^T v
  }

  // ------------------------------------------------------------------ DieMotion

  template <int dim>
  double DieMotion<dim>::difference_step(const double t)
  {
    return 1e-6 * (1.0 + std::abs(t));
  }

  template <int dim>
  Tensor<1, dim> DieMotion<dim>::velocity(const double t, const Point<dim> &X) const
  {
    const double h = difference_step(t);
    return (pose(t + h).to_global(X) - pose(t - h).to_global(X)) / (2.0 * h);
  }

  template <int dim>
  double DieMotion<dim>::angular_velocity(const double t) const
  {
    const double h = difference_step(t);
    return (pose(t + h).angle() - pose(t - h).angle()) / (2.0 * h);
  }

  template <int dim>
  Tensor<1, dim>
  DieMotion<dim>::displacement(const double t0, const double t1, const Point<dim> &X) const
  {
    return pose(t1).to_global(X) - pose(t0).to_global(X);
  }

  // ------------------------------------------------------------------ entries

  TimeFunction
  parse_time_function(const std::string &expression, const std::string &entry, const double scale)
  {
    require_expression_length(expression, entry);
    auto parser = std::make_shared<dealii::FunctionParser<1>>(1);
    try
    {
      // deal.II parses at the first evaluation
      parser->initialize("x,t", expression, {{"pi", dealii::numbers::PI}}, true);
      parser->set_time(0.);
      parser->value(Point<1>());
    }
    catch (...)
    {
      throw InputError(entry + ": cannot parse '" + abbreviate(expression) + "' (variable: t)");
    }
    // A value that is not finite (t/0, sqrt(-1-t), an overflow) is an input error naming the
    // entry wherever it is met: at t = 0 here, at the die check's times before the run.
    const TimeFunction f = [parser, scale, expression, entry](const double t)
    {
      parser->set_time(t);
      const double value = scale * parser->value(Point<1>());
      if (!std::isfinite(value))
      {
        std::ostringstream msg;
        msg << entry << ": '" << abbreviate(expression) << "' is not finite ("
            << (std::isnan(value) ? "nan"
                : value > 0       ? "inf"
                                  : "-inf")
            << ") at t = " << t;
        throw InputError(msg.str());
      }
      return value;
    };
    f(0.);
    return f;
  }

  template <int dim>
  Point<dim> parse_die_point(const std::string &text, const std::string &entry)
  {
    if constexpr (dim == 3)
      if (split_and_trim(text, ',').size() == 2)
      {
        const Point<2> p = parse_point<2>(text, entry);
        return Point<3>(p[0], p[1], 0.);
      }
    return parse_point<dim>(text, entry);
  }

  void add_moved_motion_entries(const std::string                  &motion_path,
                                std::map<std::string, std::string> &moved)
  {
    // the flat list of `Contact/Die N/Motion` before the motion subsections
    const std::vector<std::pair<std::string, std::vector<std::string>>> entries{
        {"Translation", {"Prescribed"}},
        {"Rotation", {"Prescribed"}},
        {"Pivot", {"Prescribed"}},
        {"Axis", {"Prescribed", "Rolling"}},
        {"Workpiece center", {"Rolling"}},
        {"Workpiece rolling radius", {"Rolling"}},
        {"Die rolling radius", {"Rolling"}},
        {"Initial center distance", {"Rolling"}},
        {"Initial line angle", {"Rolling"}},
        {"Direction", {"Rolling"}},
        {"Rolling factor", {"Rolling"}},
        {"Revolution angle", {"Rolling"}},
        {"Slip angle", {"Rolling"}},
        {"Feed", {"Rolling"}},
    };
    for (const auto &[entry, subsections] : entries)
    {
      std::string to;
      for (const std::string &s : subsections)
        to += (to.empty() ? "" : " or ") + ("`" + motion_path + s + "/" + entry + "`");
      moved[motion_path + entry] = to;
    }
  }

  template class DieMotion<2>;
  template class DieMotion<3>;
  template Point<2> parse_die_point<2>(const std::string &, const std::string &);
  template Point<3> parse_die_point<3>(const std::string &, const std::string &);
} // namespace ausroll::contact
