/**
 * @file carbon_profile.cc
 * The carbon content at the material points (see carbon_profile.h).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/material/carbon_profile.h>
#include <ausroll/material/property_table.h>

#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <limits>
#include <regex>
#include <sstream>

namespace ausroll::material
{
  using namespace dealii;

  namespace
  {
    const std::string entry = "Phases/Carbon content";

    /** True if @p text is a table `file: NAME.csv`. */
    bool is_table(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t");
      return first != std::string::npos && text.compare(first, 5, "file:") == 0;
    }
  } // namespace

  template <int dim>
  bool CarbonProfile<dim>::uses_depth(const std::string &text)
  {
    return is_table(text)
           || std::regex_search(text, std::regex("(^|[^A-Za-z0-9_])depth($|[^A-Za-z0-9_])"));
  }

  template <int dim>
  CarbonProfile<dim>::CarbonProfile(const std::string               &text,
                                    const Triangulation<dim>        &triangulation,
                                    const std::vector<unsigned int> &case_boundaries,
                                    const std::string               &input_directory)
      : text(text)
  {
    if (is_table(text))
      table = std::make_unique<PropertyTable>(
          PropertyTable::parse(text, entry, input_directory, false, false, "depth"));
    else
    {
      // the depth is the parser's last variable, which deal.II calls the time (FunctionParser
      // exists for dim <= 3 only, so x, y, z, depth cannot be a point of four coordinates)
      expression = std::make_unique<FunctionParser<dim>>(1);
      try
      {
        expression->initialize(dim == 2 ? "x,y,depth" : "x,y,z,depth",
                               text,
                               std::map<std::string, double>{{"pi", numbers::PI}},
                               /*time_dependent=*/true);
      }
      catch (...)
      {
        throw InputError(entry + ": cannot parse '" + abbreviate(text) + "' (variables: x, y"
                         + (dim == 3 ? ", z" : "") + ", depth; or 'file: NAME.csv')");
      }
    }
    if (uses_depth(text))
    {
      if (case_boundaries.empty())
        throw InputError("Phases/Case boundaries: the carbon profile uses the depth below the "
                         "surface, but no boundary is listed and no die has Candidate boundaries: "
                         "name the boundary ids of the carburized surface");
      boundary_depth = std::make_unique<geometry::BoundaryDepth<dim>>(
          triangulation, case_boundaries, "Phases/Case boundaries");
    }
  }

  template <int dim>
  CarbonProfile<dim>::~CarbonProfile() = default;

  template <int dim>
  double CarbonProfile<dim>::value(const Point<dim> &p) const
  {
    const double depth = boundary_depth ? boundary_depth->depth(p) : 0.;
    if (table)
      return table->value(depth);
    expression->set_time(depth);
    return expression->value(p);
  }

  template <int dim>
  void initialize_carbon(
      const CarbonProfile<dim>                                                   &profile,
      const std::string                                                          &text,
      const Mapping<dim>                                                         &mapping,
      const FiniteElement<dim>                                                   &fe,
      const Quadrature<dim>                                                      &quadrature,
      const DoFHandler<dim>                                                      &dof_handler,
      CellDataStorage<typename Triangulation<dim>::cell_iterator, MaterialPoint> &points,
      const MPI_Comm                                                              comm)
  {
    FEValues<dim> values(mapping, fe, quadrature, update_quadrature_points);
    double        lowest = std::numeric_limits<double>::max(), highest = -lowest;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        values.reinit(cell);
        const auto states = points.get_data(cell);
        for (unsigned int q = 0; q < states.size(); ++q)
        {
          const double C = profile.value(values.quadrature_point(q));
          lowest = std::isnan(C) ? -std::numeric_limits<double>::infinity() : std::min(lowest, C);
          highest = std::max(highest, C);
          states[q]->committed.carbon = states[q]->trial.carbon = C;
          states[q]->committed.martensite = states[q]->trial.martensite = 0.;
          states[q]->committed.bainite = states[q]->trial.bainite = 0.;
        }
      }
    // collective, so that every rank stops with the same message
    lowest = Utilities::MPI::min(lowest, comm);
    highest = Utilities::MPI::max(highest, comm);
    if (!(lowest >= 0. && highest <= 2.1))
    {
      std::ostringstream range;
      range << lowest << " to " << highest;
      throw InputError(entry + ": '" + abbreviate(text) + "' ranges from " + range.str()
                       + " wt% over the workpiece, outside 0 to 2.1 (steels)");
    }
  }

  template class CarbonProfile<2>;
  template class CarbonProfile<3>;
  template void
  initialize_carbon<2>(const CarbonProfile<2> &,
                       const std::string &,
                       const Mapping<2> &,
                       const FiniteElement<2> &,
                       const Quadrature<2> &,
                       const DoFHandler<2> &,
                       CellDataStorage<Triangulation<2>::cell_iterator, MaterialPoint> &,
                       const MPI_Comm);
  template void
  initialize_carbon<3>(const CarbonProfile<3> &,
                       const std::string &,
                       const Mapping<3> &,
                       const FiniteElement<3> &,
                       const Quadrature<3> &,
                       const DoFHandler<3> &,
                       CellDataStorage<Triangulation<3>::cell_iterator, MaterialPoint> &,
                       const MPI_Comm);
} // namespace ausroll::material
