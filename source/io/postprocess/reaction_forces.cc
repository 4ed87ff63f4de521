#include <ausroll/core/parse_utilities.h>
#include <ausroll/io/postprocess/reaction_forces.h>
#include <ausroll/io/postprocess/standard_set.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  template <int dim>
  ReactionForces<dim>::ReactionForces(const std::vector<unsigned int> &ids)
      : ids(ids)
  {
  }

  template <int dim>
  void ReactionForces<dim>::initialize(const PostprocessInput<dim> &input)
  {
    dofs.clear();
    const IndexSet owned = input.dof_handler.locally_owned_dofs();
    for (const unsigned int id : ids)
    {
      std::array<IndexSet, dim> sets;
      for (unsigned int c = 0; c < dim; ++c)
      {
        std::vector<bool> mask(dim, false);
        mask[c] = true;
        sets[c] = DoFTools::extract_boundary_dofs(
            input.dof_handler, ComponentMask(mask), {static_cast<types::boundary_id>(id)});
        sets[c] = sets[c] & owned;
      }
      dofs.push_back(sets);
    }
  }

  template <int dim>
  void ReactionForces<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    const MPI_Comm comm = input.dof_handler.get_communicator();
    for (unsigned int b = 0; b < ids.size(); ++b)
      for (unsigned int d = 0; d < dim; ++d)
      {
        double sum = 0.;
        for (const auto i : dofs[b][d])
          sum += input.residual[i];
        row.emplace_back("reaction_" + std::to_string(ids[b]) + "_" + std::string(1, "xyz"[d]),
                         Utilities::MPI::sum(sum, comm));
      }
  }

  template class ReactionForces<2>;
  template class ReactionForces<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_reaction_forces(const PostprocessorContext &c)
    {
      return std::make_unique<ReactionForces<dim>>(parse_unsigned_list(
          c.postprocess.reaction_boundaries, "Postprocess/Reaction boundaries"));
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_reaction_forces,
                               "reaction forces",
                               40,
                               "reaction forces of the Reaction boundaries")
