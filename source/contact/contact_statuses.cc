/**
 * @file contact_statuses.cc
 * ContactOperator: the status rules of the contact nodes (closing, opening, stick/slip, slip
 * direction), the events of the load-increment ratio and the committed/current state.
 */
#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/tangential_components.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace ausroll::contact
{
  using namespace dealii;

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
        n.current.s
            = n.current.status == ContactStatus::stick
                  ? dies[n.current.die]->die_surface().project(n.current.stick).coordinates[0]
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
  unsigned int ContactOperator<dim>::update_statuses(const unsigned int change_limit)
  {
    unsigned int changes = 0;
    for (Node &n : nodes)
    {
      if (n.current.status == ContactStatus::open || n.fresh
          || n.changes >= std::min(parameters.max_status_changes, change_limit))
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
        // (SlipDirectionTangent: Newton converges quadratically in the direction too),
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

  template class ContactOperator<2>;
  template class ContactOperator<3>;
} // namespace ausroll::contact
