#include <ausroll/core/gather_rows.h>
#include <ausroll/io/boundary_profile.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <tuple>

namespace ausroll::io
{
  using namespace dealii;

  template <int dim>
  BoundaryProfile<dim>::BoundaryProfile(const BoundaryProfileParameters &parameters)
      : parameters(parameters)
  {
  }

  template <int dim>
  void BoundaryProfile<dim>::write(const std::string                   &directory,
                                   const unsigned int                   counter,
                                   const double                         time,
                                   const Mapping<dim>                  &mapping,
                                   const DoFHandler<dim>               &dof_handler,
                                   const TrilinosWrappers::MPI::Vector &solution) const
  {
    if (empty())
      return;
    const auto &fe = dof_handler.get_fe();
    // Evaluate the displacement at the face support points of the element: face DoF i of
    // component 0 sits at quadrature point i.
    const Quadrature<dim - 1> support(fe.get_unit_face_support_points());
    FEFaceValues<dim> fe_face(mapping, fe, support, update_values | update_quadrature_points);
    const std::set<types::boundary_id> ids(parameters.boundary_ids.begin(),
                                           parameters.boundary_ids.end());

    // Rows: x-DoF index, boundary id, reference x, y, displacement x, y.
    std::vector<std::vector<double>>     rows;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::vector<Vector<double>>          u(support.size(), Vector<double>(fe.n_components()));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && ids.count(cell->face(f)->boundary_id()))
          {
            fe_face.reinit(cell, f);
            fe_face.get_function_values(solution, u);
            cell->face(f)->get_dof_indices(face_dofs);
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              if (fe.face_system_to_component_index(i).first == 0)
              {
                const Point<dim> &x = fe_face.quadrature_point(i);
                rows.push_back({double(face_dofs[i]),
                                double(cell->face(f)->boundary_id()),
                                x[0],
                                x[1],
                                u[i][0],
                                u[i][1]});
              }
          }

    const MPI_Comm                   comm = dof_handler.get_communicator();
    std::vector<std::vector<double>> all = gather_sorted_rows(comm, rows);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    all.erase(std::unique(all.begin(),
                          all.end(),
                          [](const auto &a, const auto &b) { return a[0] == b[0]; }),
              all.end());

    const Point<2> &c = parameters.center;
    const auto      angle = [&c](const std::vector<double> &r)
    {
      const double a = std::atan2(r[3] - c[1], r[2] - c[0]) * 180. / M_PI;
      return a < 0. ? a + 360. : a;
    };
    std::sort(all.begin(),
              all.end(),
              [&angle](const auto &a, const auto &b)
              {
                // Ties (several boundaries at one angle): by boundary id, then reference radius,
                // so that the order does not depend on the DoF numbering (number of ranks).
                return std::make_tuple(angle(a), a[1], a[2] * a[2] + a[3] * a[3])
                       < std::make_tuple(angle(b), b[1], b[2] * b[2] + b[3] * b[3]);
              });

    std::ostringstream name;
    name << directory << "/profile_" << std::setw(4) << std::setfill('0') << counter << ".csv";
    std::ofstream out(name.str());
    out << "time,boundary_id,x,y,current_x,current_y,angle,radius,radial_displacement\n"
        << std::setprecision(12);
    for (const auto &r : all)
    {
      const double cx = r[2] + r[4], cy = r[3] + r[5];
      const double r0 = std::hypot(r[2] - c[0], r[3] - c[1]);
      const double r1 = std::hypot(cx - c[0], cy - c[1]);
      out << time << ',' << r[1] << ',' << r[2] << ',' << r[3] << ',' << cx << ',' << cy << ','
          << angle(r) << ',' << r1 << ',' << r1 - r0 << '\n';
    }
  }

  template class BoundaryProfile<2>;
  template class BoundaryProfile<3>;
} // namespace ausroll::io
