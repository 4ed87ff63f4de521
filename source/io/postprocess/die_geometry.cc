#include <ausroll/core/exceptions.h>
#include <ausroll/io/postprocess/die_geometry.h>
#include <ausroll/io/postprocess/standard_set.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  namespace
  {
    /** Distance of @p p from the segment [a, b]. */
    template <int dim>
    double distance_to_segment(const Point<dim> &p, const Point<dim> &a, const Point<dim> &b)
    {
      const Tensor<1, dim> ab = b - a;
      const double         l2 = ab.norm_square();
      const double         s = l2 > 0. ? std::clamp((p - a) * ab / l2, 0., 1.) : 0.;
      return (p - (a + s * ab)).norm();
    }

    /** Deformed positions of the workpiece's boundary vertices on locally owned cells. */
    template <int dim>
    std::vector<Point<dim>> deformed_boundary_vertices(const PostprocessInput<dim> &input)
    {
      std::vector<Point<dim>> points;
      for (const auto &cell : input.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                Point<dim> x = face->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  x[d] += input.solution(face->vertex_dof_index(v, d));
                points.push_back(x);
              }
      return points;
    }

    /**
     * The range [lo, hi] of one surface coordinate to draw, from the coordinates @p values of the
     * projected vertices (on this rank) of a coordinate with period @p period (0: none), widened
     * by a quarter of its width on each side and by at least @p margin. Collective.
     */
    std::pair<double, double> coordinate_range(const std::vector<double> &values,
                                               const double               period,
                                               const double               margin,
                                               const MPI_Comm             comm)
    {
      if (period > 0.)
      {
        // occupied bins of the period; the arc drawn is the complement of the longest empty run
        const unsigned int  n = 720;
        std::vector<double> local(n, 0.), bins(n, 0.);
        for (const double v : values)
        {
          const double w = v - period * std::floor(v / period);
          local[std::min(n - 1, static_cast<unsigned int>(w / period * n))] = 1.;
        }
        Utilities::MPI::max(ArrayView<const double>(local), comm, ArrayView<double>(bins));
        unsigned int best_length = 0, best_end = 0, run = 0;
        for (unsigned int i = 0; i < 2 * n; ++i)
        {
          run = bins[i % n] > 0. ? 0 : run + 1;
          if (run > best_length && run <= n)
            best_length = run, best_end = i + 1;
        }
        const double bin = period / n;
        const double width = (n - best_length) * bin;
        const double widened = 1.5 * width + 2. * bin + 2. * margin;
        if (best_length == 0 || widened >= period)
          return {0., period};
        const double lo = best_end * bin - 0.25 * width - bin - margin;
        return {lo, lo + widened};
      }
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const double v : values)
        lo = std::min(lo, v), hi = std::max(hi, v);
      lo = Utilities::MPI::min(lo, comm);
      hi = Utilities::MPI::max(hi, comm);
      const double widen = std::max(0.25 * (hi - lo), margin);
      return {lo - widen, hi + widen};
    }

    /** One die's sampled surface: points (global, 3 coordinates) and cells (VTK type, ids). */
    struct DieMesh
    {
      std::vector<std::array<double, 3>> points;
      std::vector<std::vector<unsigned>> cells;
      unsigned char                      cell_type = 0; ///< VTK: 4 poly line, 9 quad
    };

    void write_die_vtu(const std::string &file,
                       const DieMesh     &mesh,
                       const unsigned int die_id,
                       const double       time)
    {
      std::ofstream out(file);
      out << std::setprecision(17);
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<FieldData>\n"
             "<DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">"
          << time << "</DataArray>\n</FieldData>\n<Piece NumberOfPoints=\"" << mesh.points.size()
          << "\" NumberOfCells=\"" << mesh.cells.size() << "\">\n";
      auto ids = [&](const std::size_t n)
      {
        out << "<DataArray type=\"Int32\" Name=\"die_id\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < n; ++i)
          out << die_id << ((i + 1) % 20 ? ' ' : '\n');
        out << "\n</DataArray>\n";
      };
      out << "<PointData Scalars=\"die_id\">\n";
      ids(mesh.points.size());
      out << "</PointData>\n<CellData Scalars=\"die_id\">\n";
      ids(mesh.cells.size());
      out << "</CellData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n";
      for (const auto &p : mesh.points)
        out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      out << "</DataArray>\n</Points>\n<Cells>\n"
             "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (const auto &c : mesh.cells)
      {
        for (const unsigned int v : c)
          out << v << ' ';
        out << '\n';
      }
      out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      std::size_t offset = 0;
      for (const auto &c : mesh.cells)
        out << (offset += c.size()) << '\n';
      out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (std::size_t i = 0; i < mesh.cells.size(); ++i)
        out << static_cast<unsigned int>(mesh.cell_type) << '\n';
      out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      out.close();
      if (!out)
        throw RunFailure("cannot write the die geometry file '" + file + "' (Output/Directory)");
    }

    /** The entries (time, file) of an existing dies.pvd whose output number is below @p counter
        (a resumed run keeps what was written before it). */
    std::vector<std::pair<double, std::string>> read_pvd_records(const std::string &pvd,
                                                                 const unsigned int counter)
    {
      std::vector<std::pair<double, std::string>> records;
      std::ifstream                               in(pvd);
      std::string                                 line;
      while (std::getline(in, line))
      {
        const auto t = line.find("timestep=\""), f = line.find("file=\"");
        if (t == std::string::npos || f == std::string::npos)
          continue;
        const std::string file = line.substr(f + 6, line.find('"', f + 6) - f - 6);
        const auto        digits = file.find_first_of("0123456789");
        try
        {
          if (digits != std::string::npos && std::stoul(file.substr(digits)) < counter)
            records.emplace_back(std::stod(line.substr(t + 10)), file);
        }
        catch (const std::exception &)
        {
          // not an entry of this writer: dropped
        }
      }
      return records;
    }
  } // namespace

  template <int dim>
  std::array<std::vector<double>, dim - 1>
  sample_coordinates(const std::function<Point<dim>(const std::array<double, dim - 1> &)> &point_at,
                     const std::array<double, dim - 1>                                    &lo,
                     const std::array<double, dim - 1>                                    &hi,
                     const double       tolerance,
                     const unsigned int max_points)
  {
    std::array<std::vector<double>, dim - 1> result;
    for (unsigned int a = 0; a < dim - 1; ++a)
    {
      const double range = hi[a] - lo[a];
      // the other coordinate (3D) is held at its ends and its middle
      std::vector<std::array<double, dim - 1>> bases(1);
      if constexpr (dim == 3)
      {
        const unsigned int b = 1 - a;
        bases.assign(3, std::array<double, dim - 1>());
        for (unsigned int k = 0; k < 3; ++k)
          bases[k][b] = lo[b] + 0.5 * k * (hi[b] - lo[b]);
      }
      for (double tol = tolerance;; tol *= 4.)
      {
        std::vector<double> values;
        for (std::array<double, dim - 1> c : bases)
        {
          auto at = [&](const double u)
          {
            c[a] = u;
            return point_at(c);
          };
          // halve [u0, u1] while a quarter point lies farther than tol from the chord
          std::function<void(double, const Point<dim> &, double, const Point<dim> &, unsigned)>
              refine = [&](const double      u0,
                           const Point<dim> &p0,
                           const double      u1,
                           const Point<dim> &p1,
                           const unsigned    depth)
          {
            const double     um = 0.5 * (u0 + u1);
            const Point<dim> pm = at(um);
            const double     deviation = std::max({distance_to_segment(pm, p0, p1),
                                                   distance_to_segment(at(0.5 * (u0 + um)), p0, p1),
                                                   distance_to_segment(at(0.5 * (um + u1)), p0, p1)});
            if (deviation <= tol || depth >= 14 || values.size() > 4 * max_points)
              return;
            refine(u0, p0, um, pm, depth + 1);
            values.push_back(um);
            refine(um, pm, u1, p1, depth + 1);
          };
          const unsigned int n0 = 16;
          for (unsigned int i = 0; i <= n0; ++i)
            values.push_back(lo[a] + range * i / n0);
          for (unsigned int i = 0; i < n0; ++i)
          {
            const double u0 = lo[a] + range * i / n0, u1 = lo[a] + range * (i + 1) / n0;
            refine(u0, at(u0), u1, at(u1), 0);
          }
        }
        std::sort(values.begin(), values.end());
        const double merge = 1e-12 * std::max(std::abs(range), 1e-300);
        values.erase(std::unique(values.begin(),
                                 values.end(),
                                 [merge](const double x, const double y)
                                 { return std::abs(x - y) <= merge; }),
                     values.end());
        if (values.size() <= max_points || tol > std::abs(range))
        {
          result[a] = values;
          break;
        }
      }
    }
    return result;
  }

  template <int dim>
  DieGeometry<dim>::DieGeometry(const bool write_vtu)
      : write_vtu(write_vtu)
  {
  }

  template <int dim>
  void DieGeometry<dim>::write_files(const PostprocessInput<dim> &input,
                                     const std::string           &directory,
                                     const unsigned int           counter)
  {
    const contact::ContactOperator<dim> &contact = input.contact;
    if (!write_vtu || !contact.active() || contact.n_dies() == 0)
      return;
    const MPI_Comm                comm = input.dof_handler.get_communicator();
    const bool                    root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::vector<Point<dim>> vertices = deformed_boundary_vertices(input);

    // the workpiece's size: the diagonal of its deformed bounding box
    std::array<double, 2 * dim> box;
    box.fill(-std::numeric_limits<double>::infinity());
    for (const Point<dim> &x : vertices)
      for (unsigned int d = 0; d < dim; ++d)
        box[d] = std::max(box[d], -x[d]), box[dim + d] = std::max(box[dim + d], x[d]);
    std::array<double, 2 * dim> global_box;
    Utilities::MPI::max(ArrayView<const double>(box.data(), box.size()),
                        comm,
                        ArrayView<double>(global_box.data(), global_box.size()));
    double size2 = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      size2 += std::pow(global_box[dim + d] + global_box[d], 2);
    const double size = std::sqrt(size2);

    std::ostringstream base;
    base << "dies_" << std::setw(4) << std::setfill('0') << counter;
    for (unsigned int k = 0; k < contact.n_dies(); ++k)
    {
      const contact::RigidDie<dim>            &die = contact.die(k);
      const contact::RigidSurface<dim>        &surface = die.surface();
      const contact::DiePose<dim>              pose = die.pose(input.time);
      std::array<std::vector<double>, dim - 1> coordinates;
      for (const Point<dim> &x : vertices)
      {
        const contact::SurfaceProjection<dim> p = surface.project(pose.to_local(x));
        if (p.valid)
          for (unsigned int a = 0; a < dim - 1; ++a)
            coordinates[a].push_back(p.coordinates[a]);
      }
      std::array<double, dim - 1> lo, hi;
      for (unsigned int a = 0; a < dim - 1; ++a)
      {
        // the margin is a length; for an angle (the period 2 pi) a 20th of the period
        const double period = surface.coordinate_periods()[a];
        const bool   angle = std::abs(period - 2. * numbers::PI) < 1e-12;
        std::tie(lo[a], hi[a]) = coordinate_range(
            coordinates[a], period, angle ? 0.1 * numbers::PI : 0.05 * size, comm);
      }
      if (!root)
        continue;

      const auto global_point = [&](const std::array<double, dim - 1> &c)
      { return pose.to_global(surface.point_at(c)); };
      const std::array<std::vector<double>, dim - 1> samples
          = sample_coordinates<dim>(global_point, lo, hi, 2e-4 * size);
      DieMesh mesh;
      auto    add_point = [&mesh](const Point<dim> &p) {
        mesh.points.push_back({{p[0], p[1], dim == 3 ? p[dim - 1] : 0.}});
      };
      if constexpr (dim == 2)
      {
        mesh.cell_type = 4; // VTK_POLY_LINE
        mesh.cells.emplace_back();
        for (const double s : samples[0])
        {
          mesh.cells.back().push_back(mesh.points.size());
          add_point(global_point({{s}}));
        }
      }
      else
      {
        mesh.cell_type = 9; // VTK_QUAD
        const std::size_t n1 = samples[1].size();
        for (const double c0 : samples[0])
          for (const double c1 : samples[1])
            add_point(global_point({{c0, c1}}));
        for (unsigned int i = 0; i + 1 < samples[0].size(); ++i)
          for (unsigned int j = 0; j + 1 < n1; ++j)
            mesh.cells.push_back({static_cast<unsigned>(i * n1 + j),
                                  static_cast<unsigned>((i + 1) * n1 + j),
                                  static_cast<unsigned>((i + 1) * n1 + j + 1),
                                  static_cast<unsigned>(i * n1 + j + 1)});
      }
      write_die_vtu(
          directory + "/" + base.str() + "_" + std::to_string(k) + ".vtu", mesh, k, input.time);
    }
    if (!root)
      return;

    // the multiblock file (one named block per die) and the time series
    const std::string vtm = base.str() + ".vtm";
    {
      std::ofstream out(directory + "/" + vtm);
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
             "byte_order=\"LittleEndian\">\n<vtkMultiBlockDataSet>\n";
      for (unsigned int k = 0; k < contact.n_dies(); ++k)
        out << "  <DataSet index=\"" << k << "\" name=\"" << contact.die(k).name << "\" file=\""
            << base.str() << "_" << k << ".vtu\"/>\n";
      out << "</vtkMultiBlockDataSet>\n</VTKFile>\n";
      out.close();
      if (!out)
        throw RunFailure("cannot write the die geometry file '" + directory + "/" + vtm
                         + "' (Output/Directory)");
    }
    const std::string pvd = directory + "/dies.pvd";
    if (first_output)
      records = read_pvd_records(pvd, counter);
    first_output = false;
    records.emplace_back(input.time, vtm);
    const std::string tmp = pvd + ".tmp";
    {
      std::ofstream out(tmp);
      DataOutBase::write_pvd_record(out, records);
      out.close();
      if (!out)
        throw RunFailure("cannot write '" + tmp + "' (Output/Directory)");
    }
    std::rename(tmp.c_str(), pvd.c_str());
  }

  template class DieGeometry<2>;
  template class DieGeometry<3>;
  template std::array<std::vector<double>, 1>
  sample_coordinates<2>(const std::function<Point<2>(const std::array<double, 1> &)> &,
                        const std::array<double, 1> &,
                        const std::array<double, 1> &,
                        const double,
                        const unsigned int);
  template std::array<std::vector<double>, 2>
  sample_coordinates<3>(const std::function<Point<3>(const std::array<double, 2> &)> &,
                        const std::array<double, 2> &,
                        const std::array<double, 2> &,
                        const double,
                        const unsigned int);
  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_die_geometry(const PostprocessorContext &c)
    {
      return std::make_unique<DieGeometry<dim>>(c.output.write_vtu);
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_die_geometry,
                               "die geometry",
                               110,
                               "the dies as geometry for ParaView (dies.pvd)")
