#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/tangent/curvature_tangent.h>
#include <ausroll/core/exceptions.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace ausroll::contact
{
  using namespace dealii;

  template <int dim>
  CurvatureTangent<dim>::CurvatureTangent()
  {
    if constexpr (dim != 2)
      throw InputError("Contact/Curvature tangent is planar (2D only); with a three-dimensional "
                       "Geometry/Type set it to false");
  }

  template <int dim>
  void CurvatureTangent<dim>::setup(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler)
  {
    dofs.clear();
    owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    const auto                          &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
        {
          const auto it = points.find(local[i]);
          if (it != points.end())
            dofs[local[i]] = DofInfo{fe.system_to_component_index(i).first, it->second};
        }
      }
  }

  template <int dim>
  double CurvatureTangent<dim>::node_term(const Tensor<1, 2> &normal,
                                          const Tensor<1, 2> &dn_ds,
                                          const Tensor<1, 2> &tangent,
                                          const double        c,
                                          const Tensor<1, 2> &r,
                                          const Tensor<2, 2> &T,
                                          const unsigned int  a,
                                          const unsigned int  b)
  {
    Tensor<1, 2> v;
    v[b] = 1.;
    v[a] = c;
    // motion along the constraint: dx = v du_b, ds = t . dx
    const Tensor<1, 2> dn = dn_ds * (tangent * v);
    const double       dc = -(dn[b] * normal[a] - normal[b] * dn[a]) / (normal[a] * normal[a]);
    const Tensor<1, 2> Tr = T * r;
    Tensor<2, 2>       T_minus_I = T;
    for (unsigned int i = 0; i < 2; ++i)
      T_minus_I[i][i] -= 1.;
    const Tensor<1, 2> w = T_minus_I * normal;
    return dc * Tr[a] + (v * w) * (dn * r);
  }

  template <int dim>
  unsigned int CurvatureTangent<dim>::add_to(const ContactTangentInput<dim> &input,
                                             TrilinosWrappers::SparseMatrix &matrix,
                                             TrilinosWrappers::MPI::Vector & /*rhs*/) const
  {
    if constexpr (dim != 2)
      return 0; // the constructor refused it
    else
    {
      const ContactOperator<dim>      &contact = input.contact;
      const AffineConstraints<double> &constraints = input.constraints;
      const auto                      &u = input.u;
      const auto                      &residual = input.residual;
      const double                     time = input.time;
      unsigned int                     n_terms = 0;
      for (const auto &line : constraints.get_lines())
      {
        // a slip line: u_a = c u_b + gap term, a and b the two components of one node
        if (line.entries.size() != 1 || !owned.is_element(line.entries[0].first))
          continue;
        const types::global_dof_index ka = line.index, kb = line.entries[0].first;
        const auto                    ia = dofs.find(ka), ib = dofs.find(kb);
        if (ia == dofs.end() || ib == dofs.end() || ia->second.component == ib->second.component
            || ia->second.support_point.distance(ib->second.support_point) > 1e-12)
          continue;
        const unsigned int                     a = ia->second.component, b = ib->second.component;
        const double                           c = line.entries[0].second;
        Point<2>                               x;
        Tensor<1, 2>                           r;
        std::array<types::global_dof_index, 2> node_dofs;
        node_dofs[a] = ka;
        node_dofs[b] = kb;
        for (unsigned int d = 0; d < 2; ++d)
        {
          x[d] = ia->second.support_point[d] + u[node_dofs[d]];
          r[d] = residual[node_dofs[d]];
        }
        // the die the node lies on: the nearest one
        int              die = -1;
        DieProjection<2> p;
        for (unsigned int k = 0; k < contact.n_dies(); ++k)
        {
          const DieProjection<2> q = contact.die(k).project(x, time);
          if (q.valid && (die < 0 || std::abs(q.gap) < std::abs(p.gap)))
          {
            die = k;
            p = q;
          }
        }
        if (die < 0)
          continue;
        // dn/ds by central differences; skipped where the normal jumps (a kink of a polyline die)
        const double           h = 1e-6 * std::max(1., x.norm());
        const DieProjection<2> plus = contact.die(die).project(x + h * p.tangent, time);
        const DieProjection<2> minus = contact.die(die).project(x - h * p.tangent, time);
        if (!plus.valid || !minus.valid)
          continue;
        const Tensor<1, 2> forward = (plus.normal - p.normal) / h;
        const Tensor<1, 2> backward = (p.normal - minus.normal) / h;
        const Tensor<1, 2> dn_ds = 0.5 * (forward + backward);
        if (dn_ds.norm() < 1e-12 || (forward - backward).norm() > 0.1 * dn_ds.norm())
          continue;
        Tensor<2, 2> T;
        T[0][0] = T[1][1] = 1.;
        const auto &transforms = contact.row_transforms();
        const auto  it = transforms.find(node_dofs[0]);
        if (it != transforms.end())
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              T[i][j] = it->second.matrix[i][j];
        const double term = node_term(p.normal, dn_ds, p.tangent, c, r, T, a, b);
        if (term != 0.)
        {
          matrix.add(kb, kb, term);
          ++n_terms;
        }
      }
      matrix.compress(VectorOperation::add);
      return n_terms;
    }
  }

  template class CurvatureTangent<2>;
  template class CurvatureTangent<3>;
} // namespace ausroll::contact
