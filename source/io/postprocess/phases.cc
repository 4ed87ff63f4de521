#include <ausroll/io/postprocess/phases.h>
#include <ausroll/io/postprocess/standard_set.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <limits>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  namespace
  {
    /** Smallest, largest and volume mean of one fraction of the committed states. */
    template <int dim, typename Fraction>
    void add_fraction_columns(const PostprocessInput<dim> &input,
                              const std::string           &name,
                              const Fraction              &fraction,
                              HistoryRow                  &row)
    {
      double lo = std::numeric_limits<double>::max(), hi = 0., integral = 0., volume = 0.;
      for (const auto &cell : input.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          const auto   points = input.material_points.get_data(cell);
          const double dV = cell->measure() / points.size(); // cell volume shared evenly
          for (const auto &p : points)
          {
            const double f = fraction(p->committed);
            lo = std::min(lo, f);
            hi = std::max(hi, f);
            integral += f * dV;
            volume += dV;
          }
        }
      const MPI_Comm comm = input.dof_handler.get_communicator();
      row.emplace_back(name + "_min", Utilities::MPI::min(lo, comm));
      row.emplace_back(name + "_max", Utilities::MPI::max(hi, comm));
      row.emplace_back(name + "_mean",
                       Utilities::MPI::sum(integral, comm) / Utilities::MPI::sum(volume, comm));
    }
  } // namespace

  template <int dim>
  void PhaseFractions<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    add_fraction_columns(
        input, "martensite", [](const material::MaterialState &s) { return s.martensite; }, row);
    if (with_bainite)
      add_fraction_columns(
          input, "bainite", [](const material::MaterialState &s) { return s.bainite; }, row);
  }

  template <int dim>
  void PhaseFractions<dim>::cell_fields(const PostprocessInput<dim> &input,
                                        std::vector<CellField>      &fields) const
  {
    const Triangulation<dim> &triangulation = input.dof_handler.get_triangulation();
    const unsigned int        n = triangulation.n_active_cells();
    Vector<float>             martensite(n), carbon(n), bainite(n);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const auto points = input.material_points.get_data(cell);
        double     f = 0., C = 0., f_b = 0.;
        for (const auto &p : points)
        {
          f += p->committed.martensite;
          C += p->committed.carbon;
          f_b += p->committed.bainite;
        }
        martensite[cell->active_cell_index()] = f / points.size();
        bainite[cell->active_cell_index()] = f_b / points.size();
        carbon[cell->active_cell_index()] = C / points.size();
      }
    fields.emplace_back("martensite_fraction", martensite);
    fields.emplace_back("carbon_content", carbon);
    if (with_bainite)
      fields.emplace_back("bainite_fraction", bainite);
  }

  template <int dim>
  Unit PhaseFractions<dim>::unit(const std::string &name) const
  {
    if (name == "carbon_content")
      return {"mass fraction", "wt%"};
    return {"volume fraction", "1"}; // martensite_* and bainite_* columns, the *_fraction fields
  }

  template class PhaseFractions<2>;
  template class PhaseFractions<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_phase_fractions(const PostprocessorContext &c)
    {
      if (!c.phases)
        return nullptr;
      return std::make_unique<PhaseFractions<dim>>(c.bainite);
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_phase_fractions,
                               "phases",
                               130,
                               "martensite fraction and carbon content when Phases are enabled")
