/**
 * @file contact_operator.cc
 * ContactOperator: the contact nodes (setup), their projection on the dies at an iterate, the
 * gaps and die checks of the whole workpiece. The status rules are in contact_statuses.cc;
 * constraints, reactions, forces, output and the packed state in contact_constraints.cc.
 */
#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/tangential_components.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/gather_rows.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace ausroll::contact
{
  using namespace dealii;

  namespace
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();
  } // namespace

  template <int dim>
  ContactOperator<dim>::ContactOperator(const ContactParameters &parameters,
                                        const FrictionContext   &friction)
      : parameters(parameters)
      , tangents(create_tangent_terms<dim>(parameters))
  {
    for (unsigned int k = 0; k < parameters.dies.size(); ++k)
      dies.push_back(std::make_unique<RigidDie<dim>>(parameters.dies[k], k, friction));
  }

  template <int dim>
  void ContactOperator<dim>::setup(const DoFHandler<dim>                           &dof_handler,
                                   const Mapping<dim>                              &mapping,
                                   const std::function<double(const Point<dim> &)> &volume_factor,
                                   const double                                     length_scale)
  {
    nodes.clear();
    transforms.clear();
    gap_tolerance = 1e-9 * length_scale;
    smallest_cell = length_scale;
    slip_length = 1e-2 * length_scale;
    // 2D: a reversal of the arc length beyond the gap tolerance (as before); 3D: beyond 1e-5 of
    // the length scale, so that the direction noise of a slip much shorter than slip_length (the
    // small sub-steps of the load-increment ratio) does not stick a node that keeps sliding
    reversal_tolerance = dim == 2 ? gap_tolerance : 1e-3 * slip_length;
    if (!active())
      return;
    for (const auto &term : tangents)
      term->setup(mapping, dof_handler);

    const FiniteElement<dim> &fe = dof_handler.get_fe();
    const Quadrature<dim - 1> support(fe.get_unit_face_support_points());
    FEFaceValues<dim>         support_values(mapping, fe, support, update_quadrature_points);
    const QGauss<dim - 1>     gauss(fe.degree + 1);
    FEFaceValues<dim>         area_values(
        mapping, fe, gauss, update_values | update_quadrature_points | update_JxW_values);
    const IndexSet &owned = dof_handler.locally_owned_dofs();

    std::unordered_map<types::global_dof_index, unsigned int> index_of;
    std::vector<types::global_dof_index>                      face_dofs(fe.n_dofs_per_face());

    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (cell->is_artificial())
        continue;
      for (const auto f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary())
          continue;
        const unsigned int        id = cell->face(f)->boundary_id();
        std::vector<unsigned int> candidate_dies;
        for (unsigned int k = 0; k < dies.size(); ++k)
          if (dies[k]->is_candidate(id))
            candidate_dies.push_back(k);
        if (candidate_dies.empty())
          continue;

        cell->face(f)->get_dof_indices(face_dofs);
        support_values.reinit(cell, f);
        area_values.reinit(cell, f);
        // group the face DoFs by support point
        std::map<unsigned int, std::array<unsigned int, dim>> by_point;
        for (unsigned int i = 0; i < face_dofs.size(); ++i)
        {
          const auto ci = fe.face_system_to_component_index(i);
          by_point[ci.second][ci.first] = i;
        }
        for (const auto &[point, local] : by_point)
        {
          const types::global_dof_index key = face_dofs[local[0]];
          auto                          it = index_of.find(key);
          if (it == index_of.end())
          {
            Node n;
            for (unsigned int c = 0; c < dim; ++c)
              n.dofs[c] = face_dofs[local[c]];
            n.X = support_values.quadrature_point(local[0]);
            n.x = n.X;
            n.owned = owned.is_element(key);
            it = index_of.emplace(key, nodes.size()).first;
            nodes.push_back(n);
          }
          Node &n = nodes[it->second];
          for (const unsigned int k : candidate_dies)
            if (std::find(n.dies.begin(), n.dies.end(), k) == n.dies.end())
              n.dies.push_back(k);
          // tributary area: integral of the nodal shape function over the face
          if (cell->is_locally_owned())
            for (unsigned int q = 0; q < gauss.size(); ++q)
              n.area += area_values.shape_value_component(fe.face_to_cell_index(local[0], f), q, 0)
                        * area_values.JxW(q) * volume_factor(area_values.quadrature_point(q));
        }
      }
    }
    // The area of a node shared by cells of different ranks: sum over ranks (owned nodes only need
    // it). Each face is integrated by the rank owning its cell; gather the contributions.
    std::map<types::global_dof_index, double> partial;
    for (const Node &n : nodes)
      if (n.area != 0.)
        partial[n.dofs[0]] = n.area;
    comm = dof_handler.get_communicator();
    const auto gathered = Utilities::MPI::all_gather(comm, partial);
    double     largest_area = 0.;
    for (Node &n : nodes)
    {
      n.area = 0.;
      for (const auto &part : gathered)
      {
        const auto it = part.find(n.dofs[0]);
        if (it != part.end())
          n.area += it->second;
      }
      largest_area = std::max(largest_area, n.area);
    }
    // Nodes on the axis of an axisymmetric model carry no area (2 pi r = 0; exactly 0 for the
    // vertex of a quadratic face): report no pressure there instead of round-off / 0.
    area_floor = 1e-10 * Utilities::MPI::max(largest_area, comm);
  }

  template <int dim>
  unsigned int ContactOperator<dim>::close_penetrating_nodes(const TrilinosWrappers::MPI::Vector &u)
  {
    update_geometry(u, true);
    unsigned int closed = 0;
    for (const Node &n : nodes)
      if (n.owned && n.fresh && n.current.status != ContactStatus::open)
        ++closed;
    return Utilities::MPI::sum(closed, comm);
  }

  template <int dim>
  void ContactOperator<dim>::start_iterate()
  {
    for (Node &n : nodes)
      n.fresh = false;
  }

  template <int dim>
  unsigned int ContactOperator<dim>::update_geometry(const TrilinosWrappers::MPI::Vector &u,
                                                     const bool allow_closing,
                                                     const bool only_unchanged_nodes)
  {
    unsigned int closed = 0;
    for (Node &n : nodes)
    {
      for (unsigned int c = 0; c < dim; ++c)
        n.x[c] = n.X[c] + u[n.dofs[c]];
      if (n.current.status != ContactStatus::open)
        n.projection = dies[n.current.die]->project(n.x, time);
      else
      {
        n.projection = DieProjection<dim>();
        n.current.die = -1;
        for (const unsigned int k : n.dies)
        {
          const DieProjection<dim> p = dies[k]->project(n.x, time);
          if (p.valid && (!n.projection.valid || p.gap < n.projection.gap))
          {
            n.projection = p;
            n.current.die = k;
          }
        }
        // A node that has used up its status changes (`Maximum status changes`) still closes
        // when it penetrates, and then stays closed (update_statuses() no longer judges it):
        // frozen open, a node chattering at the edge of a curved punch's contact could end the
        // step inside the die (doc/scenes/hard_cases.md, issue 17).
        if (allow_closing && !n.fresh && (!only_unchanged_nodes || n.changes == 0)
            && n.projection.valid
            && n.projection.gap < (n.changes == 0 ? gap_tolerance : -gap_tolerance))
          switch_status(n, closing_status(n));
      }
      // 3D: the direction follows the slip at every iterate, with its derivative in the tangent
      // (SlipDirectionTangent); nested active set: from its first turn at a converged
      // state on (update_statuses()), held before
      n.turned = false;
      n.followed_slip = 0.;
      if constexpr (dim == 3)
        if (n.current.status == ContactStatus::slip)
        {
          n.turned = update_slip_direction(n, !hold_changed || n.follow) > direction_tolerance;
        }
      if (n.current.status != ContactStatus::open)
        ++closed;
    }
    build_row_transforms();
    return closed;
  }

  template <int dim>
  double ContactOperator<dim>::unlimited_gap(const unsigned int k,
                                             const Point<dim>  &x,
                                             const double       t) const
  {
    // no search-distance limit here: adaptivity and the die checks look at the whole workpiece
    if constexpr (dim == 2)
    {
      const SurfaceProjection<2> p = dies[k]->die_surface().project(dies[k]->pose(t).to_local(x));
      return p.valid ? p.gap : infinity;
    }
    else
    {
      const SurfaceProjection<dim> p = dies[k]->surface().project(dies[k]->pose(t).to_local(x));
      return p.valid ? p.gap : infinity;
    }
  }

  template <int dim>
  double ContactOperator<dim>::die_coordinate_difference(const unsigned int die,
                                                         const double       s1,
                                                         const double       s0) const
  {
    double       d = s1 - s0;
    const double L = dies[die]->surface().coordinate_periods()[0];
    if (L > 0.)
    {
      if (d > 0.5 * L)
        d -= L;
      else if (d < -0.5 * L)
        d += L;
    }
    return d;
  }

  template <int dim>
  double ContactOperator<dim>::distance_to_dies(const Point<dim> &x, const double t) const
  {
    double distance = infinity;
    for (unsigned int k = 0; k < dies.size(); ++k)
      distance = std::min(distance, std::abs(unlimited_gap(k, x, t)));
    return distance;
  }

  template <int dim>
  void ContactOperator<dim>::check_dies(const std::vector<double> &times,
                                        const double               workpiece_size) const
  {
    for (unsigned int k = 0; k < dies.size(); ++k)
    {
      const std::string   path = "Contact/Die " + std::to_string(k) + " (" + dies[k]->name + ")";
      unsigned int        n_candidates = 0;
      double              deepest = infinity, nearest = infinity;
      Point<dim>          deepest_node;
      std::vector<double> nearest_at(times.size(), infinity); // over the nodes, per time
      for (const Node &n : nodes)
        if (n.owned && std::find(n.dies.begin(), n.dies.end(), k) != n.dies.end())
        {
          ++n_candidates;
          const double g0 = unlimited_gap(k, n.X, times.front());
          if (g0 < deepest)
          {
            deepest = g0;
            deepest_node = n.X;
          }
          for (unsigned int i = 0; i < times.size(); ++i)
          {
            const double g = unlimited_gap(k, n.X, times[i]);
            nearest = std::min(nearest, g);
            nearest_at[i] = std::min(nearest_at[i], g);
          }
        }
      if (Utilities::MPI::sum(n_candidates, comm) == 0)
        throw InputError(path
                         + "/Candidate boundaries: no workpiece boundary node carries these ids");
      const double global_deepest = Utilities::MPI::min(deepest, comm);
      if (global_deepest < -0.05 * workpiece_size)
      {
        std::ostringstream msg;
        msg << path << ": the undeformed workpiece starts " << -global_deepest
            << " mm inside the die; check its Normal / Material inside / position and Motion";
        throw InputError(msg.str());
      }
      // A shallower overlap is no flipped normal, but the first step would have to push the
      // nodes out by more than a tenth of a cell at once: Newton fails and blames convergence.
      if (global_deepest < -0.1 * smallest_cell)
      {
        std::ostringstream msg;
        msg << path << ": the undeformed workpiece starts " << -global_deepest
            << " mm inside the die at t = " << times.front()
            << " (more than a tenth of the smallest cell, " << smallest_cell
            << " mm; the first step cannot push it out); move the die back by that much in its "
               "position or Motion, or start with a gap";
        throw InputError(msg.str());
      }
      if (Utilities::MPI::min(nearest, comm) > 0.25 * workpiece_size)
      {
        std::ostringstream msg;
        msg << path << " never comes within " << 0.25 * workpiece_size
            << " mm of the workpiece during the run; check its position and Motion";
        throw InputError(msg.str());
      }
      // Near at the start but only moving away: it never touches either.
      Utilities::MPI::min(nearest_at, comm, nearest_at);
      const double start = nearest_at.front(), touch = 1e-6 * workpiece_size;
      if (start > touch && Utilities::MPI::min(nearest, comm) >= start - touch
          && nearest_at.back() > start + touch)
      {
        std::ostringstream msg;
        msg << path << " never comes within " << start
            << " mm of the workpiece during the run: it starts that far away and moves away (to "
            << nearest_at.back() << " mm); check the sign of its Motion";
        throw InputError(msg.str());
      }
      (void)deepest_node;
    }
  }

  template class ContactOperator<2>;
  template class ContactOperator<3>;
} // namespace ausroll::contact
