#include <ausroll/contact/surfaces/shape_entries_3d.h>
#include <ausroll/core/parse_utilities.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  Tensor<1, 3> get_vector(ParameterHandler &prm, const std::string &name, const std::string &entry)
  {
    return Tensor<1, 3>(parse_point<3>(prm.get(name), entry));
  }

  Tensor<1, 3>
  get_direction(ParameterHandler &prm, const std::string &name, const std::string &entry)
  {
    const Tensor<1, 3> v = get_vector(prm, name, entry);
    require(v.norm() > 0., entry, "must be a nonzero vector");
    return v;
  }

  void declare_placement(ParameterHandler  &prm,
                         const std::string &center_name,
                         const std::string &center_help,
                         const std::string &axis_help,
                         const std::string &reference_help)
  {
    prm.declare_entry(center_name, "0, 0, 0", Patterns::Anything(), center_help);
    prm.declare_entry("Axis", "0, 0, 1", Patterns::Anything(), axis_help);
    prm.declare_entry("Reference direction", "1, 0, 0", Patterns::Anything(), reference_help);
  }

  void parse_placement(ParameterHandler  &prm,
                       const std::string &center_name,
                       const std::string &path,
                       Point<3>          &center,
                       Tensor<1, 3>      &axis,
                       Tensor<1, 3>      &reference)
  {
    center = parse_point<3>(prm.get(center_name), path + center_name);
    axis = get_direction(prm, "Axis", path + "Axis");
    reference = get_vector(prm, "Reference direction", path + "Reference direction");
  }

} // namespace ausroll::contact::surfaces
