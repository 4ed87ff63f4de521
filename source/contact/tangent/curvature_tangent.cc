#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/tangent/curvature_tangent.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace ausroll::contact
{
  using namespace dealii;

  namespace
  {
    /** The die nearest to @p x (smallest |gap| among the valid projections) and its projection
        @p p; -1 if no die is in range. */
    template <int dim>
    int nearest_die(const ContactOperator<dim> &contact,
                    const Point<dim>           &x,
                    const double                time,
                    DieProjection<dim>         &p)
    {
      int die = -1;
      for (unsigned int k = 0; k < contact.n_dies(); ++k)
      {
        const DieProjection<dim> q = contact.die(k).project(x, time);
        if (q.valid && (die < 0 || std::abs(q.gap) < std::abs(p.gap)))
        {
          die = k;
          p = q;
        }
      }
      return die;
    }
  } // namespace

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
    if constexpr (dim == 3)
      return add_to_3d(input, matrix);
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
        DieProjection<2> p;
        const int        die = nearest_die(contact, x, time, p);
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

  template <int dim>
  Tensor<2, 3> CurvatureTangent<dim>::node_term_3d(const Tensor<1, 3>                &normal,
                                                   const std::array<Tensor<1, 3>, 2> &dn_dt,
                                                   const std::array<Tensor<1, 3>, 2> &tangents,
                                                   const unsigned int                 k,
                                                   const Tensor<1, 3>                &r,
                                                   const Tensor<2, 3>                &T)
  {
    // v_j = e_j + c_j e_k for the free components j (v_k unused)
    std::array<Tensor<1, 3>, 3> v;
    for (unsigned int j = 0; j < 3; ++j)
      if (j != k)
      {
        v[j][j] = 1.;
        v[j][k] = -normal[j] / normal[k];
      }
    const Tensor<1, 3> Tr = T * r;
    Tensor<2, 3>       T_minus_I = T;
    for (unsigned int i = 0; i < 3; ++i)
      T_minus_I[i][i] -= 1.;
    const Tensor<1, 3> w = T_minus_I * normal;
    Tensor<2, 3>       term;
    for (unsigned int jj = 0; jj < 3; ++jj)
      if (jj != k)
      {
        // motion along the constraint: dx = v_j' du_j'
        const Tensor<1, 3> dn = dn_dt[0] * (tangents[0] * v[jj]) + dn_dt[1] * (tangents[1] * v[jj]);
        for (unsigned int j = 0; j < 3; ++j)
          if (j != k)
          {
            const double dc = -(dn[j] * normal[k] - normal[j] * dn[k]) / (normal[k] * normal[k]);
            term[j][jj] = dc * Tr[k] + (v[j] * w) * (dn * r);
          }
      }
    return term;
  }

  template <int dim>
  unsigned int CurvatureTangent<dim>::add_to_3d(const ContactTangentInput<dim> &input,
                                                TrilinosWrappers::SparseMatrix &matrix) const
  {
    unsigned int n_terms = 0;
    if constexpr (dim == 3)
    {
      const ContactOperator<dim> &contact = input.contact;
      for (const auto &line : input.constraints.get_lines())
      {
        // a 3D slip line: u_k = c_i u_i + c_j u_j + gap term, i, j, k the components of one node
        if (line.entries.size() != 2 || !owned.is_element(line.index))
          continue;
        const auto ik = dofs.find(line.index);
        if (ik == dofs.end())
          continue;
        const unsigned int                     k = ik->second.component;
        std::array<types::global_dof_index, 3> node_dofs;
        node_dofs[k] = line.index;
        bool one_node = true;
        for (const auto &entry : line.entries)
        {
          const auto it = dofs.find(entry.first);
          one_node = one_node && it != dofs.end() && it->second.component != k
                     && it->second.support_point.distance(ik->second.support_point) <= 1e-12;
          if (one_node)
            node_dofs[it->second.component] = entry.first;
        }
        if (!one_node || line.entries[0].first == line.entries[1].first)
          continue;
        Point<3>     x;
        Tensor<1, 3> r;
        for (unsigned int d = 0; d < 3; ++d)
        {
          x[d] = ik->second.support_point[d] + input.u[node_dofs[d]];
          r[d] = input.residual[node_dofs[d]];
        }
        // the die the node lies on: the nearest one
        DieProjection<3> p;
        const int        die = nearest_die(contact, x, input.time, p);
        if (die < 0)
          continue;
        // dn/dt_a by central differences; skipped where the normal jumps (an edge of the die)
        const double                h = 1e-6 * std::max(1., x.norm());
        std::array<Tensor<1, 3>, 2> dn_dt;
        bool                        smooth = true, curved = false;
        for (unsigned int a = 0; a < 2 && smooth; ++a)
        {
          const DieProjection<3> plus = contact.die(die).project(x + h * p.tangents[a], input.time);
          const DieProjection<3> minus
              = contact.die(die).project(x - h * p.tangents[a], input.time);
          if (!plus.valid || !minus.valid)
          {
            smooth = false;
            break;
          }
          const Tensor<1, 3> forward = (plus.normal - p.normal) / h;
          const Tensor<1, 3> backward = (p.normal - minus.normal) / h;
          dn_dt[a] = 0.5 * (forward + backward);
          smooth = (forward - backward).norm() <= 0.1 * dn_dt[a].norm() + 1e-12;
          curved = curved || dn_dt[a].norm() >= 1e-12;
        }
        if (!smooth || !curved)
          continue;
        Tensor<2, 3> T = unit_symmetric_tensor<3>();
        const auto  &transforms = contact.row_transforms();
        const auto   it = transforms.find(node_dofs[0]);
        if (it != transforms.end())
          T = it->second.matrix;
        const Tensor<2, 3> term = node_term_3d(p.normal, dn_dt, p.tangents, k, r, T);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            if (i != k && j != k && term[i][j] != 0.)
              matrix.add(node_dofs[i], node_dofs[j], term[i][j]);
        ++n_terms;
      }
    }
    matrix.compress(VectorOperation::add);
    return n_terms;
  }

  template class CurvatureTangent<2>;
  template class CurvatureTangent<3>;
} // namespace ausroll::contact
