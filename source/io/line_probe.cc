#include <ausroll/core/exceptions.h>
#include <ausroll/core/gather_rows.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/io/line_probe.h>
#include <ausroll/io/owned_cell_around_point.h>
#include <ausroll/io/postprocess/material_state.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace ausroll::io
{
  using namespace dealii;

  std::vector<LineProbeSpecification> parse_line_probes(const std::string &specification,
                                                        const unsigned int dim)
  {
    const std::string                   entry = "Postprocess/Line probes";
    std::vector<LineProbeSpecification> probes;
    std::vector<std::string>            names;
    for (const std::string &item : split_and_trim(specification, ';'))
    {
      const auto colon = item.find(':');
      if (colon == std::string::npos || colon == 0)
        throw InputError(entry + ": '" + item + "' must read 'name: x0, y0, x1, y1, n'");
      LineProbeSpecification probe;
      // the whole text before the colon ("a b" is refused, not cut to "a")
      const std::vector<std::string> before = split_and_trim(item.substr(0, colon), '\n');
      probe.name = before.empty() ? std::string() : before.front();
      require_label(probe.name, entry);
      const std::vector<double> v = parse_double_list(item.substr(colon + 1), entry);
      // Every point is located in the mesh after each mesh change and written at every output.
      if (v.size() == 2 * dim + 1 && v.back() > max_probe_points)
      {
        std::ostringstream n;
        n << v.back();
        throw InputError(entry + ": probe '" + probe.name + "' has " + n.str()
                         + " points, more than ausroll accepts (" + std::to_string(max_probe_points)
                         + "; each point is searched in the mesh and written at every output)");
      }
      if (v.size() != 2 * dim + 1 || v.back() < 2
          || v.back() != static_cast<unsigned int>(v.back()))
        throw InputError(entry + ": '" + item + "' needs " + std::to_string(dim)
                         + " start coordinates, " + std::to_string(dim)
                         + " end coordinates and a number of points >= 2");
      probe.start.assign(v.begin(), v.begin() + dim);
      probe.end.assign(v.begin() + dim, v.begin() + 2 * dim);
      probe.n_points = static_cast<unsigned int>(v.back());
      probes.push_back(probe);
      names.push_back(probe.name);
    }
    require_unique_labels(names, entry);
    return probes;
  }

  std::vector<DepthProbeSpecification>
  parse_depth_probes(const std::string              &specification,
                     const unsigned int              dim,
                     const std::vector<std::string> &line_probe_names)
  {
    const std::string entry = "Postprocess/Depth probes";
    const std::string form = dim == 2 ? "'name: x, y, depth, n'" : "'name: x, y, z, depth, n'";
    std::vector<DepthProbeSpecification> probes;
    std::vector<std::string>             names;
    for (const std::string &item : split_and_trim(specification, ';'))
    {
      const auto colon = item.find(':');
      if (colon == std::string::npos || colon == 0)
        throw InputError(entry + ": '" + item + "' must read " + form);
      DepthProbeSpecification        probe;
      const std::vector<std::string> before = split_and_trim(item.substr(0, colon), '\n');
      probe.name = before.empty() ? std::string() : before.front();
      require_label(probe.name, entry);
      if (std::find(line_probe_names.begin(), line_probe_names.end(), probe.name)
          != line_probe_names.end())
        throw InputError(entry + ": the name '" + probe.name
                         + "' is also a line probe's (Postprocess/Line probes)");
      const std::vector<double> v = parse_double_list(item.substr(colon + 1), entry);
      if (v.size() == dim + 2 && v.back() > max_probe_points)
      {
        std::ostringstream n;
        n << v.back();
        throw InputError(entry + ": probe '" + probe.name + "' has " + n.str()
                         + " points, more than ausroll accepts (" + std::to_string(max_probe_points)
                         + ")");
      }
      if (v.size() != dim + 2 || v.back() < 2 || v.back() != static_cast<unsigned int>(v.back()))
        throw InputError(entry + ": '" + item + "' must read " + form
                         + " (n: a number of points >= 2)");
      if (!(v[dim] > 0.))
        throw InputError(entry + ": probe '" + probe.name + "' needs a positive depth");
      probe.point.assign(v.begin(), v.begin() + dim);
      probe.depth = v[dim];
      probe.n_points = static_cast<unsigned int>(v.back());
      probes.push_back(probe);
      names.push_back(probe.name);
    }
    require_unique_labels(names, entry);
    return probes;
  }

  template <int dim>
  LineProbes<dim>::LineProbes(const std::string &specification, const unsigned int n_q_points_1d)
      : LineProbes(
          parse_line_probes(specification, dim), n_q_points_1d, "Postprocess/Line probes", "probe")
  {
  }

  template <int dim>
  LineProbes<dim>::LineProbes(const std::vector<LineProbeSpecification> &lines,
                              const unsigned int                         n_q_points_1d,
                              const std::string                         &entry,
                              const std::string                         &prefix)
      : interpolation(n_q_points_1d)
      , entry(entry)
      , prefix(prefix)
  {
    for (const LineProbeSpecification &p : lines)
    {
      Probe probe;
      probe.name = p.name;
      for (unsigned int d = 0; d < dim; ++d)
      {
        probe.start[d] = p.start[d];
        probe.end[d] = p.end[d];
      }
      if (p.normal.size() == dim)
      {
        // the frame of the surface: n; t in the plane of the section (2D) or in the x-y plane
        // (3D: along the profile of a body extruded in z); w = n x t
        probe.framed = true;
        for (unsigned int d = 0; d < dim; ++d)
          probe.n[d] = p.normal[d];
        probe.n /= probe.n.norm();
        Tensor<1, 3> z;
        z[2] = 1.;
        probe.t = cross_product_3d(z, probe.n);
        if (probe.t.norm() < 1e-8) // a normal along z (3D): t along x
        {
          Tensor<1, 3> x;
          x[0] = 1.;
          probe.t = cross_product_3d(probe.n, cross_product_3d(x, probe.n));
        }
        probe.t /= probe.t.norm();
        probe.w = cross_product_3d(probe.n, probe.t);
      }
      const unsigned int n = p.n_points;
      for (unsigned int i = 0; i < n; ++i)
      {
        Sample s;
        s.position = probe.start + (probe.end - probe.start) * (double(i) / (n - 1));
        probe.samples.push_back(s);
      }
      probes.push_back(probe);
    }
  }

  template <int dim>
  void LineProbes<dim>::locate(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler)
  {
    const MPI_Comm     comm = dof_handler.get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    for (Probe &probe : probes)
    {
      std::vector<unsigned int> owner(probe.samples.size(), n_ranks);
      for (unsigned int i = 0; i < probe.samples.size(); ++i)
      {
        Sample &s = probe.samples[i];
        s.local = false;
        // a point on a curved boundary (the start of a depth probe) may lie just outside the
        // mapped cells: then the nearest point of a cell within 1 % of its size
        auto found = owned_cell_around_point(mapping, dof_handler, s.position);
        if (!found)
          found = owned_cell_around_point(mapping, dof_handler, s.position, 1e-2);
        if (found)
        {
          s.cell = found->first;
          s.unit_point = found->second;
          owner[i] = rank;
        }
      }
      {
        std::vector<unsigned int> local_owner = owner;
        Utilities::MPI::min(
            ArrayView<const unsigned int>(local_owner), comm, ArrayView<unsigned int>(owner));
      }
      for (unsigned int i = 0; i < probe.samples.size(); ++i)
      {
        if (owner[i] == n_ranks)
        {
          std::ostringstream msg;
          msg << entry << ": point (" << probe.samples[i].position << ") of probe '" << probe.name
              << "' is outside the workpiece";
          throw InputError(msg.str());
        }
        probe.samples[i].local = owner[i] == rank;
      }
    }
  }

  template <int dim>
  void LineProbes<dim>::write(const std::string                          &directory,
                              const unsigned int                          counter,
                              const double                                time,
                              const Mapping<dim>                         &mapping,
                              const DoFHandler<dim>                      &dof_handler,
                              const TrilinosWrappers::MPI::Vector        &solution,
                              const mechanics::MaterialPointStorage<dim> &material_points,
                              const bool                                  small_strain,
                              const bool                                  state_columns) const
  {
    const MPI_Comm comm = dof_handler.get_communicator();
    const auto     components = postprocess::tensor_components<dim>();
    const unsigned n_shear = dim == 3 ? 2 : 0; // stress_xz, stress_yz
    for (const Probe &probe : probes)
    {
      // Each rank evaluates its samples: (index, values...).
      std::vector<std::vector<double>> rows;
      for (unsigned int i = 0; i < probe.samples.size(); ++i)
      {
        const Sample &s = probe.samples[i];
        if (!s.local)
          continue;
        const Quadrature<dim> q(s.unit_point);
        FEValues<dim>         fe_values(mapping, dof_handler.get_fe(), q, update_values);
        fe_values.reinit(s.cell);
        std::vector<Tensor<1, dim>> u(1);
        fe_values[FEValuesExtractors::Vector(0)].get_function_values(solution, u);

        const auto          points = material_points.get_data(s.cell);
        const auto          weights = interpolation.weights(s.unit_point);
        double              fields[6] = {0, 0, 0, 0, 0, 0};
        double              state[4] = {0, 0, 0, 0}; // temperature, martensite, bainite, carbon
        std::vector<double> more(n_shear + components.size(), 0.); // shear stresses, strain
        for (unsigned int k = 0; k < points.size(); ++k)
        {
          const auto &st = points[k]->committed;
          const auto  eps = postprocess::strain_tensor(st, small_strain);
          for (unsigned int i = 0; i < n_shear; ++i)
            more[i]
                += weights[k] * st.stress[components[4 + i].second[0]][components[4 + i].second[1]];
          for (unsigned int i = 0; i < components.size(); ++i)
            more[n_shear + i] += weights[k] * eps[components[i].second[0]][components[i].second[1]];
          fields[0] += weights[k] * st.stress[0][0];
          fields[1] += weights[k] * st.stress[1][1];
          fields[2] += weights[k] * st.stress[2][2];
          fields[3] += weights[k] * st.stress[0][1];
          fields[4] += weights[k] * st.von_mises_stress();
          fields[5] += weights[k] * st.equivalent_plastic_strain;
          state[0] += weights[k] * st.temperature;
          state[1] += weights[k] * st.martensite;
          state[2] += weights[k] * st.bainite;
          state[3] += weights[k] * st.carbon;
        }
        std::vector<double> row{double(i), s.position.distance(probe.start)};
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(s.position[d]);
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(u[0][d]);
        row.insert(row.end(), fields, fields + 6);
        row.insert(row.end(), more.begin(), more.end());
        if (probe.framed)
        {
          SymmetricTensor<2, 3> sigma;
          sigma[0][0] = fields[0];
          sigma[1][1] = fields[1];
          sigma[2][2] = fields[2];
          sigma[0][1] = fields[3];
          if (dim == 3)
          {
            sigma[0][2] = more[0];
            sigma[1][2] = more[1];
          }
          const auto &n = probe.n, &t = probe.t, &w = probe.w;
          row.push_back(n * (sigma * n));
          row.push_back(t * (sigma * t));
          if (dim == 3)
            row.push_back(w * (sigma * w));
          row.push_back(n * (sigma * t));
          if (dim == 3)
          {
            row.push_back(n * (sigma * w));
            row.push_back(t * (sigma * w));
          }
        }
        if (state_columns)
          row.insert(row.end(), state, state + 4);
        rows.push_back(row);
      }
      const std::vector<std::vector<double>> all = gather_sorted_rows(comm, rows);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        continue;

      std::ostringstream name;
      name << directory << "/" << prefix << "_" << probe.name << "_" << std::setw(4)
           << std::setfill('0') << counter << ".csv";
      std::ofstream out(name.str());
      out << "time,s,x,y" << (dim == 3 ? ",z" : "") << ",ux,uy" << (dim == 3 ? ",uz" : "")
          << ",stress_xx,stress_yy,stress_zz,stress_xy,von_mises_stress,equivalent_plastic_strain";
      for (unsigned int i = 0; i < n_shear; ++i)
        out << ",stress_" << components[4 + i].first;
      for (const auto &c : components)
        out << ",strain_" << c.first;
      if (probe.framed)
        out << (dim == 2 ? ",stress_nn,stress_tt,stress_nt"
                         : ",stress_nn,stress_tt,stress_ww,stress_nt,stress_nw,stress_tw");
      if (state_columns)
        out << ",temperature,martensite,bainite,carbon";
      out << '\n' << std::setprecision(10);
      for (const auto &row : all)
      {
        out << time;
        for (unsigned int k = 1; k < row.size(); ++k)
          out << ',' << row[k];
        out << '\n';
      }
    }
  }

  template class LineProbes<2>;
  template class LineProbes<3>;
} // namespace ausroll::io
