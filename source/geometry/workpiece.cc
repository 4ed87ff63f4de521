#include <ausroll/core/exceptions.h>
#include <ausroll/core/input_file.h>
#include <ausroll/core/parameter_file.h>
#include <ausroll/geometry/gear_tooth_mesh.h>
#include <ausroll/geometry/workpiece.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ausroll::geometry
{
  using namespace dealii;

  namespace
  {
    /**
     * Quarter annulus a <= r <= b, 0 <= theta <= pi/2 as a polar grid of radial x angular cells;
     * all cells carry a PolarManifold (manifold id 1) so that refinement follows the circles.
     */
    void quarter_ring(const GeometryParameters &p, Triangulation<2> &coarse)
    {
      GridGenerator::subdivided_hyper_rectangle(coarse,
                                                {p.radial_cells, p.angular_cells},
                                                Point<2>(p.inner_radius, 0.),
                                                Point<2>(p.outer_radius, numbers::PI / 2.));
      GridTools::transform([](const Point<2> &rt)
                           { return Point<2>(rt[0] * std::cos(rt[1]), rt[0] * std::sin(rt[1])); },
                           coarse);
      const double tol = 1e-8 * p.outer_radius;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
          {
            const Point<2> c = face->center();
            const double   r = c.norm();
            if (std::abs(c[1]) < tol)
              face->set_boundary_id(2);
            else if (std::abs(c[0]) < tol)
              face->set_boundary_id(3);
            else if (r < 0.5 * (p.inner_radius + p.outer_radius))
              face->set_boundary_id(0);
            else
              face->set_boundary_id(1);
          }
    }

    /**
     * Annulus a <= r <= b about the centre c: a polar grid of `Cells radially` x `Cells around`
     * cells. The full annulus (`Sector angle` = 360) closes its last angular column onto the
     * first (shared vertices, no seam); a sector 0 <= angle <= `Sector angle` is open. Boundary
     * ids: 0 inner circle, 1 outer circle; a sector's cut edges 2 (angle 0) and 3 (its angle).
     */
    void ring(const GeometryParameters &p, Triangulation<2> &coarse)
    {
      const unsigned int n_r = p.ring_cells_radially, n_t = p.ring_cells_around;
      const bool         full = p.ring_sector_angle >= 360.;
      const double sector = full ? 2. * numbers::PI : p.ring_sector_angle * numbers::PI / 180.;
      const unsigned int    columns = full ? n_t : n_t + 1; // vertices around
      std::vector<Point<2>> vertices;
      for (unsigned int i = 0; i <= n_r; ++i)
        for (unsigned int j = 0; j < columns; ++j)
        {
          const double r
              = p.ring_inner_radius + (p.ring_outer_radius - p.ring_inner_radius) * i / double(n_r);
          const double phi = sector * j / double(n_t);
          vertices.emplace_back(p.ring_center
                                + Tensor<1, 2>({r * std::cos(phi), r * std::sin(phi)}));
        }
      // Local x = radial, local y = counter-clockwise: positive Jacobian.
      std::vector<CellData<2>> cells;
      for (unsigned int i = 0; i < n_r; ++i)
        for (unsigned int j = 0; j < n_t; ++j)
        {
          CellData<2>        cell;
          const unsigned int jn = (j + 1) % columns;
          cell.vertices
              = {i * columns + j, (i + 1) * columns + j, i * columns + jn, (i + 1) * columns + jn};
          cells.push_back(cell);
        }
      coarse.create_triangulation(vertices, cells, SubCellData());
      const double mid = 0.5 * (p.ring_inner_radius + p.ring_outer_radius);
      const double tol = 1e-8 * p.ring_outer_radius;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
          {
            const Tensor<1, 2> x = face->center() - p.ring_center;
            // a cut edge is radial: its centre lies on the ray at angle 0 or at the sector angle
            const Tensor<1, 2> end({std::cos(sector), std::sin(sector)});
            if (!full && std::abs(x[1]) < tol && x[0] > 0.)
              face->set_boundary_id(2);
            else if (!full && std::abs(x[0] * end[1] - x[1] * end[0]) < tol && x * end > 0.)
              face->set_boundary_id(3);
            else
              face->set_boundary_id(x.norm() < mid ? 0 : 1);
          }
    }

    void rectangle(const GeometryParameters &p, Triangulation<2> &coarse)
    {
      require(p.rectangle_cells.size() == 2, "Geometry/Rectangle/Cells", "needs two numbers");
      GridGenerator::subdivided_hyper_rectangle(
          coarse, p.rectangle_cells, p.lower_left, p.upper_right, /*colorize=*/true);
    }

    template <int dim>
    void mesh_file(const GeometryParameters &p, Triangulation<dim> &coarse)
    {
      // InputError "Geometry/Mesh file: cannot open '<file>': <why>" (FIFO, device, too large, ...)
      std::ifstream in = open_input_file(
          p.mesh_file, "Geometry/Mesh file: cannot open", file_size_limit::mesh_file);
      GridIn<dim> grid_in(coarse);
      try
      {
        const std::string ext = p.mesh_file.substr(p.mesh_file.find_last_of('.') + 1);
        if (ext == "msh")
          grid_in.read_msh(in);
        else if (ext == "inp")
          grid_in.read_abaqus(in);
        else if (ext == "ucd")
          grid_in.read_ucd(in);
        else
          throw InputError("Geometry/Mesh file: '" + p.mesh_file
                           + "' must end in .msh (Gmsh), .inp (Abaqus) or .ucd (UCD)");
      }
      catch (const ExceptionBase &e)
      {
        const std::string format
            = p.mesh_file.size() > 4 && p.mesh_file.compare(p.mesh_file.size() - 4, 4, ".inp") == 0
                  ? " as an Abaqus input file"
                  : "";
        throw InputError("Geometry/Mesh file: cannot read '" + p.mesh_file + "'" + format + ": "
                         + user_message(e));
      }
    }

    /** `Geometry/Type = block`: colorized box (ids 0..5 on x_min, x_max, y_min, ..., z_max). */
    void block(const GeometryParameters &p, Triangulation<3> &coarse)
    {
      require(p.block_cells.size() == 3, "Geometry/Block/Cells", "needs three numbers");
      GridGenerator::subdivided_hyper_rectangle(
          coarse, p.block_cells, p.block_lower, p.block_upper, /*colorize=*/true);
    }

    /** Coordinates 0, h/n, ..., h of the planes between @p layers layers over @p height. */
    std::vector<double> slices(const double height, const unsigned int layers)
    {
      std::vector<double> z(layers + 1);
      for (unsigned int i = 0; i <= layers; ++i)
        z[i] = height * i / double(layers);
      return z;
    }

    /**
     * `Geometry/Type = quarter cylinder`: deal.II's three-cell quarter disk (x, y >= 0) extruded
     * along z. Manifold ids: 1 on the mantle (faces and their lines), 2 (transfinite) on the two
     * cells next to it, flat on the central cell. Boundary ids: see boundary_ids_3d.
     */
    void quarter_cylinder(const GeometryParameters &p, Triangulation<3> &coarse)
    {
      Triangulation<2> section;
      GridGenerator::quarter_hyper_ball(section, Point<2>(), p.cylinder_radius);
      const double tol = 1e-8 * p.cylinder_radius;
      section.set_all_manifold_ids(numbers::flat_manifold_id);
      const auto on_arc = [&](const auto &face)
      {
        for (const unsigned int v : face->vertex_indices())
          if (std::abs(face->vertex(v).norm() - p.cylinder_radius) > tol)
            return false;
        return true;
      };
      for (const auto &cell : section.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && on_arc(face))
            cell->set_all_manifold_ids(2);
      for (const auto &cell : section.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && on_arc(face))
            face->set_manifold_id(1);
      GridGenerator::extrude_triangulation(section,
                                           slices(p.cylinder_length, p.cylinder_layers),
                                           coarse,
                                           /*copy_manifold_ids=*/true,
                                           {1, numbers::flat_manifold_id, 2});
      namespace ids = boundary_ids_3d::quarter_cylinder;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
          {
            const Point<3> c = face->center();
            face->set_boundary_id(std::abs(c[2]) < tol                       ? ids::bottom
                                  : std::abs(c[2] - p.cylinder_length) < tol ? ids::top
                                  : std::abs(c[0]) < tol                     ? ids::symmetry_x
                                  : std::abs(c[1]) < tol                     ? ids::symmetry_y
                                                                             : ids::mantle);
          }
    }

    /**
     * `Geometry/Type = thick ring`: the `Ring` annulus (or sector) extruded over
     * 0 <= z <= Thickness / 2. Boundary ids: 0 bore, 1 rim (from 2D), 2 side face, 3 symmetry
     * face z = 0, a sector's cut faces 4 (angle 0) and 5 (the sector angle).
     */
    void thick_ring(const GeometryParameters &p, Triangulation<3> &coarse)
    {
      Triangulation<2> section;
      ring(p, section);
      const double half = 0.5 * p.ring_thickness;
      GridGenerator::extrude_triangulation(section, slices(half, p.ring_layers), coarse);
      const double tol = 1e-8 * half;
      namespace ids = boundary_ids_3d::thick_ring;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
          {
            const double z = face->center()[2];
            if (std::abs(z) < tol)
              face->set_boundary_id(ids::symmetry);
            else if (std::abs(z - half) < tol)
              face->set_boundary_id(ids::side);
            else if (face->boundary_id() == 2) // a sector's cut faces (2D ids 2, 3)
              face->set_boundary_id(ids::cut_start);
            else if (face->boundary_id() == 3)
              face->set_boundary_id(ids::cut_end);
          }
    }

    /** Manifolds of the quarter cylinder: cylindrical on the mantle, transfinite next to it. */
    void attach_cylinder_manifolds(Triangulation<3> &tria)
    {
      tria.set_manifold(1, CylindricalManifold<3>(Tensor<1, 3>({0., 0., 1.}), Point<3>()));
      TransfiniteInterpolationManifold<3> transfinite;
      transfinite.initialize(tria);
      tria.set_manifold(2, transfinite);
    }
  } // namespace

  namespace
  {
    /**
     * Lower-right quarter of a disk: x >= x_c, y <= y_c. Built from deal.II's three-cell quarter
     * ball rotated by -90 degrees. Boundary ids: 0 arc, 1 top edge (y = y_c), 2 axis (x = x_c).
     */
    void quarter_disk(const GeometryParameters &p, Triangulation<2> &coarse)
    {
      require(p.disk_radius > 0., "Geometry/Quarter disk/Radius", "must be positive");
      GridGenerator::quarter_hyper_ball(coarse, Point<2>(), p.disk_radius);
      const Point<2> c = p.disk_center;
      GridTools::transform([c](const Point<2> &x) { return Point<2>(c[0] + x[1], c[1] - x[0]); },
                           coarse);
      const double tol = 1e-8 * p.disk_radius;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
          {
            const Point<2> m = face->center();
            if (std::abs(m[1] - c[1]) < tol)
              face->set_boundary_id(1);
            else if (std::abs(m[0] - c[0]) < tol)
              face->set_boundary_id(2);
            else
              face->set_boundary_id(0);
          }
    }

    /** Manifolds of the quarter disk: polar on the arc, transfinite in the cells next to it. */
    template <int dim>
    void attach_disk_manifolds(const GeometryParameters &p, Triangulation<dim> &tria)
    {
      if constexpr (dim == 2)
      {
        tria.set_all_manifold_ids(numbers::flat_manifold_id);
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == 0)
            {
              cell->set_all_manifold_ids(2);
              face->set_manifold_id(1);
            }
        tria.set_manifold(1, PolarManifold<2>(p.disk_center));
        TransfiniteInterpolationManifold<2> transfinite;
        transfinite.initialize(tria);
        tria.set_manifold(2, transfinite);
      }
    }

    /** Refine towards `Refinement point`: level k refines cells closer than radius / 2^k. */
    template <int dim>
    void refine_towards_point(const GeometryParameters &p, Triangulation<dim> &tria)
    {
      if (p.refinement_radius <= 0. || p.local_refinements == 0)
        return;
      Point<dim> target;
      for (int d = 0; d < std::min(dim, 2); ++d)
        target[d] = p.refinement_point[d];
      double radius = p.refinement_radius;
      for (unsigned int level = 0; level < p.local_refinements;
           ++level, radius *= p.refinement_radius_factor)
      {
        double flagged = 0.;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned()
              && cell->center().distance(target) < radius + 0.5 * cell->diameter())
          {
            cell->set_refine_flag();
            ++flagged;
          }
        // the cells after this level, counted before they are made
        const double after
            = tria.n_global_active_cells()
              + Utilities::MPI::sum(flagged, tria.get_communicator()) * ((1u << dim) - 1);
        if (after > max_cells)
        {
          std::ostringstream msg;
          msg << "Geometry/Local refinements: level " << level + 1 << " of " << p.local_refinements
              << " would give " << after << " cells, more than ausroll accepts (" << max_cells
              << "); use fewer Local refinements, a smaller Refinement radius or a smaller "
                 "Refinement radius factor";
          throw InputError(msg.str());
        }
        tria.execute_coarsening_and_refinement();
      }
    }
  } // namespace

  template <int dim>
  void create_workpiece(const GeometryParameters                  &parameters,
                        Triangulation<dim>                        &triangulation,
                        const bool                                 refine,
                        const std::function<void(double n_cells)> &check_cells)
  {
    // Coarse cells from the entries, bounded before anything is allocated.
    {
      double      n = 0.;
      std::string entries;
      switch (parameters.type)
      {
        case WorkpieceType::quarter_ring:
          n = double(parameters.radial_cells) * parameters.angular_cells;
          entries = "Geometry/Quarter ring/Radial cells x Angular cells";
          break;
        case WorkpieceType::ring:
          n = double(parameters.ring_cells_around) * parameters.ring_cells_radially;
          entries = "Geometry/Ring/Cells around x Cells radially";
          break;
        case WorkpieceType::rectangle:
          n = 1.;
          for (const unsigned int c : parameters.rectangle_cells)
            n *= c;
          entries = "Geometry/Rectangle/Cells";
          break;
        case WorkpieceType::block:
          n = 1.;
          for (const unsigned int c : parameters.block_cells)
            n *= c;
          entries = "Geometry/Block/Cells";
          break;
        case WorkpieceType::quarter_cylinder:
          n = 3. * parameters.cylinder_layers;
          entries = "Geometry/Quarter cylinder/Layers";
          break;
        case WorkpieceType::thick_ring:
          n = double(parameters.ring_cells_around) * parameters.ring_cells_radially
              * parameters.ring_layers;
          entries = "Geometry/Ring/Cells around x Cells radially x Geometry/Thick ring/Layers";
          break;
        case WorkpieceType::extruded_gear_tooth:
          n = 100. * parameters.gear_tooth.teeth * parameters.gear_layers; // <= 56 per tooth
          entries = "Geometry/Gear tooth/Teeth x Geometry/Extruded gear tooth/Layers";
          break;
        default:
          break;
      }
      if (n > max_coarse_cells)
        throw InputError(entries + ": " + std::to_string(static_cast<long long>(n))
                         + " coarse cells is more than ausroll accepts ("
                         + std::to_string(static_cast<long long>(max_coarse_cells))
                         + "); use fewer coarse cells and Geometry/Global refinements");
    }
    parameters.require_dimension(dim);
    Triangulation<dim> coarse;
    if (parameters.type == WorkpieceType::mesh_file)
      mesh_file(parameters, coarse);
    else if constexpr (dim == 2)
    {
      if (parameters.type == WorkpieceType::quarter_ring)
        quarter_ring(parameters, coarse);
      else if (parameters.type == WorkpieceType::quarter_disk)
        quarter_disk(parameters, coarse);
      else if (parameters.type == WorkpieceType::gear_tooth)
        create_gear_tooth_mesh(parameters.gear_tooth, coarse);
      else if (parameters.type == WorkpieceType::ring)
        ring(parameters, coarse);
      else
        rectangle(parameters, coarse);
    }
    else
    {
      if (parameters.type == WorkpieceType::block)
        block(parameters, coarse);
      else if (parameters.type == WorkpieceType::quarter_cylinder)
        quarter_cylinder(parameters, coarse);
      else if (parameters.type == WorkpieceType::thick_ring)
        thick_ring(parameters, coarse);
      else
        create_extruded_gear_tooth_mesh(parameters.gear_tooth,
                                        0.5 * parameters.gear_face_width,
                                        parameters.gear_layers,
                                        coarse,
                                        parameters.gear_layer_ratio);
    }

    triangulation.copy_triangulation(coarse);
    if constexpr (dim == 2)
    {
      if (parameters.type == WorkpieceType::quarter_ring)
      {
        triangulation.set_all_manifold_ids(1);
        triangulation.set_manifold(1, PolarManifold<2>(Point<2>()));
      }
      if (parameters.type == WorkpieceType::quarter_disk)
        attach_disk_manifolds(parameters, triangulation);
      if (parameters.type == WorkpieceType::gear_tooth)
        attach_gear_tooth_manifolds(parameters.gear_tooth, triangulation);
      if (parameters.type == WorkpieceType::ring)
      {
        // Polar manifold (periodic in the angle) on every cell: refined points lie on circles.
        triangulation.set_all_manifold_ids(1);
        triangulation.set_manifold(1, PolarManifold<2>(parameters.ring_center));
      }
    }
    else
    {
      if (parameters.type == WorkpieceType::quarter_cylinder)
        attach_cylinder_manifolds(triangulation);
      if (parameters.type == WorkpieceType::thick_ring)
      {
        // cylindrical manifold about the ring axis on every cell: bore and rim stay circles
        triangulation.set_all_manifold_ids(1);
        const Point<3> c(parameters.ring_center[0], parameters.ring_center[1], 0.);
        triangulation.set_manifold(1, CylindricalManifold<3>(Tensor<1, 3>({0., 0., 1.}), c));
      }
      if (parameters.type == WorkpieceType::extruded_gear_tooth)
        attach_extruded_gear_tooth_manifolds(parameters.gear_tooth, triangulation);
    }
    const double estimate = double(triangulation.n_cells())
                            * std::pow(double(1u << dim), parameters.global_refinements);
    if (estimate > max_cells)
    {
      std::ostringstream msg;
      msg << "Geometry/Global refinements: " << parameters.global_refinements
          << " refinements of the " << triangulation.n_cells() << " coarse cells give " << estimate
          << " cells, more than ausroll accepts (" << max_cells
          << "); use fewer refinements or coarse cells";
      throw InputError(msg.str());
    }
    if (!refine)
      return;
    if (check_cells)
      check_cells(estimate);
    triangulation.refine_global(parameters.global_refinements);
    refine_towards_point(parameters, triangulation);
  }

  void require_dof_estimate(const double n_cells, const unsigned int degree, const unsigned int dim)
  {
    const double estimate = n_cells * std::pow(double(degree), double(dim)) * dim;
    if (estimate > max_dofs)
    {
      std::ostringstream msg;
      msg << "Model/Polynomial degree: " << n_cells << " cells of degree " << degree
          << " give about " << estimate << " unknowns, more than ausroll accepts (" << max_dofs
          << "); lower the degree or Geometry/Global refinements / Local refinements";
      throw InputError(msg.str());
    }
  }

  template <int dim>
  void require_boundary_ids(const Triangulation<dim>        &triangulation,
                            const std::vector<unsigned int> &ids,
                            const std::string               &entry)
  {
    const std::vector<types::boundary_id> present = triangulation.get_boundary_ids();
    for (const unsigned int id : ids)
      if (std::find(present.begin(), present.end(), id) == present.end())
      {
        std::string list;
        for (const auto p : present)
          list += (list.empty() ? "" : ", ") + std::to_string(p);
        throw InputError(entry + ": the workpiece has no boundary with id " + std::to_string(id)
                         + " (its boundary ids: " + list + "; see Geometry/Type)");
      }
  }

  template <int dim>
  void require_off_axis(const Triangulation<dim> &triangulation, const std::string &entry)
  {
    const auto   box = GridTools::compute_bounding_box(triangulation);
    const double x_min = box.get_boundary_points().first[0];
    const double size = box.get_boundary_points().first.distance(box.get_boundary_points().second);
    if (x_min < -1e-9 * size)
    {
      std::ostringstream msg;
      msg << entry << ": the workpiece reaches x = " << x_min
          << " mm, but x is the radius of an axisymmetric body (the axis is x = 0): move the "
             "workpiece (Geometry) to x >= 0";
      throw InputError(msg.str());
    }
  }

  template void require_boundary_ids<2>(const Triangulation<2> &,
                                        const std::vector<unsigned int> &,
                                        const std::string &);
  template void require_boundary_ids<3>(const Triangulation<3> &,
                                        const std::vector<unsigned int> &,
                                        const std::string &);
  template void require_off_axis<2>(const Triangulation<2> &, const std::string &);
  template void require_off_axis<3>(const Triangulation<3> &, const std::string &);
  template void create_workpiece<2>(const GeometryParameters &,
                                    Triangulation<2> &,
                                    const bool,
                                    const std::function<void(double)> &);
  template void create_workpiece<3>(const GeometryParameters &,
                                    Triangulation<3> &,
                                    const bool,
                                    const std::function<void(double)> &);
} // namespace ausroll::geometry
