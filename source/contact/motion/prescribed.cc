#include <ausroll/contact/motion/prescribed.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <deal.II/base/numbers.h>

#include <vector>

namespace ausroll::contact
{
  using namespace dealii;

  // ------------------------------------------------------------------ PrescribedMotion

  template <int dim>
  PrescribedMotion<dim>::PrescribedMotion(VectorTimeFunction<dim> translation,
                                          TimeFunction            rotation,
                                          const Point<dim>       &pivot)
      : PrescribedMotion(std::move(translation), std::move(rotation), pivot, pivot)
  {
  }

  template <int dim>
  PrescribedMotion<dim>::PrescribedMotion(VectorTimeFunction<dim> translation,
                                          TimeFunction            rotation,
                                          const Point<dim>       &pivot,
                                          const Point<dim>       &pivot_rest_position,
                                          const Tensor<1, dim>   &axis)
      : translation(std::move(translation))
      , rotation(std::move(rotation))
      , pivot(pivot)
      , pivot_rest(pivot_rest_position)
      , axis(axis)
  {
  }

  template <int dim>
  PrescribedMotion<dim> PrescribedMotion<dim>::constant_velocity(const Tensor<1, dim> &velocity)
  {
    return PrescribedMotion([velocity](const double t) { return velocity * t; }, TimeFunction());
  }

  template <int dim>
  DiePose<dim> PrescribedMotion<dim>::pose(const double t) const
  {
    const Tensor<1, dim> u = translation ? translation(t) : Tensor<1, dim>();
    return DiePose<dim>(pivot_rest + u, value_or_zero(rotation, t), pivot, axis);
  }

  void PrescribedMotionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Translation",
                      "0; 0",
                      Patterns::Anything(),
                      "Displacement of the pivot 'ux(t); uy(t)' (3D: 'ux(t); uy(t); uz(t)') (mm).");
    prm.declare_entry("Rotation",
                      "0",
                      Patterns::Anything(),
                      "Rotation angle phi(t) about the pivot (degrees, counter-clockwise; 3D: "
                      "about Axis through the pivot, right-hand rule).");
    prm.declare_entry("Pivot",
                      "0, 0",
                      Patterns::Anything(),
                      "Rotation centre in die coordinates (3D: x, y, z; x, y means z = 0).");
    prm.declare_entry("Axis", "0, 0, 1", Patterns::Anything(), "3D only: axis of the Rotation.");
  }

  void
  PrescribedMotionParameters::parse(ParameterHandler &prm, const std::string &, const std::string &)
  {
    translation = prm.get("Translation");
    rotation = prm.get("Rotation");
    pivot = prm.get("Pivot");
    axis = prm.get("Axis");
  }

  namespace
  {
    template <int dim>
    std::unique_ptr<DieMotion<dim>> make(const PrescribedMotionParameters &p,
                                         const std::string                &path)
    {
      Tensor<1, dim> axis;
      if constexpr (dim == 3)
      {
        axis = Tensor<1, 3>(parse_die_point<3>(p.axis, path + "Axis"));
        require(axis.norm() > 0., path + "Axis", "must be a nonzero vector");
      }
      const std::vector<std::string> u = split_and_trim(p.translation, ';');
      require(u.size() == dim,
              path + "Translation",
              dim == 2 ? "needs two expressions 'ux(t); uy(t)'"
                       : "needs three expressions 'ux(t); uy(t); uz(t)' in a 3D run");
      std::vector<TimeFunction> components;
      for (unsigned int c = 0; c < dim; ++c)
        components.push_back(parse_time_function(u[c], path + "Translation"));
      const TimeFunction phi
          = parse_time_function(p.rotation, path + "Rotation", numbers::PI / 180.);
      const Point<dim> pivot = parse_die_point<dim>(p.pivot, path + "Pivot");
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
  } // namespace

  std::unique_ptr<DieMotion<2>> PrescribedMotionParameters::create_2d(const std::string &path) const
  {
    return make<2>(*this, path);
  }

  std::unique_ptr<DieMotion<3>> PrescribedMotionParameters::create_3d(const std::string &path) const
  {
    return make<3>(*this, path);
  }

  template class PrescribedMotion<2>;
  template class PrescribedMotion<3>;
} // namespace ausroll::contact

AUSROLL_REGISTER_DIE_MOTION(ausroll::contact::PrescribedMotionParameters,
                            "prescribed",
                            "Prescribed",
                            "Translation and Rotation about Pivot as functions of t")
