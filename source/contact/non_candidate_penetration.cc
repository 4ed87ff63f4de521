#include <ausroll/contact/non_candidate_penetration.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <functional>
#include <map>
#include <sstream>

namespace ausroll::contact
{
  using namespace dealii;

  template <int dim>
  void NonCandidatePenetration<dim>::setup(const Mapping<dim>    &mapping,
                                           const DoFHandler<dim> &dof_handler)
  {
    nodes.clear();
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    const IndexSet                       owned = dof_handler.locally_owned_dofs();
    const auto                          &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    // node key: the DoF of component 0; one entry per node
    std::map<types::global_dof_index, BoundaryNode> found;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
          {
            cell->face(f)->get_dof_indices(face_dofs);
            std::map<Point<dim>,
                     BoundaryNode,
                     std::function<bool(const Point<dim> &, const Point<dim> &)>>
                by_point(
                    [](const Point<dim> &a, const Point<dim> &b)
                    {
                      for (unsigned int d = 0; d < dim; ++d)
                        if (std::abs(a[d] - b[d]) > 1e-12)
                          return a[d] < b[d];
                      return false;
                    });
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
            {
              const auto p = points.find(face_dofs[i]);
              if (p == points.end())
                continue;
              BoundaryNode &n = by_point[p->second];
              n.X = p->second;
              n.dofs[fe.face_system_to_component_index(i).first] = face_dofs[i];
            }
            for (const auto &[X, n] : by_point)
              if (owned.is_element(n.dofs[0]))
              {
                BoundaryNode &node = found.emplace(n.dofs[0], n).first->second;
                node.boundary_ids.push_back(cell->face(f)->boundary_id());
              }
          }
    for (const auto &[key, n] : found)
      nodes.push_back(n);
  }

  template <int dim>
  typename NonCandidatePenetration<dim>::Penetration
  NonCandidatePenetration<dim>::find(const ContactOperator<dim>          &contact,
                                     const TrilinosWrappers::MPI::Vector &u,
                                     const double                         time,
                                     const double                         tolerance,
                                     const MPI_Comm                       comm) const
  {
    return find_crossing(contact, u, time, u, -1., tolerance, comm);
  }

  template <int dim>
  typename NonCandidatePenetration<dim>::Penetration
  NonCandidatePenetration<dim>::find_crossing(const ContactOperator<dim>          &contact,
                                              const TrilinosWrappers::MPI::Vector &u,
                                              const double                         time,
                                              const TrilinosWrappers::MPI::Vector &u_start,
                                              const double                         t_start,
                                              const double                         tolerance,
                                              const MPI_Comm                       comm) const
  {
    double       depth = tolerance;
    int          die = -1;
    BoundaryNode deepest;
    for (const BoundaryNode &n : nodes)
      for (unsigned int k = 0; k < contact.n_dies(); ++k)
      {
        const RigidDie<dim> &d = contact.die(k);
        bool                 candidate = false;
        for (const unsigned int id : n.boundary_ids)
          candidate = candidate || d.is_candidate(id);
        if (candidate)
          continue;
        Point<dim> x;
        for (unsigned int c = 0; c < dim; ++c)
          x[c] = n.X[c] + u[n.dofs[c]];
        // beyond the end of an open, finite die (or on the extension of a polyline) a negative
        // gap is no penetration: DieProjection::depth()
        const DieProjection<dim> p = d.project(x, time);
        if (!p.valid || p.depth() <= depth)
          continue;
        if (t_start >= 0.)
        {
          // only nodes outside the die at the start of the step
          Point<dim> x0;
          for (unsigned int c = 0; c < dim; ++c)
            x0[c] = n.X[c] + u_start[n.dofs[c]];
          const DieProjection<dim> p0 = d.project(x0, t_start);
          if (!p0.valid || p0.depth() > tolerance)
            continue;
        }
        {
          depth = p.depth();
          die = k;
          deepest = n;
        }
      }
    // the deepest node over all ranks, told by its rank
    Penetration result;
    const auto  extremes = Utilities::MPI::min_max_avg(die >= 0 ? depth : 0., comm);
    if (extremes.max <= tolerance)
      return result;
    const unsigned int          root = extremes.max_index;
    std::array<double, 2 + dim> data;
    data[0] = die;
    data[1] = deepest.boundary_ids.empty() ? 0 : deepest.boundary_ids[0];
    for (unsigned int c = 0; c < dim; ++c)
      data[2 + c] = deepest.X[c];
    data = Utilities::MPI::broadcast(comm, data, root);
    result.found = true;
    result.die = static_cast<unsigned int>(data[0]);
    result.boundary = static_cast<unsigned int>(data[1]);
    result.depth = extremes.max;
    for (unsigned int c = 0; c < dim; ++c)
      result.X[c] = data[2 + c];
    return result;
  }

  template <int dim>
  std::string NonCandidatePenetration<dim>::describe(const Penetration &p,
                                                     const std::string &die_name,
                                                     const unsigned int step,
                                                     const double       time)
  {
    std::ostringstream msg;
    msg << "boundary " << p.boundary << " of the workpiece passes through die " << p.die << " '"
        << die_name << "' by " << p.depth << " mm at the node (" << p.X
        << ") (reference coordinates) in step " << step << ", t = " << time
        << ": it is not among Contact/Die " << p.die << "/Candidate boundaries";
    return msg.str();
  }

  template <int dim>
  typename NonCandidatePenetration<dim>::Penetration
  NonCandidatePenetration<dim>::boundary_to_add(const ContactOperator<dim>          &contact,
                                                const TrilinosWrappers::MPI::Vector &u,
                                                const double                         time,
                                                const TrilinosWrappers::MPI::Vector &u_start,
                                                const double                         t_start,
                                                const double                         tolerance,
                                                const std::set<unsigned int>        &held,
                                                const MPI_Comm                       comm) const
  {
    Penetration p = find_crossing(contact, u, time, u_start, t_start, tolerance, comm);
    if (p.found && held.count(p.boundary) != 0)
      p.found = false;
    return p;
  }

  template <int dim>
  std::string NonCandidatePenetration<dim>::added_note(const Penetration &p,
                                                       const std::string &die_name,
                                                       const unsigned int step,
                                                       const double       time)
  {
    std::ostringstream msg;
    msg << describe(p, die_name, step, time)
        << "; it is now a candidate of that die (Contact/Penetrating boundaries = add), and the "
           "step is solved again. Add "
        << p.boundary << " to Contact/Die " << p.die
        << "/Candidate boundaries to say so in the input";
    return msg.str();
  }

  template <int dim>
  std::string NonCandidatePenetration<dim>::check(const ContactOperator<dim>          &contact,
                                                  const TrilinosWrappers::MPI::Vector &u,
                                                  const double                         time,
                                                  const unsigned int                   step,
                                                  const double                         tolerance,
                                                  const MPI_Comm                       comm)
  {
    if (reported)
      return "";
    const Penetration p = find(contact, u, time, tolerance, comm);
    if (!p.found)
      return "";
    reported = true;
    std::ostringstream msg;
    msg << describe(p, contact.die(p.die).name, step, time)
        << ", so it cannot touch the die; results from here on are not those of the forming "
           "process. Add "
        << p.boundary << " to Contact/Die " << p.die
        << "/Candidate boundaries (or set Contact/Penetrating boundaries = add)";
    return msg.str();
  }

  template class NonCandidatePenetration<2>;
  template class NonCandidatePenetration<3>;
} // namespace ausroll::contact
