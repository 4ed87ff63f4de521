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

    /** Read the point entry @p text of @p dim coordinates (3D also "x, y": z = 0, so that the
        2D defaults serve); InputError naming @p entry. */
    template <int dim>
    Point<dim> read_point(const std::string &text, const std::string &entry)
    {
      if constexpr (dim == 3)
        if (split_and_trim(text, ',').size() == 2)
        {
          const Point<2> p = parse_point<2>(text, entry);
          return Point<3>(p[0], p[1], 0.);
        }
      return parse_point<dim>(text, entry);
    }

    template <int dim>
    std::unique_ptr<DieMotion<dim>> make_motion(const DieParameters &p, const std::string &path)
    {
      Tensor<1, dim> axis;
      if constexpr (dim == 3)
      {
        if (p.motion != MotionType::fixed)
        {
          axis = Tensor<1, 3>(read_point<3>(p.axis, path + "Motion/Axis"));
          require(axis.norm() > 0., path + "Motion/Axis", "must be a nonzero vector");
        }
      }
      switch (p.motion)
      {
        case MotionType::fixed:
          return std::make_unique<FixedPose<dim>>();
        case MotionType::prescribed:
        {
          const std::vector<std::string> u = split_and_trim(p.translation, ';');
          require(u.size() == dim,
                  path + "Motion/Translation",
                  dim == 2 ? "needs two expressions 'ux(t); uy(t)'"
                           : "needs three expressions 'ux(t); uy(t); uz(t)' in a 3D run");
          std::vector<TimeFunction> components;
          for (unsigned int c = 0; c < dim; ++c)
            components.push_back(time_function(u[c], path + "Motion/Translation"));
          const TimeFunction phi = time_function(p.rotation, path + "Motion/Rotation", degree);
          const Point<dim>   pivot = read_point<dim>(p.pivot, path + "Motion/Pivot");
          return std::make_unique<PrescribedMotion<dim>>(
              [components](const double t)
              {
                Tensor<1, dim> v;
                for (unsigned int c = 0; c < dim; ++c)
                  v[c] = components[c](t);
                return v;
              },
              phi,
              pivot,
              pivot,
              axis);
        }
        case MotionType::rolling:
        {
          typename RollingMotion<dim>::Data data;
          data.workpiece_center
              = read_point<dim>(p.workpiece_center, path + "Motion/Workpiece center");
          data.axis = axis;
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
            return std::make_unique<RollingMotion<dim>>(data);
          }
          catch (const std::exception &e)
          {
            throw InputError(path + "Motion: " + e.what());
          }
        }
      }
      return nullptr;
    }

    /** The surface of die @p p in a run of dimension @p dim; InputError naming `Shape` if the
        shape has the other dimension. */
    template <int dim>
    std::unique_ptr<const RigidSurface<dim>> make_surface(const DieParameters &p,
                                                          const std::string   &path)
    {
      if constexpr (dim == 2)
      {
        require(p.surface != nullptr,
                path + "Shape",
                "'" + p.shape + "' is a 3D die shape; a 2D run needs one of "
                    + surfaces::ShapeRegistry<2>::instance().selection());
        return p.surface->create(p.surface_path);
      }
      else
      {
        require(p.surface_3d != nullptr,
                path + "Shape",
                "'" + p.shape + "' is a 2D die shape; a 3D run needs one of "
                    + surfaces::ShapeRegistry<3>::instance().selection());
        return p.surface_3d->create(p.surface_path);
      }
    }
  } // namespace

  template <int dim>
  RigidDie<dim>::RigidDie(const DieParameters   &p,
                          const unsigned int     index,
                          const FrictionContext &friction_context)
      : name(p.name)
      , friction(
            create_friction_law(p, friction_context, "Contact/Die " + std::to_string(index) + "/"))
      , search_distance(p.search_distance > 0. ? p.search_distance
                                               : std::numeric_limits<double>::infinity())
      , shape(make_surface<dim>(p, "Contact/Die " + std::to_string(index) + "/"))
      , candidates(p.candidate_boundaries.begin(), p.candidate_boundaries.end())
  {
    const std::string path = "Contact/Die " + std::to_string(index) + "/";
    if constexpr (dim == 2)
    {
      profile = std::make_unique<DieProfile>(*shape);
      read_point<2>(p.pivot, path + "Motion/Pivot"); // checked in every 2D run, as before
      read_point<2>(p.workpiece_center, path + "Motion/Workpiece center");
    }
    motion = make_motion<dim>(p, path);
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

  template <int dim>
  DieProjection<dim> RigidDie<dim>::project(const Point<dim> &x, const double t) const
  {
    const DiePose<dim>           pose = motion->pose(t);
    const SurfaceProjection<dim> p = shape->project(pose.to_local(x), search_distance);
    DieProjection<dim>           result;
    if (!p.valid)
      return result;
    result.valid = true;
    result.gap = p.gap;
    result.local_point = p.point;
    result.point = pose.to_global(p.point);
    result.normal = pose.rotate_vector_to_global(p.normal);
    for (unsigned int a = 0; a < dim - 1; ++a)
      result.tangents[a] = pose.rotate_vector_to_global(p.tangents[a]);
    result.tangent = result.tangents[0];
    result.coordinates = p.coordinates;
    result.s = p.coordinates[0];
    result.end_margin = p.at_end ? 0. : p.end_margin;
    return result;
  }

  template <int dim>
  Point<dim> RigidDie<dim>::material_point(const Point<dim> &X, const double t) const
  {
    return motion->pose(t).to_global(X);
  }

  template class RigidDie<2>;
  template class RigidDie<3>;
} // namespace ausroll::contact
