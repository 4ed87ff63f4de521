#include <ausroll/adaptivity/material_point_transfer.h>

#include <deal.II/base/geometry_info.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace ausroll::adaptivity
{
  using namespace dealii;
  using material::MaterialState;

  template <int dim>
  MaterialPointTransfer<dim>::MaterialPointTransfer(
      parallel::distributed::Triangulation<dim> &triangulation,
      mechanics::MaterialPointStorage<dim>      &storage,
      const Quadrature<dim>                     &quadrature,
      const TransferMethod                       method,
      std::function<void(MaterialState &)>       make_admissible)
      : triangulation(triangulation)
      , storage(storage)
      , quadrature(quadrature)
      , method(method)
      , make_admissible(std::move(make_admissible))
  {
    const unsigned int n_q = quadrature.size();
    const unsigned int n_children = GeometryInfo<dim>::max_children_per_cell;
    const unsigned int n_1d
        = static_cast<unsigned int>(std::lround(std::pow(double(n_q), 1. / dim)));
    const mechanics::QuadratureInterpolation<dim> lagrange(n_1d);

    prolongation.assign(n_children, FullMatrix<double>(n_q, n_q));
    restriction.reinit(n_q, n_children * n_q);
    if (method == TransferMethod::polynomial)
    {
      // Prolongation: the parent's Lagrange polynomial at the children's points.
      FullMatrix<double> phi(n_children * n_q, n_q);
      for (unsigned int c = 0; c < n_children; ++c)
        for (unsigned int q = 0; q < n_q; ++q)
        {
          const std::vector<double> w = lagrange.weights(
              GeometryInfo<dim>::child_to_cell_coordinates(quadrature.point(q), c));
          for (unsigned int p = 0; p < n_q; ++p)
            prolongation[c](q, p) = phi(c * n_q + q, p) = w[p];
        }
      // Restriction: least-squares fit of the children's values, (Phi^T Phi)^-1 Phi^T.
      FullMatrix<double> normal(n_q, n_q);
      phi.Tmmult(normal, phi);
      normal.gauss_jordan();
      normal.mTmult(restriction, phi);
    }
    else
      for (unsigned int c = 0; c < n_children; ++c)
        for (unsigned int q = 0; q < n_q; ++q)
        {
          // nearest parent point
          const Point<dim> x = GeometryInfo<dim>::child_to_cell_coordinates(quadrature.point(q), c);
          unsigned int     nearest = 0;
          for (unsigned int p = 1; p < n_q; ++p)
            if (x.distance(quadrature.point(p)) < x.distance(quadrature.point(nearest)))
              nearest = p;
          prolongation[c](q, nearest) = 1.;
          // average of the child that holds parent point q
          if (GeometryInfo<dim>::child_cell_from_point(quadrature.point(q)) == c)
            for (unsigned int k = 0; k < n_q; ++k)
              restriction(q, c * n_q + k) = 1. / n_q;
        }
  }

  template <int dim>
  std::vector<char>
  MaterialPointTransfer<dim>::pack(const typename Triangulation<dim>::cell_iterator &cell,
                                   const typename Triangulation<dim>::CellStatus     status) const
  {
    const unsigned int  n_q = quadrature.size();
    const unsigned int  m = MaterialState::n_packed_values;
    std::vector<double> values;
    values.reserve(n_q * m);
    if (status == Triangulation<dim>::CELL_COARSEN)
    {
      // The children still exist: restrict their points to the parent's points now.
      std::vector<double> children;
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        for (const auto &point : storage.get_data(cell->child(c)))
          point->committed.pack(children);
      for (unsigned int q = 0; q < n_q; ++q)
      {
        std::vector<double> v(m, 0.);
        for (unsigned int j = 0; j < restriction.n(); ++j)
          if (restriction(q, j) != 0.)
            for (unsigned int k = 0; k < m; ++k)
              v[k] += restriction(q, j) * children[j * m + k];
        MaterialState state;
        state.unpack(v.data());
        if (method == TransferMethod::polynomial && make_admissible)
          make_admissible(state);
        state.pack(values);
      }
    }
    else
      for (const auto &point : storage.get_data(cell))
        point->committed.pack(values);

    std::vector<char> buffer(values.size() * sizeof(double));
    std::memcpy(buffer.data(), values.data(), buffer.size());
    return buffer;
  }

  template <int dim>
  MaterialState MaterialPointTransfer<dim>::child_state(const std::vector<double> &parent_values,
                                                        const unsigned int         c,
                                                        const unsigned int         q) const
  {
    const unsigned int  m = MaterialState::n_packed_values;
    std::vector<double> v(m, 0.);
    for (unsigned int p = 0; p < quadrature.size(); ++p)
      if (prolongation[c](q, p) != 0.)
        for (unsigned int k = 0; k < m; ++k)
          v[k] += prolongation[c](q, p) * parent_values[p * m + k];
    MaterialState state;
    state.unpack(v.data());
    if (method == TransferMethod::polynomial && make_admissible)
      make_admissible(state);
    return state;
  }

  template <int dim>
  void MaterialPointTransfer<dim>::prepare()
  {
    handle = triangulation.register_data_attach(
        [this](const typename Triangulation<dim>::cell_iterator &cell,
               const typename Triangulation<dim>::CellStatus status) { return pack(cell, status); },
        /*returns_variable_size_data=*/false);
  }

  template <int dim>
  void MaterialPointTransfer<dim>::unpack()
  {
    const unsigned int n_q = quadrature.size();
    storage.clear();
    storage.initialize(triangulation.begin_active(), triangulation.end(), n_q);

    triangulation.notify_ready_to_unpack(
        handle,
        [this, n_q](const typename Triangulation<dim>::cell_iterator               &cell,
                    const typename Triangulation<dim>::CellStatus                   status,
                    const boost::iterator_range<std::vector<char>::const_iterator> &data)
        {
          std::vector<double> values(n_q * MaterialState::n_packed_values);
          std::memcpy(values.data(), &*data.begin(), values.size() * sizeof(double));
          if (status == Triangulation<dim>::CELL_REFINE)
          {
            for (unsigned int c = 0; c < cell->n_children(); ++c)
              if (cell->child(c)->is_locally_owned())
              {
                const auto points = storage.get_data(cell->child(c));
                for (unsigned int q = 0; q < n_q; ++q)
                {
                  points[q]->committed = child_state(values, c, q);
                  points[q]->trial = points[q]->committed;
                }
              }
          }
          else if (cell->is_locally_owned())
          {
            const auto points = storage.get_data(cell);
            for (unsigned int q = 0; q < n_q; ++q)
            {
              points[q]->committed.unpack(values.data() + q * MaterialState::n_packed_values);
              points[q]->trial = points[q]->committed;
            }
          }
        });
    handle = numbers::invalid_unsigned_int;
  }

  template class MaterialPointTransfer<2>;
  template class MaterialPointTransfer<3>;
} // namespace ausroll::adaptivity
