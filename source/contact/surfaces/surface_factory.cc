#include <ausroll/contact/surfaces/surface_factory.h>

#include <vector>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  std::string shape_selection()
  {
    return ShapeRegistry<2>::instance().selection() + "|"
           + ShapeRegistry<3>::instance().selection();
  }

  void declare_shape_parameters(ParameterHandler &prm)
  {
    ShapeRegistry<2>::instance().declare_subsections(prm);
    ShapeRegistry<3>::instance().declare_subsections(prm);
  }

  void add_moved_shape_entries(const std::string                  &parent_path,
                               std::map<std::string, std::string> &moved)
  {
    // the flat list of shape entries of `Contact/Die N` (and of a 3D `Profile`) before the shape
    // subsections
    const std::vector<std::pair<std::string, std::vector<std::string>>> entries{
        {"Point", {"Flat"}},
        {"Normal", {"Flat"}},
        {"Center", {"Circle"}},
        {"Radius", {"Circle"}},
        {"Material inside", {"Circle"}},
        {"Points", {"Polyline", "Arc line"}},
        {"Points file", {"Polyline", "Arc line"}},
        {"Fillet radii", {"Arc line"}},
        {"Number of teeth", {"Involute gear"}},
        {"Diametral pitch", {"Involute gear"}},
        {"Module", {"Involute gear"}},
        {"Pressure angle", {"Involute gear"}},
        {"Addendum", {"Involute gear"}},
        {"Dedendum", {"Involute gear"}},
        {"Tooth thickness", {"Involute gear"}},
        {"Root fillet radius", {"Involute gear"}},
        {"Tip radius", {"Involute gear"}},
        {"Tooth axis angle", {"Involute gear"}},
        {"Teeth in sector", {"Involute gear"}},
    };
    for (const auto &[entry, subsections] : entries)
    {
      std::string to;
      for (const std::string &s : subsections)
        to += (to.empty() ? "" : " or ") + ("`" + parent_path + s + "/" + entry + "`");
      moved[parent_path + entry] = to;
    }
  }

  std::map<std::string, std::string> moved_die_entries(const unsigned int n_dies)
  {
    std::map<std::string, std::string> result;
    for (unsigned int k = 0; k < n_dies; ++k)
    {
      const std::string die = "Contact/Die " + std::to_string(k) + "/";
      add_moved_shape_entries(die, result);
      add_moved_shape_entries(die + "Revolved profile/Profile/", result);
      add_moved_shape_entries(die + "Extruded profile/Profile/", result);
    }
    return result;
  }
} // namespace ausroll::contact::surfaces
