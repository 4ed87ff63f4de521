#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/mechanics/boundary_conditions.h>

#include <deal.II/base/numbers.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <map>
#include <sstream>

namespace ausroll::mechanics
{
  using namespace dealii;

  namespace
  {
    std::string condition_name(const unsigned int i)
    {
      return "Boundary conditions/Condition " + std::to_string(i);
    }
  } // namespace

  void BoundaryConditionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Number of conditions",
                      "0",
                      Patterns::Integer(0, max_conditions),
                      "How many of the subsections 'Condition 0', 'Condition 1', ... are used.");
    for (unsigned int i = 0; i < max_conditions; ++i)
    {
      prm.enter_subsection("Condition " + std::to_string(i));
      prm.declare_entry(
          "Boundary id", "0", Patterns::Integer(0, 255), "Boundary id the condition acts on.");
      prm.declare_entry("Type",
                        "fixed",
                        Patterns::Selection("fixed|displacement|pressure|traction"),
                        "fixed: u = 0; displacement: the selected components follow Value; "
                        "pressure: normal pressure Value (MPa, positive pushes into the body), on "
                        "the deformed surface (follower load) unless Model/Kinematics = small "
                        "strain; traction: dead load, force per reference area, one expression per "
                        "direction.");
      prm.declare_entry("Components",
                        "x, y",
                        Patterns::Anything(),
                        "Displacement components prescribed by Type = displacement (x, y, z).");
      prm.declare_entry(
          "Value",
          "0",
          Patterns::Anything(),
          "Expressions in x, y, (z,) t and pi, separated by ';' (one per selected "
          "component for displacement, one for pressure, one per direction for traction).");
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  std::set<unsigned int> BoundaryConditionParameters::held_boundaries() const
  {
    std::set<unsigned int> held;
    for (const BoundaryCondition &c : conditions)
      if (c.type == BoundaryConditionType::fixed || c.type == BoundaryConditionType::displacement)
        held.insert(c.id);
    return held;
  }

  void BoundaryConditionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    const unsigned int n = prm.get_integer("Number of conditions");
    conditions.clear();
    for (unsigned int i = 0; i < n; ++i)
    {
      prm.enter_subsection("Condition " + std::to_string(i));
      BoundaryCondition c;
      c.id = prm.get_integer("Boundary id");
      const std::string type = prm.get("Type");
      c.type = type == "fixed"          ? BoundaryConditionType::fixed
               : type == "displacement" ? BoundaryConditionType::displacement
               : type == "pressure"     ? BoundaryConditionType::pressure
                                        : BoundaryConditionType::traction;
      c.components = prm.get("Components");
      c.value = prm.get("Value");
      conditions.push_back(c);
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  template <int dim>
  BoundaryConditions<dim>::BoundaryConditions(const BoundaryConditionParameters &parameters)
  {
    const std::string                   variables = dim == 2 ? "x,y,t" : "x,y,z,t";
    const std::map<std::string, double> constants{{"pi", numbers::PI}};
    for (unsigned int i = 0; i < parameters.conditions.size(); ++i)
    {
      const BoundaryCondition &c = parameters.conditions[i];
      Entry                    e;
      e.condition = c;
      std::vector<bool>              mask(dim, false);
      std::vector<std::string>       expressions(dim, "0");
      const std::vector<std::string> values = split_and_trim(c.value, ';');

      switch (c.type)
      {
        case BoundaryConditionType::fixed:
          std::fill(mask.begin(), mask.end(), true);
          break;
        case BoundaryConditionType::displacement:
        {
          const std::vector<std::string> comps = split_and_trim(c.components, ',');
          require(!comps.empty(), condition_name(i) + "/Components", "no component given");
          for (const std::string &comp : comps)
          {
            const unsigned int d = comp == "x" ? 0 : comp == "y" ? 1 : comp == "z" ? 2 : 99;
            require(d < dim,
                    condition_name(i) + "/Components",
                    "'" + comp + "' is not a displacement component (x, y"
                        + (dim == 3 ? ", z)" : ")"));
            mask[d] = true;
          }
          require(values.size() == comps.size(),
                  condition_name(i) + "/Value",
                  "needs one expression per component in Components ("
                      + std::to_string(comps.size()) + ")");
          for (unsigned int k = 0; k < comps.size(); ++k)
            expressions[comps[k] == "x" ? 0 : comps[k] == "y" ? 1 : 2] = values[k];
          break;
        }
        case BoundaryConditionType::pressure:
          require(values.size() == 1, condition_name(i) + "/Value", "needs one expression");
          expressions[0] = values[0];
          break;
        case BoundaryConditionType::traction:
          require(values.size() == dim,
                  condition_name(i) + "/Value",
                  "needs " + std::to_string(dim) + " expressions separated by ';'");
          expressions = values;
          break;
      }
      e.mask = ComponentMask(mask);
      e.function = std::make_unique<FunctionParser<dim>>(dim);
      for (const std::string &expression : expressions)
        require_expression_length(expression, condition_name(i) + "/Value");
      try
      {
        e.function->initialize(variables, expressions, constants, true);
        // Evaluate once so that errors surface now, not in the middle of a run.
        e.function->set_time(0.);
        Vector<double> v(dim);
        e.function->vector_value(Point<dim>(), v);
      }
      catch (...)
      {
        throw InputError(condition_name(i) + "/Value: cannot parse '" + abbreviate(c.value)
                         + "' (variables: " + variables + ", pi)");
      }
      entries.push_back(std::move(e));
    }
  }

  template <int dim>
  void BoundaryConditions<dim>::check_values(const Triangulation<dim>  &triangulation,
                                             const std::vector<double> &times) const
  {
    for (unsigned int i = 0; i < entries.size(); ++i)
    {
      const Entry            &e = entries[i];
      std::vector<Point<dim>> points;
      // vertices of the coarse mesh: the same on every MPI rank
      for (const auto &cell : triangulation.cell_iterators_on_level(0))
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == e.condition.id)
            for (const auto v : cell->face(f)->vertex_indices())
              points.push_back(cell->face(f)->vertex(v));
      if (points.size() > 64) // a bounded sample of the boundary
      {
        std::vector<Point<dim>> sample;
        for (unsigned int k = 0; k < 64; ++k)
          sample.push_back(points[k * points.size() / 64]);
        points.swap(sample);
      }
      Vector<double> v(dim);
      for (const double t : times)
      {
        e.function->set_time(t);
        for (const Point<dim> &x : points)
        {
          e.function->vector_value(x, v);
          for (unsigned int d = 0; d < dim; ++d)
            if (!std::isfinite(v[d]))
            {
              std::ostringstream msg;
              msg << condition_name(i) << "/Value: '" << abbreviate(e.condition.value)
                  << "' is not finite ("
                  << (std::isnan(v[d]) ? "nan"
                      : v[d] > 0       ? "inf"
                                       : "-inf")
                  << ") at t = " << t << ", x = (" << x << ")";
              throw InputError(msg.str());
            }
        }
      }
    }
  }

  template <int dim>
  void
  BoundaryConditions<dim>::add_increment_constraints(const DoFHandler<dim> &dof_handler,
                                                     const double           time,
                                                     const TrilinosWrappers::MPI::Vector &current,
                                                     AffineConstraints<double> &constraints) const
  {
    for (const Entry &e : entries)
    {
      if (e.condition.type != BoundaryConditionType::fixed
          && e.condition.type != BoundaryConditionType::displacement)
        continue;
      e.function->set_time(time);
      std::map<types::global_dof_index, double> values;
      VectorTools::interpolate_boundary_values(
          dof_handler, e.condition.id, *e.function, values, e.mask);
      for (const auto &[dof, value] : values)
        if (constraints.can_store_line(dof) && !constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.set_inhomogeneity(dof, value - current[dof]);
        }
    }
  }

  template <int dim>
  bool BoundaryConditions<dim>::has_surface_load(const types::boundary_id id) const
  {
    for (const Entry &e : entries)
      if (e.condition.id == id
          && (e.condition.type == BoundaryConditionType::pressure
              || e.condition.type == BoundaryConditionType::traction))
        return true;
    return false;
  }

  template <int dim>
  Tensor<1, dim> BoundaryConditions<dim>::dead_traction(const types::boundary_id id,
                                                        const Point<dim>        &X,
                                                        const double             time) const
  {
    Tensor<1, dim> t;
    for (const Entry &e : entries)
      if (e.condition.id == id && e.condition.type == BoundaryConditionType::traction)
      {
        e.function->set_time(time);
        for (unsigned int d = 0; d < dim; ++d)
          t[d] += e.function->value(X, d);
      }
    return t;
  }

  template <int dim>
  double BoundaryConditions<dim>::pressure(const types::boundary_id id,
                                           const Point<dim>        &X,
                                           const double             time) const
  {
    double p = 0.;
    for (const Entry &e : entries)
      if (e.condition.id == id && e.condition.type == BoundaryConditionType::pressure)
      {
        e.function->set_time(time);
        p += e.function->value(X, 0);
      }
    return p;
  }

  template <int dim>
  Tensor<1, dim> BoundaryConditions<dim>::traction(const types::boundary_id id,
                                                   const Point<dim>        &X,
                                                   const Tensor<1, dim>    &normal,
                                                   const double             time) const
  {
    return dead_traction(id, X, time) - pressure(id, X, time) * normal;
  }

  template <int dim>
  std::vector<std::pair<std::string, double>>
  BoundaryConditions<dim>::pressure_values(const double time) const
  {
    std::vector<std::pair<std::string, double>> values;
    for (const Entry &e : entries)
      if (e.condition.type == BoundaryConditionType::pressure)
      {
        e.function->set_time(time);
        values.emplace_back("pressure_" + std::to_string(e.condition.id),
                            e.function->value(Point<dim>(), 0));
      }
    return values;
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace ausroll::mechanics
