#include <ausroll/contact/contact_operator.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/gather_rows.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace ausroll::contact
{
  using namespace dealii;

  namespace
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();

    /** Magnitude of tangential components (2D: |R_t| as before; 3D: the Euclidean norm). */
    template <std::size_t n>
    double magnitude(const std::array<double, n> &v)
    {
      if constexpr (n == 1)
        return std::abs(v[0]);
      else
      {
        double sum = 0.;
        for (const double x : v)
          sum += x * x;
        return std::sqrt(sum);
      }
    }
  } // namespace

  template <int dim>
  ContactOperator<dim>::ContactOperator(const ContactParameters &parameters,
                                        const FrictionContext   &friction)
      : parameters(parameters)
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
      // (add_slip_direction_tangent()); nested active set: from its first turn at a converged
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
  unsigned int ContactOperator<dim>::add_slip_direction_tangent(
      [[maybe_unused]] const AffineConstraints<double> &constraints,
      TrilinosWrappers::SparseMatrix                   &matrix,
      TrilinosWrappers::MPI::Vector                    &rhs) const
  {
    unsigned int n_terms = 0;
    if constexpr (dim == 3)
    {
      FullMatrix<double>                   block(dim, dim);
      dealii::Vector<double>               zero(dim);
      std::vector<types::global_dof_index> dofs(dim);
      for (const Node &n : nodes)
      {
        if (!n.owned || n.current.status != ContactStatus::slip || n.followed_slip <= 0.
            || !dies[n.current.die]->friction->switches_stick_slip())
          continue;
        // d(T d)/dx = T (P - d (x) d) / |s|, T the slip limit at this assembly's normal force
        const double T
            = dies[n.current.die]->friction->slip_limit(n.current.Rn, n.area).value(n.current.Rn);
        const Tensor<1, dim>  d = slip_vector(n);
        const Tensor<1, dim> &normal = n.projection.normal;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            block(i, j)
                = T / n.followed_slip * ((i == j ? 1. : 0.) - normal[i] * normal[j] - d[i] * d[j]);
        for (unsigned int c = 0; c < dim; ++c)
          dofs[c] = n.dofs[c];
        zero = 0.;
        constraints.distribute_local_to_global(block, zero, dofs, matrix, rhs, true);
        ++n_terms;
      }
    }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    return Utilities::MPI::sum(n_terms, comm);
  }

  template <int dim>
  ContactStatus ContactOperator<dim>::closing_status(const Node &n) const
  {
    return dies[n.current.die]->friction->sticks_when_closing() ? ContactStatus::stick
                                                                : ContactStatus::slip;
  }

  template <int dim>
  void ContactOperator<dim>::switch_status(Node &n, const ContactStatus status)
  {
    if (status == n.current.status)
      return;
    ++n.changes;
    // Nested active set: a node that changed at this state is judged again only after the
    // equations have been solved with its new constraint.
    n.fresh = hold_changed;
    if (status == ContactStatus::stick)
    {
      // A node that stops slipping sticks where its slip started (no relative motion over the
      // step); a node that closes sticks where it meets the die.
      if (n.current.status != ContactStatus::slip)
        n.current.stick = n.projection.local_point;
      else if constexpr (dim == 2)
        n.current.stick = dies[n.current.die]->die_surface().point_at(n.current.s);
      else
        n.current.stick = n.current.start;
    }
    if (status == ContactStatus::slip)
    {
      // direction of the slip: opposite to the tangential force (3D: -R_T / |R_T|, the radial
      // return onto the isotropic cone)
      if constexpr (dim == 2)
        n.current.direction[0] = n.current.Rt[0] > 0. ? -1 : (n.current.Rt[0] < 0. ? 1 : 0);
      else
      {
        const double size = magnitude(n.current.Rt);
        for (unsigned int a = 0; a < dim - 1; ++a)
          n.current.direction[a] = size > 0. ? -n.current.Rt[a] / size : 0.;
      }
      if constexpr (dim == 2)
        n.current.s = n.current.status == ContactStatus::stick
                          ? dies[n.current.die]->die_surface().project(n.current.stick).s
                          : n.projection.s;
      else
      {
        n.current.start
            = n.current.status == ContactStatus::stick ? n.current.stick : n.projection.local_point;
        n.current.s = n.projection.s;
      }
    }
    if (status == ContactStatus::open)
      n.current.direction = {};
    n.direction_pending = false;
    n.follow = false;
    n.current.status = status;
  }

  template <int dim>
  std::array<double, dim - 1> ContactOperator<dim>::slip_increment(const Node &n) const
  {
    // the die-relative displacement of the contact point since the slip started, in the global
    // frame of the current pose, resolved along the current tangents
    const Tensor<1, dim> slip = dies[n.current.die]->pose(time).rotate_vector_to_global(
        n.projection.local_point - n.current.start);
    std::array<double, dim - 1> components;
    for (unsigned int a = 0; a < dim - 1; ++a)
      components[a] = slip * n.projection.tangents[a];
    return components;
  }

  template <int dim>
  double ContactOperator<dim>::update_slip_direction(Node &n, const bool follow_slip) const
  {
    // The friction force opposes the slip of the node over the step so far (backward Euler in
    // the direction: d = slip / |slip|) once that slip is well defined, i.e. larger than
    // slip_length; a smaller slip keeps the direction it had (from the tangential force when the
    // node began to slip, or from the previous step), as the 2D sign is kept.
    if (n.direction_pending)
    {
      n.current.direction = n.next_direction;
      n.direction_pending = false;
    }
    if (!follow_slip)
      return 0.;
    const std::array<double, dim - 1> slip = slip_increment(n);
    const double                      size = magnitude(slip);
    if (size <= slip_length)
      return 0.;
    n.followed_slip = size;
    double change = 0.;
    for (unsigned int a = 0; a < dim - 1; ++a)
    {
      change = std::max(change, std::abs(slip[a] / size - n.current.direction[a]));
      n.current.direction[a] = slip[a] / size;
    }
    return change;
  }

  template <int dim>
  double ContactOperator<dim>::slip_along_direction(const Node &n) const
  {
    if constexpr (dim == 2)
      return n.current.direction[0]
             * die_coordinate_difference(n.current.die, n.projection.s, n.current.s);
    else
    {
      const std::array<double, dim - 1> slip = slip_increment(n);
      double                            along = 0.;
      for (unsigned int a = 0; a < dim - 1; ++a)
        along += n.current.direction[a] * slip[a];
      return along;
    }
  }

  template <int dim>
  Tensor<1, dim> ContactOperator<dim>::slip_vector(const Node &n) const
  {
    Tensor<1, dim> d;
    for (unsigned int a = 0; a < dim - 1; ++a)
      d += n.current.direction[a] * n.projection.tangents[a];
    return d;
  }

  template <int dim>
  double ContactOperator<dim>::unlimited_gap(const unsigned int k,
                                             const Point<dim>  &x,
                                             const double       t) const
  {
    // no search-distance limit here: adaptivity and the die checks look at the whole workpiece
    if constexpr (dim == 2)
    {
      const Projection p = dies[k]->die_surface().project(dies[k]->pose(t).to_local(x));
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
  void ContactOperator<dim>::build_row_transforms()
  {
    transforms.clear();
    // A slipping node's tangential equation becomes t.r + s T(n.r) = 0 (s the slip sign, T the
    // slip limit of the friction law, affine near the current state: T = T(0) + T' R_n), i.e.
    // rows <- (I + s T' t (x) n) rows + s T(0) t: Coulomb I + mu s t (x) n, Tresca an offset.
    // 3D: s t is the slip direction vector d = d_1 t_1 + d_2 t_2 of the tangent plane, and the
    // two tangential equations become r_T + T(n.r) d = 0 (isotropic cone, force along -d).
    for (const Node &n : nodes)
      if (n.current.status == ContactStatus::slip
          && dies[n.current.die]->friction->switches_stick_slip()
          && magnitude(n.current.direction) != 0.)
      {
        NodalRowTransform<dim> t;
        t.dofs = n.dofs;
        const SlipLimit limit = dies[n.current.die]->friction->slip_limit(n.current.Rn, n.area);
        const Tensor<1, dim> d = slip_vector(n);
        for (unsigned int i = 0; i < dim; ++i)
        {
          for (unsigned int j = 0; j < dim; ++j)
            t.matrix[i][j] = (i == j ? 1. : 0.) + limit.slope * d[i] * n.projection.normal[j];
          t.offset[i] = limit.intercept * d[i];
        }
        transforms.emplace(n.dofs[0], t);
      }
  }

  template <int dim>
  double ContactOperator<dim>::add_constraints(const TrilinosWrappers::MPI::Vector &u,
                                               AffineConstraints<double> &constraints) const
  {
    (void)u;
    double violation = 0.;
    for (const Node &n : nodes)
    {
      for (unsigned int c = 0; c < dim; ++c)
        n.fixed[c] = constraints.is_constrained(n.dofs[c]);
      if (n.current.status == ContactStatus::stick)
      {
        const Point<dim> target = dies[n.current.die]->material_point(n.current.stick, time);
        for (unsigned int c = 0; c < dim; ++c)
          if (!constraints.is_constrained(n.dofs[c]))
          {
            constraints.add_line(n.dofs[c]);
            constraints.set_inhomogeneity(n.dofs[c], target[c] - n.x[c]);
            if (n.owned)
              violation = std::max(violation, std::abs(target[c] - n.x[c]));
          }
      }
      else if (n.current.status == ContactStatus::slip && dim == 3)
      {
        // n . delta u = -gap on the free component k with the largest |n_k|:
        // u_k = (-gap - sum_{j != k} n_j u_j) / n_k
        const Tensor<1, dim> &normal = n.projection.normal;
        int                   k = -1;
        for (unsigned int c = 0; c < dim; ++c)
          if (!constraints.is_constrained(n.dofs[c])
              && (k < 0 || std::abs(normal[c]) > std::abs(normal[k])))
            k = c;
        if (k < 0 || std::abs(normal[k]) < 1e-12)
          continue;
        constraints.add_line(n.dofs[k]);
        for (unsigned int j = 0; j < dim; ++j)
          if (j != static_cast<unsigned int>(k))
            constraints.add_entry(n.dofs[k], n.dofs[j], -normal[j] / normal[k]);
        constraints.set_inhomogeneity(n.dofs[k], -n.projection.gap / normal[k]);
        if (n.owned)
          violation = std::max(violation, std::abs(n.projection.gap));
      }
      else if (n.current.status == ContactStatus::slip)
      {
        const Tensor<1, dim> &normal = n.projection.normal;
        // constrain the component with the larger normal entry that is still free
        const unsigned int first = std::abs(normal[0]) >= std::abs(normal[1]) ? 0 : 1;
        unsigned int       k = first;
        if (constraints.is_constrained(n.dofs[k]))
          k = 1 - first;
        if (constraints.is_constrained(n.dofs[k]) || std::abs(normal[k]) < 1e-12)
          continue;
        const unsigned int j = 1 - k;
        constraints.add_line(n.dofs[k]);
        constraints.add_entry(n.dofs[k], n.dofs[j], -normal[j] / normal[k]);
        constraints.set_inhomogeneity(n.dofs[k], -n.projection.gap / normal[k]);
        if (n.owned)
          violation = std::max(violation, std::abs(n.projection.gap));
      }
    }
    return violation;
  }

  template <int dim>
  void ContactOperator<dim>::compute_reactions(const TrilinosWrappers::MPI::Vector &residual)
  {
    double largest = 0.;
    for (Node &n : nodes)
    {
      for (unsigned int c = 0; c < dim; ++c)
        n.R[c] = residual[n.dofs[c]];
      if (n.current.status != ContactStatus::open || n.projection.valid)
      {
        n.current.Rn = n.R * n.projection.normal;
        Tensor<1, dim> R_tangential = n.R;
        if constexpr (dim == 3)
          for (unsigned int c = 0; c < dim; ++c)
            if (n.fixed[c])
              R_tangential[c] = 0.;
        for (unsigned int a = 0; a < dim - 1; ++a)
          n.current.Rt[a] = R_tangential * n.projection.tangents[a];
      }
      else
      {
        n.current.Rn = 0.;
        n.current.Rt = {};
      }
      if (n.current.status != ContactStatus::open)
        largest = std::max(largest, n.R.norm());
    }
    // Forces below this are round-off (the residual of the free equations is ~1e-10 of them).
    force_tolerance = 1e-8 * Utilities::MPI::max(largest, comm);
  }

  template <int dim>
  unsigned int ContactOperator<dim>::update_statuses()
  {
    unsigned int changes = 0;
    for (Node &n : nodes)
    {
      if (n.current.status == ContactStatus::open || n.fresh
          || n.changes >= parameters.max_status_changes)
        continue;
      const FrictionLaw &friction = *dies[n.current.die]->friction;
      ContactStatus      target = n.current.status;
      // 3D: a sticking node whose tangential force leaves the cone slips first, even if the
      // same (unsolved) reaction is tensile: the tension of a stick constraint dragged by a large
      // die step is often an artefact of the drag; the next iterate decides about opening.
      if (dim == 3 && n.current.status == ContactStatus::stick && n.current.Rn < -force_tolerance
          && friction.switches_stick_slip()
          && magnitude(n.current.Rt)
                 > std::abs(friction.slip_limit(0., n.area).value(0.)) + force_tolerance)
        target = ContactStatus::slip;
      else if (n.current.Rn < -force_tolerance)
        target = ContactStatus::open;
      else if (n.current.status == ContactStatus::stick
               && friction
                      .respond(n.current.Rn,
                               dim == 2 ? n.current.Rt[0] : magnitude(n.current.Rt),
                               n.area,
                               force_tolerance)
                      .slip)
        target = ContactStatus::slip;
      else if (n.current.status == ContactStatus::slip && friction.switches_stick_slip()
               && slip_along_direction(n) < -reversal_tolerance)
        target = ContactStatus::stick;
      if (target != n.current.status)
      {
        switch_status(n, target);
        if (n.owned)
          ++changes;
      }
      else if constexpr (dim == 3)
      {
        // Nested active set: the slip direction of a node is held during its first Newton pass
        // of the step (the friction force -T d a fixed-direction load, as the slip sign in 2D)
        // and follows the slip here, at the converged state; a turn is a change like a status
        // change (one more pass, counted against `Maximum status changes`), and from then on the
        // direction follows the slip at every iterate with its derivative in the tangent
        // (add_slip_direction_tangent(): Newton converges quadratically in the direction too),
        // so a node turns here at most once per step and the converged state has d = s / |s|
        // exactly (n.turned: a turn between the last assembly and this state). Held direction
        // in every pass (the rule before): the direction converged as a fixed point over 4-8
        // passes per step on the flat die's side-face edge. Following from the first iterate:
        // the slip of the first iterates of a large step is far from the converged one and the
        // direction flips (line searches, a cutback on the flat die's first rolling step).
        if (hold_changed && n.current.status == ContactStatus::slip
            && friction.switches_stick_slip()
            && (n.follow ? n.turned : update_slip_direction(n, true) > direction_tolerance))
        {
          ++n.changes;
          n.fresh = true;
          n.follow = true;
          if (n.owned)
            ++changes;
        }
      }
    }
    build_row_transforms();
    return Utilities::MPI::sum(changes, comm);
  }

  template <int dim>
  typename ContactOperator<dim>::Event ContactOperator<dim>::node_event(const Node &n) const
  {
    // Linear interpolation between the committed state (fraction 0) and the iterate (fraction 1)
    // (NOFEAP Appendix A); an event counts only when the quantity moves towards its threshold.
    Event event;
    if (n.changes >= parameters.max_status_changes)
      return event;
    if (n.current.status == ContactStatus::open)
    {
      if (!n.projection.valid)
        return event;
      const double g1 = n.projection.gap;
      event.target = closing_status(n);
      if (n.committed_gap_valid && n.committed.die == n.current.die && n.committed_gap >= 0.
          && g1 < n.committed_gap)
        event.alpha = n.committed_gap / (n.committed_gap - g1); // open -> closed: the gap closes
      else if (g1 < -gap_tolerance)
        event.alpha = 0.; // penetrating without a history: close at once
      return event;
    }

    const FrictionLaw &friction = *dies[n.current.die]->friction;
    const double       dRn = n.current.Rn - n.committed.Rn;
    // closed -> open: the normal force becomes tensile
    if (dRn < 0. && n.committed.Rn >= 0.)
      event = Event{n.committed.Rn / -dRn, ContactStatus::open};
    else if (n.current.Rn < -force_tolerance)
      event = Event{0., ContactStatus::open};
    if (!friction.switches_stick_slip())
      return event;
    if (n.current.status == ContactStatus::stick)
    {
      // stick -> slip: s . R_t reaches the slip limit T(R_n) (s = direction of the final
      // tangential force: 2D its sign, 3D the unit vector R_t / |R_t|); f = s . R_t - T(R_n) is
      // linear in the step on one affine piece of T, else secant
      std::array<double, dim - 1> s;
      if constexpr (dim == 2)
        s[0] = n.current.Rt[0] >= 0. ? 1. : -1.;
      else
      {
        const double size = magnitude(n.current.Rt);
        for (unsigned int a = 0; a < dim - 1; ++a)
          s[a] = size > 0. ? n.current.Rt[a] / size : 0.;
      }
      double s_Rt0 = s[0] * n.committed.Rt[0], s_dRt = s[0] * (n.current.Rt[0] - n.committed.Rt[0]);
      for (unsigned int a = 1; a < dim - 1; ++a)
      {
        s_Rt0 += s[a] * n.committed.Rt[a];
        s_dRt += s[a] * (n.current.Rt[a] - n.committed.Rt[a]);
      }
      const SlipLimit l0 = friction.slip_limit(n.committed.Rn, n.area);
      const SlipLimit l1 = friction.slip_limit(n.current.Rn, n.area);
      const double    dT = l0.slope == l1.slope ? (l1.intercept - l0.intercept) + l1.slope * dRn
                                                : l1.value(n.current.Rn) - l0.value(n.committed.Rn);
      const double    f0 = s_Rt0 - l0.value(n.committed.Rn);
      const double    df = s_dRt - dT;
      if (df > 0.)
      {
        const double alpha = f0 >= 0. ? 0. : -f0 / df;
        if (alpha < event.alpha)
          event = Event{alpha, ContactStatus::slip};
      }
    }
    else if (slip_along_direction(n) < -reversal_tolerance)
      event = Event{0., ContactStatus::stick}; // slip reversal: switch at once (load factor zero)
    return event;
  }

  template <int dim>
  double ContactOperator<dim>::event_ratio() const
  {
    double alpha = 1.;
    for (const Node &n : nodes)
      if (n.owned)
        alpha = std::min(alpha, node_event(n).alpha);
    return Utilities::MPI::min(alpha, comm);
  }

  template <int dim>
  unsigned int ContactOperator<dim>::apply_events(const double alpha_limit)
  {
    unsigned int switched = 0;
    for (Node &n : nodes)
    {
      const Event event = node_event(n);
      if (event.alpha > alpha_limit)
        continue;
      switch_status(n, event.target);
      if (n.owned)
        ++switched;
    }
    build_row_transforms();
    return Utilities::MPI::sum(switched, comm);
  }

  template <int dim>
  void ContactOperator<dim>::commit(const bool new_step)
  {
    for (Node &n : nodes)
    {
      if constexpr (dim == 3)
        if (n.current.status == ContactStatus::slip)
        {
          // a slip shorter than slip_length sets the direction of the next step (applied at its
          // first projection: the forces of this converged state keep theirs)
          const std::array<double, dim - 1> slip = slip_increment(n);
          const double                      size = magnitude(slip);
          n.direction_pending = size > gap_tolerance;
          for (unsigned int a = 0; a < dim - 1; ++a)
            n.next_direction[a] = n.direction_pending ? slip[a] / size : 0.;
        }
      if (new_step)
        n.closed_in_last_step
            = n.committed.status == ContactStatus::open && n.current.status != ContactStatus::open;
      n.committed = n.current;
      // die coordinate and gap of the converged geometry; an open node carries no force
      n.committed.s = n.projection.s;
      n.committed.start = n.projection.local_point;
      n.committed_gap = n.projection.gap;
      n.committed_gap_valid = n.projection.valid;
      if (n.current.status == ContactStatus::open)
      {
        n.committed.Rn = 0.;
        n.committed.Rt = {};
      }
      n.changes = 0;
      n.follow = false;
      if (n.current.status == ContactStatus::slip)
      {
        n.current.s = n.projection.s;
        n.current.start = n.projection.local_point;
      }
    }
  }

  template <int dim>
  unsigned int ContactOperator<dim>::close_touching_nodes()
  {
    unsigned int closed = 0;
    for (Node &n : nodes)
      if (n.current.status == ContactStatus::open && n.projection.valid
          && n.projection.gap < gap_tolerance)
      {
        switch_status(n, closing_status(n));
        if (n.owned)
          ++closed;
      }
    build_row_transforms();
    return Utilities::MPI::sum(closed, comm);
  }

  template <int dim>
  void ContactOperator<dim>::promote_statuses()
  {
    for (Node &n : nodes)
    {
      // statuses of the current iterate, forces (and die coordinate unless slipping) of the
      // committed state
      const NodeState start = n.committed;
      n.committed = n.current;
      n.committed.Rn = start.Rn;
      n.committed.Rt = start.Rt;
      if (n.current.status != ContactStatus::slip)
      {
        n.committed.s = start.s;
        n.committed.start = start.start;
      }
    }
  }

  template <int dim>
  void ContactOperator<dim>::reset()
  {
    for (Node &n : nodes)
    {
      n.current = n.committed;
      n.changes = 0;
      n.follow = false;
    }
    build_row_transforms();
  }

  template <int dim>
  unsigned int ContactOperator<dim>::release_fresh_sticks()
  {
    // 2D only: a 3D slip needs its start point and direction of the converged geometry
    // (update_slip_direction()), which a reset after a failed solve does not restore.
    if constexpr (dim == 3)
      return 0;
    unsigned int switched = 0;
    for (Node &n : nodes)
      if (n.closed_in_last_step && n.changes < parameters.max_status_changes
          && n.current.status == ContactStatus::stick && n.current.Rn > 0.
          && magnitude(n.current.Rt) > 0. && dies[n.current.die]->friction->switches_stick_slip())
      {
        // after reset(): the committed reactions give the sign of the friction force
        switch_status(n, ContactStatus::slip);
        if (n.owned)
          ++switched;
      }
    build_row_transforms();
    return Utilities::MPI::sum(switched, comm);
  }

  template <int dim>
  typename ContactOperator<dim>::DieContact
  ContactOperator<dim>::die_contact(const unsigned int k) const
  {
    DieContact         result;
    Tensor<1, dim>     force;
    Tensor<1, 3>       moment;
    const DiePose<dim> pose = dies[k]->pose(time);
    unsigned int       n_stick = 0, n_slip = 0;
    double             s_min = infinity, s_max = -infinity;
    double             x_min = infinity, x_max = -infinity; // die-frame x of closed nodes
    for (const Node &n : nodes)
      if (n.owned && n.current.status != ContactStatus::open
          && n.current.die == static_cast<int>(k))
      {
        const Tensor<1, dim> f = contact_force(n);
        force += f;
        const Tensor<1, dim> arm = n.x - pose.reference_position();
        if constexpr (dim == 3)
          moment += cross_product_3d(arm, f);
        else
          moment[2] += arm[0] * f[1] - arm[1] * f[0];
        ++(n.current.status == ContactStatus::stick ? n_stick : n_slip);
        s_min = std::min(s_min, n.projection.s);
        s_max = std::max(s_max, n.projection.s);
        const double x_local = pose.to_local(n.x)[0];
        x_min = std::min(x_min, x_local);
        x_max = std::max(x_max, x_local);
      }
    for (unsigned int d = 0; d < dim; ++d)
      result.force[d] = Utilities::MPI::sum(force[d], comm);
    for (unsigned int d = 0; d < 3; ++d)
      result.moment[d] = Utilities::MPI::sum(moment[d], comm);
    result.n_stick = Utilities::MPI::sum(n_stick, comm);
    result.n_slip = Utilities::MPI::sum(n_slip, comm);
    s_min = Utilities::MPI::min(s_min, comm);
    s_max = Utilities::MPI::max(s_max, comm);
    result.contact_length = s_max >= s_min ? s_max - s_min : 0.;
    x_min = Utilities::MPI::min(x_min, comm);
    x_max = Utilities::MPI::max(x_max, comm);
    result.contact_width = x_max >= x_min ? x_max - x_min : 0.;
    return result;
  }

  template <int dim>
  Tensor<1, dim> ContactOperator<dim>::contact_force(const Node &n) const
  {
    // Normal part from the residual; tangential part from the residual when sticking, from the
    // friction law when slipping (so that a symmetry condition on the same node does not count).
    std::array<double, dim - 1> tangential = n.current.Rt;
    if (n.current.status == ContactStatus::slip)
    {
      const FrictionLaw &friction = *dies[n.current.die]->friction;
      const double       limit = friction.switches_stick_slip()
                                     ? friction.slip_limit(n.current.Rn, n.area).value(n.current.Rn)
                                     : 0.;
      for (unsigned int a = 0; a < dim - 1; ++a)
        tangential[a] = friction.switches_stick_slip() ? -n.current.direction[a] * limit : 0.;
    }
    Tensor<1, dim> f;
    for (unsigned int d = 0; d < dim; ++d)
    {
      f[d] = n.current.Rn * n.projection.normal[d] + tangential[0] * n.projection.tangents[0][d];
      for (unsigned int a = 1; a < dim - 1; ++a)
        f[d] += tangential[a] * n.projection.tangents[a][d];
    }
    return f;
  }

  template <int dim>
  void ContactOperator<dim>::write_csv(const std::string &filename, const MPI_Comm comm) const
  {
    // 2D: die,s,X,Y,x,y,gap,p_n,t_t,R_n,R_t,status;
    // 3D: die,s1,s2,X,Y,Z,x,y,z,gap,p_n,t_1,t_2,R_n,R_t1,R_t2,status (t_a, R_ta along the
    // die tangents)
    std::vector<std::vector<double>> rows;
    for (const Node &n : nodes)
      if (n.owned && n.current.die >= 0 && n.projection.valid)
      {
        const Tensor<1, dim> f = contact_force(n);
        std::vector<double>  row{double(n.current.die)};
        for (unsigned int a = 0; a < dim - 1; ++a)
          row.push_back(n.projection.coordinates[a]);
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(n.X[d]);
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(n.x[d]);
        row.push_back(n.projection.gap);
        row.push_back(n.area > area_floor ? n.current.Rn / n.area : 0.);
        for (unsigned int a = 0; a < dim - 1; ++a)
          row.push_back(n.area > area_floor ? (f * n.projection.tangents[a]) / n.area : 0.);
        row.push_back(n.current.Rn);
        for (unsigned int a = 0; a < dim - 1; ++a)
          row.push_back(f * n.projection.tangents[a]);
        row.push_back(double(static_cast<int>(n.current.status)));
        rows.push_back(row);
      }
    const std::vector<std::vector<double>> all = gather_sorted_rows(comm, rows);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream out(filename);
    // the time to the digits of history.csv, so that a checker can find the row of this file
    out << std::setprecision(10) << "# time = " << time;
    if constexpr (dim == 2)
      out << "; status: 0 open, 1 stick, 2 slip; p_n, t_t in MPa, R_n, R_t in N\n"
          << "die,s,X,Y,x,y,gap,p_n,t_t,R_n,R_t,status\n";
    else
      out << "; status: 0 open, 1 stick, 2 slip; p_n, t_1, t_2 in MPa, R_n, R_t1, R_t2 in N "
             "(along the die tangents)\n"
          << "die,s1,s2,X,Y,Z,x,y,z,gap,p_n,t_1,t_2,R_n,R_t1,R_t2,status\n";
    for (const auto &row : all)
    {
      out << dies[static_cast<unsigned int>(row[0])]->name;
      for (unsigned int k = 1; k < row.size(); ++k)
        out << ',' << row[k];
      out << '\n';
    }
  }

  template <int dim>
  void ContactOperator<dim>::fill_output_vectors(TrilinosWrappers::MPI::Vector &pressure_traction,
                                                 TrilinosWrappers::MPI::Vector &status_gap) const
  {
    pressure_traction = 0.;
    status_gap = 0.;
    for (const Node &n : nodes)
      if (n.owned && n.projection.valid)
      {
        if (n.area > area_floor)
        {
          pressure_traction[n.dofs[0]]
              = n.current.status == ContactStatus::open ? 0. : n.current.Rn / n.area;
          for (unsigned int a = 0; a < dim - 1; ++a)
            pressure_traction[n.dofs[a + 1]]
                = n.current.status == ContactStatus::open
                      ? 0.
                      : (contact_force(n) * n.projection.tangents[a]) / n.area;
        }
        status_gap[n.dofs[0]] = static_cast<int>(n.current.status);
        status_gap[n.dofs[1]] = n.projection.gap;
      }
    pressure_traction.compress(VectorOperation::insert);
    status_gap.compress(VectorOperation::insert);
  }

  template <int dim>
  std::pair<unsigned int, unsigned int> ContactOperator<dim>::n_stick_slip() const
  {
    unsigned int n_stick = 0, n_slip = 0;
    for (const Node &n : nodes)
      if (n.owned)
      {
        n_stick += n.current.status == ContactStatus::stick ? 1 : 0;
        n_slip += n.current.status == ContactStatus::slip ? 1 : 0;
      }
    return {Utilities::MPI::sum(n_stick, comm), Utilities::MPI::sum(n_slip, comm)};
  }

  template <int dim>
  unsigned int ContactOperator<dim>::n_changed_statuses() const
  {
    unsigned int changed = 0;
    for (const Node &n : nodes)
      if (n.owned && n.current.status != n.committed.status)
        ++changed;
    return Utilities::MPI::sum(changed, comm);
  }

  namespace
  {
    /** Doubles per node in pack_state(): 14 in 2D, 3D with the slip start point; the last one
        is Node::closed_in_last_step (checkpoints before 2026-12-02 had 13 in 2D). */
    template <int dim>
    constexpr unsigned int packed_node_size = 2 * dim + 2 * (dim - 1) + 8 + (dim == 3 ? dim : 0);
  } // namespace

  template <int dim>
  std::vector<double> ContactOperator<dim>::pack_state() const
  {
    std::vector<double> local;
    for (const Node &n : nodes)
      if (n.owned && n.committed.status != ContactStatus::open)
      {
        // 2D: X, Y, status, die, stick x, y, sign, s, gap, gap valid, R_n, R_t, current s,
        // closed in the last step
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(n.X[d]);
        local.push_back(double(static_cast<int>(n.committed.status)));
        local.push_back(double(n.committed.die));
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(n.committed.stick[d]);
        for (unsigned int a = 0; a < dim - 1; ++a)
          local.push_back(n.committed.direction[a]);
        local.insert(
            local.end(),
            {n.committed.s, n.committed_gap, n.committed_gap_valid ? 1. : 0., n.committed.Rn});
        for (unsigned int a = 0; a < dim - 1; ++a)
          local.push_back(n.committed.Rt[a]);
        local.push_back(n.current.s);
        if constexpr (dim == 3)
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(n.current.start[d]);
        local.push_back(n.closed_in_last_step ? 1. : 0.);
      }
    std::vector<double> all;
    for (const auto &part : Utilities::MPI::all_gather(comm, local))
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }

  template <int dim>
  void ContactOperator<dim>::unpack_state(const std::vector<double> &state)
  {
    // Saved nodes by position (rounded to a tolerance grid).
    const double           scale = std::max(gap_tolerance * 1e3, 1e-12);
    constexpr unsigned int size = packed_node_size<dim>;
    std::map<std::array<long long, dim>, const double *> saved;
    const auto                                           key = [scale](const auto &x)
    {
      std::array<long long, dim> k;
      for (unsigned int d = 0; d < dim; ++d)
        k[d] = std::llround(x[d] / scale);
      return k;
    };
    for (std::size_t k = 0; k + size <= state.size(); k += size)
      saved[key(&state[k])] = &state[k];

    for (Node &n : nodes)
    {
      const auto it = saved.find(key(n.X));
      if (it == saved.end())
        continue;
      const double *d = it->second + dim;
      n.committed.status = static_cast<ContactStatus>(static_cast<int>(*d++));
      n.committed.die = static_cast<int>(*d++);
      for (unsigned int c = 0; c < dim; ++c)
        n.committed.stick[c] = *d++;
      for (unsigned int a = 0; a < dim - 1; ++a)
        n.committed.direction[a] = *d++;
      n.committed.s = *d++;
      n.committed_gap = *d++;
      n.committed_gap_valid = *d++ != 0.;
      n.committed.Rn = *d++;
      for (unsigned int a = 0; a < dim - 1; ++a)
        n.committed.Rt[a] = *d++;
      n.current = n.committed;
      n.current.s = *d++;
      if constexpr (dim == 3)
        for (unsigned int c = 0; c < dim; ++c)
          n.current.start[c] = *d++;
      n.closed_in_last_step = *d++ != 0.;
      n.changes = 0;
    }
    build_row_transforms();
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

  template <int dim>
  std::vector<typename ContactOperator<dim>::HeatContact>
  ContactOperator<dim>::heat_contacts() const
  {
    std::vector<HeatContact> contacts;
    for (const Node &n : nodes)
    {
      if (!n.owned || n.current.status == ContactStatus::open || n.current.die < 0)
        continue;
      HeatContact c;
      c.dof = n.dofs[0];
      c.area = n.area;
      c.die = n.current.die;
      if (n.current.status == ContactStatus::slip && n.committed.status != ContactStatus::open
          && n.committed.die == n.current.die)
      {
        // slip of the step relative to the die, in die coordinates: 2D along the arc length,
        // 3D the chord between the converged die points
        double slip = 0.;
        if constexpr (dim == 2)
          slip = std::abs(die_coordinate_difference(c.die, n.projection.s, n.committed.s));
        else
          slip = (n.projection.local_point - n.committed.start).norm();
        double Rt = 0.;
        for (const double r : n.current.Rt)
          Rt += r * r;
        c.friction_work = std::sqrt(Rt) * slip;
      }
      contacts.push_back(c);
    }
    return contacts;
  }

  template class ContactOperator<2>;
  template class ContactOperator<3>;
} // namespace ausroll::contact
