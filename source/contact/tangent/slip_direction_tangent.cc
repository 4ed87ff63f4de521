#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/tangent/slip_direction_tangent.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace ausroll::contact
{
  using namespace dealii;

  template <int dim>
  unsigned int SlipDirectionTangent<dim>::add_to(const ContactTangentInput<dim> &input,
                                                 TrilinosWrappers::SparseMatrix &matrix,
                                                 TrilinosWrappers::MPI::Vector  &rhs) const
  {
    // 2D: the slip direction is a fixed sign over the step (see the class comment)
    if constexpr (dim == 2)
      return 0;
    else
    {
      unsigned int                         n_terms = 0;
      FullMatrix<double>                   block(dim, dim);
      dealii::Vector<double>               zero(dim);
      std::vector<types::global_dof_index> dofs(dim);
      for (const auto &n : input.contact.followed_slips())
      {
        // d(T d)/dx = T (P - d (x) d) / |s|, T the slip limit at this assembly's normal force
        const Tensor<1, dim> &d = n.direction;
        const Tensor<1, dim> &normal = n.normal;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            block(i, j) = n.slip_limit / n.slip
                          * ((i == j ? 1. : 0.) - normal[i] * normal[j] - d[i] * d[j]);
        for (unsigned int c = 0; c < dim; ++c)
          dofs[c] = n.dofs[c];
        zero = 0.;
        input.constraints.distribute_local_to_global(block, zero, dofs, matrix, rhs, true);
        ++n_terms;
      }
      matrix.compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);
      return n_terms;
    }
  }

  template class SlipDirectionTangent<2>;
  template class SlipDirectionTangent<3>;
} // namespace ausroll::contact
