#include <ausroll/contact/rigid_die.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/involute_gear.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

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

    std::unique_ptr<DieSurface> make_surface(const DieParameters &p, const std::string &path)
    {
      switch (p.shape)
      {
        case DieShape::flat:
        {
          const Tensor<1, 2> n = p.normal / p.normal.norm();
          // travel direction with the die material on the right: t = n rotated by -90 degrees
          const Tensor<1, 2> direction({n[1], -n[0]});
          return std::make_unique<DieSurface>(DieSurface::flat(p.point, direction));
        }
        case DieShape::circle:
          return std::make_unique<DieSurface>(
              DieSurface::circle(p.center, p.radius, p.material_inside));
        case DieShape::polyline:
        case DieShape::arc_line:
        {
          std::vector<Point<2>> points;
          if (!p.points.empty())
            for (const std::string &item : split_and_trim(p.points, ';'))
              points.push_back(parse_point<2>(item, path + "Points"));
          else
            try
            {
              points = DieSurface::read_points_file(p.points_file);
            }
            catch (const std::exception &e)
            {
              throw InputError(path + "Points file: " + e.what());
            }
          require(points.size() >= 2, path + "Points", "needs at least two points");
          try
          {
            if (p.shape == DieShape::polyline)
              return std::make_unique<DieSurface>(DieSurface::polyline(points, false, true));
            require(!p.fillet_radii.empty(), path + "Fillet radii", "needs at least one radius");
            return std::make_unique<DieSurface>(
                DieSurface::arc_line_composite(points, p.fillet_radii, false, true));
          }
          catch (const InputError &)
          {
            throw;
          }
          catch (const std::exception &e)
          {
            throw InputError(path + "Points: " + e.what());
          }
        }
        case DieShape::involute_gear:
        {
          geometry::ToothProportions proportions;
          if (p.addendum >= 0.)
            proportions.addendum = p.addendum;
          if (p.dedendum >= 0.)
            proportions.dedendum = p.dedendum;
          if (p.tooth_thickness > 0.)
            proportions.pitch_tooth_thickness = p.tooth_thickness;
          proportions.root_fillet_radius = p.fillet_radius;
          try
          {
            const geometry::InvoluteGear gear
                = p.diametral_pitch > 0.
                      ? geometry::InvoluteGear::from_diametral_pitch(
                          p.teeth, p.diametral_pitch, p.pressure_angle * degree, proportions)
                      : geometry::InvoluteGear(
                          p.teeth, p.module, p.pressure_angle * degree, proportions);
            return std::make_unique<DieSurface>(DieSurface::involute_gear(
                gear, p.tooth_axis_angle * degree, p.sector_teeth, p.tip_radius));
          }
          catch (const EntryError &e)
          {
            // the gear and the die-surface factory name the entry that failed
            throw InputError(path + e.entry() + ": " + e.what_is_wrong());
          }
          catch (const std::exception &e)
          {
            throw InputError(path + "Shape = involute gear: invalid gear (" + std::string(e.what())
                             + ")");
          }
        }
      }
      return nullptr;
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
      , candidates(p.candidate_boundaries.begin(), p.candidate_boundaries.end())
  {
    const std::string path = "Contact/Die " + std::to_string(index) + "/";
    surface = make_surface(p, path);
    motion = make_motion(p, path);
  }

  DieProjection RigidDie::project(const Point<2> &x, const double t) const
  {
    const DiePose    pose = motion->pose(t);
    const Projection p = surface->project(pose.to_local(x), search_distance);
    DieProjection    result;
    if (!p.valid)
      return result;
    result.valid = true;
    result.gap = p.gap;
    result.local_point = p.point;
    result.point = pose.to_global(p.point);
    result.normal = pose.rotate_vector_to_global(p.normal);
    result.tangent = pose.rotate_vector_to_global(p.tangent);
    result.s = p.s;
    return result;
  }

  Point<2> RigidDie::material_point(const Point<2> &X, const double t) const
  {
    return motion->pose(t).to_global(X);
  }
} // namespace ausroll::contact
