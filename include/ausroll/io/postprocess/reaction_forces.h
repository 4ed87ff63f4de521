/**
 * @file reaction_forces.h
 * Reaction forces on boundaries (`Postprocess/Reaction boundaries`).
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

#include <deal.II/base/index_set.h>

#include <array>

namespace ausroll::io::postprocess
{
  /**
   * History columns `reaction_<id>_x`, `reaction_<id>_y` (`_z` in 3D; force, N) for each id of
   * `Postprocess/Reaction boundaries`, in the order given: the sum of the residual f_int - f_ext
   * over the DoFs of that component on boundary <id>, i.e. the force the supports exert on the
   * body there, in the force unit of the assembly (for a bar in uniaxial stress sigma pulled on
   * its end face: sigma A with A that face's area). A DoF on two listed boundaries counts in
   * both.
   */
  template <int dim>
  class ReactionForces : public Postprocessor<dim>
  {
  public:
    /** Boundaries of @p ids (`Postprocess/Reaction boundaries`). */
    explicit ReactionForces(const std::vector<unsigned int> &ids);
    std::string name() const override { return "reaction forces"; }
    void        initialize(const PostprocessInput<dim> &input) override;
    void        execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;
    Unit        unit(const std::string &column) const override
    {
      (void)column;
      return {"force", "N"};
    }

  private:
    std::vector<unsigned int> ids;
    /** Per boundary and component, the locally owned DoFs on it. */
    std::vector<std::array<dealii::IndexSet, dim>> dofs;
  };
} // namespace ausroll::io::postprocess
