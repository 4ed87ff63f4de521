#include <ausroll/contact/surfaces/arc_line.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/contact/surfaces/ellipse.h>
#include <ausroll/contact/surfaces/flat.h>
#include <ausroll/contact/surfaces/involute_gear.h>
#include <ausroll/contact/surfaces/polyline.h>
#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/core/exceptions.h>

#include <vector>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  namespace
  {
    /** One 2D die shape: its `Shape` name, its subsection, and how to declare and make it. */
    struct Shape
    {
      std::string name;
      std::string subsection;
      void (*declare)(ParameterHandler &);
      std::unique_ptr<ShapeParameters> (*make)();
    };

    template <class Parameters>
    std::unique_ptr<ShapeParameters> make()
    {
      return std::make_unique<Parameters>();
    }

    /** The 2D die shapes: one line each. */
    const std::vector<Shape> &shapes()
    {
      static const std::vector<Shape> table{
          {"flat", "Flat", &FlatParameters::declare_parameters, &make<FlatParameters>},
          {"circle", "Circle", &CircleParameters::declare_parameters, &make<CircleParameters>},
          {"polyline",
           "Polyline",
           &PolylineParameters::declare_parameters,
           &make<PolylineParameters>},
          {"arc line",
           "Arc line",
           &ArcLineParameters::declare_parameters,
           &make<ArcLineParameters>},
          {"involute gear",
           "Involute gear",
           &InvoluteGearParameters::declare_parameters,
           &make<InvoluteGearParameters>},
          {"ellipse", "Ellipse", &EllipseParameters::declare_parameters, &make<EllipseParameters>},
      };
      return table;
    }

    const Shape &find_shape(const std::string &name, const std::string &die_path)
    {
      for (const Shape &s : shapes())
        if (s.name == name)
          return s;
      throw InputError(die_path + "Shape: unknown shape '" + name + "' (expected one of "
                       + shape_selection() + ")");
    }
  } // namespace

  std::string shape_selection()
  {
    std::string names;
    for (const Shape &s : shapes())
      names += (names.empty() ? "" : "|") + s.name;
    return names;
  }

  void declare_shape_parameters(ParameterHandler &prm)
  {
    for (const Shape &s : shapes())
    {
      prm.enter_subsection(s.subsection);
      s.declare(prm);
      prm.leave_subsection();
    }
  }

  std::string shape_path(const std::string &shape, const std::string &die_path)
  {
    return die_path + find_shape(shape, die_path).subsection + "/";
  }

  std::shared_ptr<const ShapeParameters> parse_shape_parameters(const std::string &shape,
                                                                ParameterHandler  &prm,
                                                                const std::string &die_path,
                                                                const std::string &input_directory)
  {
    const Shape                     &s = find_shape(shape, die_path);
    std::unique_ptr<ShapeParameters> parameters = s.make();
    prm.enter_subsection(s.subsection);
    parameters->parse(prm, die_path + s.subsection + "/", input_directory);
    prm.leave_subsection();
    return parameters;
  }

  std::map<std::string, std::string> moved_die_entries(const unsigned int n_dies)
  {
    // the flat list of shape entries of `Contact/Die N` before the shape subsections
    const std::vector<std::pair<std::string, std::vector<std::string>>> moved{
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
    std::map<std::string, std::string> result;
    for (unsigned int k = 0; k < n_dies; ++k)
    {
      const std::string die = "Contact/Die " + std::to_string(k) + "/";
      for (const auto &[entry, subsections] : moved)
      {
        std::string to;
        for (const std::string &s : subsections)
          to += (to.empty() ? "" : " or ") + ("`" + die + s + "/" + entry + "`");
        result[die + entry] = to;
      }
    }
    return result;
  }
} // namespace ausroll::contact::surfaces
