#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/contact_strategy.h>
#include <ausroll/contact/die_motion.h>
#include <ausroll/contact/friction_law.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

namespace ausroll::contact
{
  using namespace dealii;

  bool is_3d_shape(const std::string &shape)
  {
    return surfaces::ShapeRegistry<3>::instance().contains(shape);
  }

  void ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Number of dies",
                      "0",
                      Patterns::Integer(0, max_dies),
                      "Rigid dies used (subsections Die 0, Die 1, ...).");
    prm.declare_entry("Strategy",
                      "active set",
                      Patterns::Selection(StrategyRegistry::instance().selection()),
                      "How contact statuses are found (a strategy's entries are in the subsection "
                      "of its name): "
                          + StrategyRegistry::instance().descriptions() + ".");
    StrategyRegistry::instance().declare_subsections(prm);
    prm.declare_entry(
        "Maximum status changes",
        "6",
        Patterns::Integer(1, 100),
        "A node may change its contact status at most this often within one load step "
        "(guards the active set against chattering).");
    prm.declare_entry(
        "Curvature tangent",
        "false",
        Patterns::Bool(),
        "Add to the tangent of a slipping node on a curved die the change of its equation as the "
        "die normal turns while the node slides (reaction over die radius). Newton then converges "
        "quadratically also when the contact forces are large (elastic punch: 58 instead of 90 "
        "iterations, doc/scenes/hard_cases.md); 2D and 3D (from the die's curvature along its "
        "tangent plane); false keeps the tangent of earlier versions, to which the shipped "
        "scenes' regression outputs are pinned.");
    prm.declare_entry(
        "Penetrating boundaries",
        "add",
        Patterns::Selection("add|warn"),
        "A workpiece boundary that is not among a die's Candidate boundaries cannot touch that "
        "die and would pass through it (the free side of an upsetting folding onto the platen "
        "when only the top face is a candidate). add: after a converged step in which a node of "
        "such a boundary crossed into the die (by more than 1 % of the smallest cell), the "
        "boundary becomes a candidate of the die, the run says so, and the step is solved again "
        "from its start; warn: only warn, results from then on are not those of the forming "
        "process. Boundaries with prescribed displacements are only warned about.");
    for (unsigned int k = 0; k < max_dies; ++k)
    {
      prm.enter_subsection("Die " + std::to_string(k));
      prm.declare_entry("Name",
                        "die" + std::to_string(k),
                        Patterns::Anything(),
                        "Label in history.csv (die_<Name>_force_x, ...).");
      prm.declare_entry("Shape",
                        "flat",
                        Patterns::Selection(surfaces::shape_selection()),
                        "Die surface, described in die coordinates in the subsection of the same "
                        "name (Flat, Circle, ...); the Motion places it. 2D runs: "
                            + surfaces::ShapeRegistry<2>::instance().descriptions() + ". 3D runs: "
                            + surfaces::ShapeRegistry<3>::instance().descriptions() + ".");
      prm.declare_entry("Friction",
                        "Coulomb",
                        Patterns::Selection(FrictionRegistry::instance().selection()),
                        "Friction law, its entries in the subsection of the same name: "
                            + FrictionRegistry::instance().descriptions()
                            + ". k = sigma_0 / sqrt(3) from the workpiece's initial yield stress "
                              "Material/Yield stress; a zero coefficient or factor is "
                              "frictionless.");
      FrictionRegistry::instance().declare_subsections(prm);
      prm.declare_entry(
          "Candidate boundaries",
          "",
          Patterns::List(Patterns::Integer(0, 255)),
          "Workpiece boundary ids whose nodes may touch this die (empty: all boundaries).");
      prm.declare_entry(
          "Search distance",
          "0",
          Patterns::Double(0.),
          "Nodes farther than this from the die are not projected (mm; 0: no limit).");
      surfaces::declare_shape_parameters(prm);

      prm.enter_subsection("Motion");
      prm.declare_entry("Type",
                        "fixed",
                        Patterns::Selection(MotionRegistry::instance().selection()),
                        "Motion of the die, its entries in the subsection of the same name: "
                            + MotionRegistry::instance().descriptions() + ".");
      MotionRegistry::instance().declare_subsections(prm);
      prm.leave_subsection();
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  std::map<std::string, std::string> ContactParameters::moved_entries()
  {
    std::map<std::string, std::string> moved = surfaces::moved_die_entries(max_dies);
    for (unsigned int k = 0; k < max_dies; ++k)
      add_moved_motion_entries("Contact/Die " + std::to_string(k) + "/Motion/", moved);
    // the friction entries moved into the subsection of their law
    for (unsigned int k = 0; k < max_dies; ++k)
    {
      const std::string die = "Contact/Die " + std::to_string(k) + "/";
      moved[die + "Friction coefficient"] = "`" + die + "Coulomb/Friction coefficient` or `" + die
                                            + "Coulomb capped by shear/Friction coefficient`";
      moved[die + "Friction factor"] = "`" + die + "Tresca/Friction factor`, `" + die
                                       + "Coulomb capped by shear/Friction factor` or `" + die
                                       + "Levanov/Friction factor`";
    }
    moved["Contact/Ratio tolerance"] = "`Contact/Load increment ratio/Ratio tolerance`";
    return moved;
  }

  void ContactParameters::parse_parameters(ParameterHandler  &prm,
                                           const std::string &input_directory)
  {
    prm.enter_subsection("Contact");
    const unsigned int n_dies = prm.get_integer("Number of dies");
    strategy = prm.get("Strategy");
    strategy_parameters = StrategyRegistry::instance().parse(
        strategy, prm, "Contact/", input_directory, "Strategy");
    max_status_changes = prm.get_integer("Maximum status changes");
    curvature_tangent = prm.get_bool("Curvature tangent");
    add_penetrating_boundaries = prm.get("Penetrating boundaries") == "add";
    dies.clear();
    for (unsigned int k = 0; k < n_dies; ++k)
    {
      const std::string path = "Contact/Die " + std::to_string(k) + "/";
      prm.enter_subsection("Die " + std::to_string(k));
      DieParameters d;
      d.name = prm.get("Name");
      require_label(d.name, path + "Name");
      for (unsigned int j = 0; j < dies.size(); ++j)
        require(dies[j].name != d.name,
                path + "Name",
                "'" + d.name + "' is also the name of Contact/Die " + std::to_string(j)
                    + "; each die needs a name of its own (it names history.csv columns)");
      d.shape = prm.get("Shape");
      if (is_3d_shape(d.shape))
      {
        const auto &shapes = surfaces::ShapeRegistry<3>::instance();
        d.surface_path = shapes.path(d.shape, path);
        d.surface_3d = shapes.parse(d.shape, prm, path, input_directory, "Shape");
      }
      else
      {
        const auto &shapes = surfaces::ShapeRegistry<2>::instance();
        d.surface_path = shapes.path(d.shape, path);
        d.surface = shapes.parse(d.shape, prm, path, input_directory, "Shape");
      }
      d.friction_law = prm.get("Friction");
      d.friction = FrictionRegistry::instance().parse(
          d.friction_law, prm, path, input_directory, "Friction");
      d.candidate_boundaries
          = parse_unsigned_list(prm.get("Candidate boundaries"), path + "Candidate boundaries");
      d.search_distance = prm.get_double("Search distance");

      prm.enter_subsection("Motion");
      d.motion_type = prm.get("Type");
      const auto &motions = MotionRegistry::instance();
      d.motion_path = motions.path(d.motion_type, path + "Motion/");
      d.motion = motions.parse(d.motion_type, prm, path + "Motion/", input_directory, "Type");
      prm.leave_subsection();
      prm.leave_subsection();
      dies.push_back(d);
    }
    prm.leave_subsection();
  }

} // namespace ausroll::contact
