/**
 * @file contact_constraints.cc
 * ContactOperator: the constraints and friction row transforms of the contact nodes, the
 * slipping nodes the slip direction tangent reads, the reactions, the forces on the dies, the
 * output, the packed state of checkpoints and the contact data of the heat equation.
 */
#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/tangential_components.h>
#include <ausroll/core/gather_rows.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>

namespace ausroll::contact
{
  using namespace dealii;

  namespace
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();
  } // namespace

  template <int dim>
  std::vector<typename ContactOperator<dim>::FollowedSlip>
  ContactOperator<dim>::followed_slips() const
  {
    std::vector<FollowedSlip> slips;
    for (const Node &n : nodes)
      if (n.owned && n.current.status == ContactStatus::slip && n.followed_slip > 0.
          && dies[n.current.die]->friction->switches_stick_slip())
        slips.push_back(FollowedSlip{
            n.dofs,
            n.projection.normal,
            slip_vector(n),
            n.followed_slip,
            dies[n.current.die]->friction->slip_limit(n.current.Rn, n.area).value(n.current.Rn)});
    return slips;
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
