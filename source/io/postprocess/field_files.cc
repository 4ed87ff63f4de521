#include <ausroll/geometry/boundary_depth.h>
#include <ausroll/io/postprocess/field_files.h>
#include <ausroll/io/postprocess/standard_set.h>

#include <deal.II/dofs/dof_tools.h>

#include <iomanip>
#include <sstream>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  template <int dim>
  LineProbeFiles<dim>::LineProbeFiles(const std::string &specification,
                                      const unsigned int n_q_points_1d)
      : probes(specification, n_q_points_1d)
  {
  }

  template <int dim>
  void LineProbeFiles<dim>::initialize(const PostprocessInput<dim> &input)
  {
    probes.locate(input.mapping, input.dof_handler);
  }

  template <int dim>
  void LineProbeFiles<dim>::write_files(const PostprocessInput<dim> &input,
                                        const std::string           &directory,
                                        const unsigned int           counter)
  {
    probes.write(directory,
                 counter,
                 input.time,
                 input.mapping,
                 input.dof_handler,
                 input.solution,
                 input.material_points,
                 input.model.is_small_strain(),
                 input.thermal != nullptr);
  }

  template <int dim>
  DepthProbeFiles<dim>::DepthProbeFiles(const PostprocessParameters &parameters,
                                        const unsigned int           n_q_points_1d)
      : specifications(parse_depth_probes(parameters.depth_probes, dim))
      , boundaries(parameters.depth_probe_boundaries)
      , n_q_points_1d(n_q_points_1d)
  {
  }

  template <int dim>
  void DepthProbeFiles<dim>::initialize(const PostprocessInput<dim> &input)
  {
    if (!probes)
    {
      // the lines, once: from the nearest point of the initial outline along its normal (the
      // coarse cells and their manifolds are the initial outline on every rank)
      const Triangulation<dim> &triangulation = input.dof_handler.get_triangulation();
      std::vector<unsigned int> ids = boundaries;
      if (ids.empty())
        for (const types::boundary_id id : triangulation.get_boundary_ids())
          ids.push_back(id);
      const geometry::BoundaryDepth<dim> outline(
          triangulation, ids, "Postprocess/Depth probe boundaries");
      std::vector<LineProbeSpecification> lines;
      for (const DepthProbeSpecification &d : specifications)
      {
        Point<dim> p;
        for (unsigned int k = 0; k < dim; ++k)
          p[k] = d.point[k];
        const auto             foot = outline.nearest(p);
        LineProbeSpecification line;
        line.name = d.name;
        line.n_points = d.n_points;
        for (unsigned int k = 0; k < dim; ++k)
        {
          line.start.push_back(foot.point[k]);
          line.end.push_back(foot.point[k] + d.depth * foot.inward_normal[k]);
          line.normal.push_back(foot.inward_normal[k]);
        }
        lines.push_back(line);
      }
      probes = std::make_unique<LineProbes<dim>>(
          lines, n_q_points_1d, "Postprocess/Depth probes", "depth");
    }
    probes->locate(input.mapping, input.dof_handler);
  }

  template <int dim>
  void DepthProbeFiles<dim>::write_files(const PostprocessInput<dim> &input,
                                         const std::string           &directory,
                                         const unsigned int           counter)
  {
    probes->write(directory,
                  counter,
                  input.time,
                  input.mapping,
                  input.dof_handler,
                  input.solution,
                  input.material_points,
                  input.model.is_small_strain(),
                  input.thermal != nullptr);
  }

  template <int dim>
  BoundaryProfileFiles<dim>::BoundaryProfileFiles(const BoundaryProfileParameters &parameters)
      : profile(parameters)
  {
  }

  template <int dim>
  void BoundaryProfileFiles<dim>::write_files(const PostprocessInput<dim> &input,
                                              const std::string           &directory,
                                              const unsigned int           counter)
  {
    profile.write(directory, counter, input.time, input.mapping, input.dof_handler, input.solution);
  }

  template <int dim>
  void ContactFiles<dim>::write_files(const PostprocessInput<dim> &input,
                                      const std::string           &directory,
                                      const unsigned int           counter)
  {
    written = input.contact.active();
    if (!written)
      return;
    const MPI_Comm     comm = input.dof_handler.get_communicator();
    std::ostringstream name;
    name << directory << "/contact_" << std::setw(4) << std::setfill('0') << counter << ".csv";
    input.contact.write_csv(name.str(), comm);

    const IndexSet owned = input.dof_handler.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(input.dof_handler);
    TrilinosWrappers::MPI::Vector owned_a(owned, comm), owned_b(owned, comm);
    input.contact.fill_output_vectors(owned_a, owned_b);
    pressure_traction.reinit(owned, relevant, comm);
    status_gap.reinit(owned, relevant, comm);
    pressure_traction = owned_a;
    status_gap = owned_b;
  }

  template <int dim>
  void ContactFiles<dim>::nodal_fields(std::vector<NodalField> &fields) const
  {
    if (!written)
      return;
    fields.emplace_back(std::vector<std::string>{"contact_pressure", "contact_traction"},
                        &pressure_traction);
    fields.emplace_back(std::vector<std::string>{"contact_status", "contact_gap"}, &status_gap);
  }

  template <int dim>
  Unit ContactFiles<dim>::unit(const std::string &name) const
  {
    if (name == "contact_gap")
      return {"length", "mm"};
    if (name == "contact_status")
      return {"code", "1"};
    return {"stress", "MPa"}; // contact_pressure, contact_traction
  }

  template class LineProbeFiles<2>;
  template class DepthProbeFiles<2>;
  template class BoundaryProfileFiles<2>;
  template class ContactFiles<2>;
  template class LineProbeFiles<3>;
  template class DepthProbeFiles<3>;
  template class BoundaryProfileFiles<3>;
  template class ContactFiles<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_line_probe_files(const PostprocessorContext &c)
    {
      return std::make_unique<LineProbeFiles<dim>>(c.postprocess.line_probes, c.quadrature_points);
    }

    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_depth_probe_files(const PostprocessorContext &c)
    {
      if (c.postprocess.depth_probes.find_first_not_of(" \t\n") == std::string::npos)
        return nullptr;
      return std::make_unique<DepthProbeFiles<dim>>(c.postprocess, c.quadrature_points);
    }

    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_boundary_profile_files(const PostprocessorContext &c)
    {
      return std::make_unique<BoundaryProfileFiles<dim>>(c.postprocess.boundary_profile);
    }

    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_contact_files(const PostprocessorContext &)
    {
      return std::make_unique<ContactFiles<dim>>();
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_line_probe_files,
                               "line probes",
                               70,
                               "fields along the Line probes, one file per output")

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_depth_probe_files,
                               "depth probes",
                               75,
                               "fields along the Depth probes, normal to the initial surface, one "
                               "file per output")

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_boundary_profile_files,
                               "boundary profile",
                               80,
                               "the deformed boundary profile, one file per output")

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_contact_files,
                               "contact nodes",
                               90,
                               "the contact nodes and their statuses, one file per output")
