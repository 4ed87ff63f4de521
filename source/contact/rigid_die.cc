#include <ausroll/contact/rigid_die.h>
#include <ausroll/core/exceptions.h>

#include <limits>

namespace ausroll::contact
{
  using namespace dealii;

  namespace
  {
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
    if constexpr (dim == 2)
      profile = std::make_unique<DieProfile>(*shape);
    motion = create_motion<dim>(*p.motion, p.motion_path);
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
