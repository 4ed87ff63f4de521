#include <ausroll/contact/surfaces/chain_surface.h>
#include <ausroll/contact/surfaces/flat.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/plane_vectors.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;
  using namespace geometry::plane;

  geometry::CurveChain
  flat_chain(const Point<2> &point, const Tensor<1, 2> &direction, const double half_length)
  {
    require(half_length > 0.0, curve_entry, "a flat die needs a positive half length");
    require(direction.norm() > 0.0, curve_entry, "a flat die needs a non-zero direction");
    if (std::isinf(half_length))
      return geometry::CurveChain(
          {geometry::CurveSegment::line_through(point, direction, -inf, inf)}, false);
    const Tensor<1, 2> d = direction / direction.norm();
    return geometry::CurveChain(
        {geometry::CurveSegment::line(point - half_length * d, point + half_length * d)}, false);
  }

  void FlatParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Point", "0, 0", Patterns::Anything(), "A point of the die surface.");
    prm.declare_entry("Normal",
                      "0, 1",
                      Patterns::Anything(),
                      "Surface normal pointing out of the die, towards the workpiece.");
  }

  void FlatParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    point = parse_point<2>(prm.get("Point"), path + "Point");
    normal = parse_point<2>(prm.get("Normal"), path + "Normal");
    require(normal.norm() > 0., path + "Normal", "must not be the zero vector");
  }

  std::unique_ptr<const RigidSurface<2>> FlatParameters::create(const std::string &) const
  {
    const Tensor<1, 2> n = normal / normal.norm();
    // travel direction with the die material on the right: t = n rotated by -90 degrees
    const Tensor<1, 2> direction({n[1], -n[0]});
    return std::make_unique<ChainSurface>("flat", flat_chain(point, direction));
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(2,
                           ausroll::contact::surfaces::FlatParameters,
                           "flat",
                           "Flat",
                           "an infinite straight line through Point with the outward Normal")
