#include <ausroll/contact/rigid_die.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace ausroll::contact
{
  using namespace dealii;

  namespace
  {
    constexpr double degree = numbers::PI / 180.;

    /** A scalar function of t parsed from @p expression; InputError names @p entry. */
    TimeFunction
    time_function(const std::string &expression, const std::string &entry, const double scale = 1.)
    {
      require_expression_length(expression, entry);
      auto parser = std::make_shared<FunctionParser<1>>(1);
      try
      {
        // deal.II parses at the first evaluation
        parser->initialize("x,t", expression, {{"pi", numbers::PI}}, true);
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

    std::unique_ptr<DieMotion> make_motion(const DieParameters &p, const std::string &path)
    {
      switch (p.motion)
      {
        case MotionType::fixed:
          return std::make_unique<FixedPose>();
        case MotionType::prescribed:
        {
          const std::vector<std::string> u = split_and_trim(p.translation, ';');
          require(
              u.size() == 2, path + "Motion/Translation", "needs two expressions 'ux(t); uy(t)'");
          const TimeFunction ux = time_function(u[0], path + "Motion/Translation");
          const TimeFunction uy = time_function(u[1], path + "Motion/Translation");
          const TimeFunction phi = time_function(p.rotation, path + "Motion/Rotation", degree);
          return std::make_unique<PrescribedMotion>(
              [ux, uy](const double t) {
                return Tensor<1, 2>({ux(t), uy(t)});
              },
              phi,
              p.pivot);
        }
        case MotionType::rolling:
        {
          RollingMotion::Data data;
          data.workpiece_center = p.workpiece_center;
          data.workpiece_radius = p.workpiece_radius;
          data.die_radius = p.die_radius;
          if (p.center_distance > 0.)
            data.initial_center_distance = p.center_distance;
          data.initial_line_angle = p.line_angle * degree;
          data.direction = p.direction;
          data.beta = p.beta;
          data.revolution_angle
              = time_function(p.revolution, path + "Motion/Revolution angle", degree);
          data.slip_angle = time_function(p.slip, path + "Motion/Slip angle", degree);
          data.feed = time_function(p.feed, path + "Motion/Feed");
          try
          {
            return std::make_unique<RollingMotion>(data);
          }
          catch (const std::exception &e)
          {
            throw InputError(path + "Motion: " + e.what());
          }
        }
      }
      return nullptr;
    }
  } // namespace

  RigidDie::RigidDie(const DieParameters &p, const unsigned int index)
      : name(p.name)
      , friction(create_friction_law(p))
      , search_distance(p.search_distance > 0. ? p.search_distance
                                               : std::numeric_limits<double>::infinity())
      , shape(p.surface ? p.surface->create(p.surface_path)
                        : throw std::logic_error("RigidDie: DieParameters without a shape"))
      , profile(*shape)
      , candidates(p.candidate_boundaries.begin(), p.candidate_boundaries.end())
  {
    const std::string path = "Contact/Die " + std::to_string(index) + "/";
    motion = make_motion(p, path);
  }

  Projection DieProfile::project(const Point<2> &x, const double max_distance) const
  {
    if (const auto *chain = dynamic_cast<const ChainSurface *>(surface))
      return chain->chain().project(x, max_distance);
    const SurfaceProjection<2> q = surface->project(x, max_distance);
    Projection                 p;
    if (!q.valid)
      return p;
    p.valid = true;
    p.point = q.point;
    p.gap = q.gap;
    p.distance = q.distance;
    p.normal = q.normal;
    p.tangent = q.tangents[0];
    p.curvature = q.curvatures[0];
    p.s = q.coordinates[0];
    p.at_corner = q.at_edge;
    p.at_end = q.at_end;
    return p;
  }

  DieProjection RigidDie::project(const Point<2> &x, const double t) const
  {
    const DiePose              pose = motion->pose(t);
    const SurfaceProjection<2> p = shape->project(pose.to_local(x), search_distance);
    DieProjection              result;
    if (!p.valid)
      return result;
    result.valid = true;
    result.gap = p.gap;
    result.local_point = p.point;
    result.point = pose.to_global(p.point);
    result.normal = pose.rotate_vector_to_global(p.normal);
    result.tangent = pose.rotate_vector_to_global(p.tangents[0]);
    result.s = p.coordinates[0];
    return result;
  }

  Point<2> RigidDie::material_point(const Point<2> &X, const double t) const
  {
    return motion->pose(t).to_global(X);
  }
} // namespace ausroll::contact
