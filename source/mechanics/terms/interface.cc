#include <ausroll/mechanics/terms/interface.h>

namespace ausroll::mechanics
{
  template <int dim>
  AssemblyLayout::AssemblyLayout(const dealii::FiniteElement<dim> &fe,
                                 const unsigned int                n_q,
                                 const unsigned int                n_face_q)
      : n_dofs(fe.n_dofs_per_cell())
      , n_q(n_q)
      , n_face_q(n_face_q)
      , n_base(fe.n_dofs_per_cell() / dim) // support points of the FE_Q base element
      , component(n_dofs)
      , node_dofs(n_base)
  {
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const auto ci = fe.system_to_component_index(i);
      component[i] = ci.first;
      node_dofs[ci.second][ci.first] = i;
    }
  }

  template AssemblyLayout::AssemblyLayout(const dealii::FiniteElement<2> &,
                                          const unsigned int,
                                          const unsigned int);
  template AssemblyLayout::AssemblyLayout(const dealii::FiniteElement<3> &,
                                          const unsigned int,
                                          const unsigned int);
} // namespace ausroll::mechanics
