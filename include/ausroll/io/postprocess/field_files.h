/**
 * @file field_files.h
 * The CSV files written with every output: line probes, boundary profiles and the contact nodes
 * (with their VTU nodal fields).
 */
#pragma once

#include <ausroll/io/boundary_profile.h>
#include <ausroll/io/line_probe.h>
#include <ausroll/io/postprocess/interface.h>

#include <memory>
#include <vector>

namespace ausroll::io::postprocess
{
  /** `probe_<name>_NNNN.csv` of every `Postprocess/Line probes` line (columns: io::LineProbes). */
  template <int dim>
  class LineProbeFiles : public Postprocessor<dim>
  {
  public:
    /** Probes of @p specification; samples interpolate the material points of a Gauss rule with
        @p n_q_points_1d points per direction (`Model/Quadrature points`). */
    LineProbeFiles(const std::string &specification, const unsigned int n_q_points_1d);
    std::string name() const override { return "line probes"; }
    void        initialize(const PostprocessInput<dim> &input) override;
    void        write_files(const PostprocessInput<dim> &input,
                            const std::string           &directory,
                            const unsigned int           counter) override;

  private:
    LineProbes<dim> probes;
  };

  /**
   * `depth_<name>_NNNN.csv` of every `Postprocess/Depth probes` line: a line probe from the point
   * of the initial outline nearest to the given point along the inward normal there (found once,
   * on the coarse mesh's exact outline: geometry::BoundaryDepth), with the stress also in the
   * frame of the surface (columns: io::LineProbes).
   */
  template <int dim>
  class DepthProbeFiles : public Postprocessor<dim>
  {
  public:
    /** The probes of `Postprocess/Depth probes` in @p parameters (Gauss rule of @p n_q_points_1d
        points per direction). */
    DepthProbeFiles(const PostprocessParameters &parameters, const unsigned int n_q_points_1d);
    std::string name() const override { return "depth probes"; }
    void        initialize(const PostprocessInput<dim> &input) override;
    void        write_files(const PostprocessInput<dim> &input,
                            const std::string           &directory,
                            const unsigned int           counter) override;

  private:
    std::vector<DepthProbeSpecification> specifications;
    std::vector<unsigned int>            boundaries;
    unsigned int                         n_q_points_1d;
    std::unique_ptr<LineProbes<dim>>     probes; ///< made at the first initialize()
  };

  /** `profile_NNNN.csv` of `Postprocess/Boundary profile` (columns: io::BoundaryProfile). */
  template <int dim>
  class BoundaryProfileFiles : public Postprocessor<dim>
  {
  public:
    explicit BoundaryProfileFiles(const BoundaryProfileParameters &parameters);
    std::string name() const override { return "boundary profile"; }
    void        write_files(const PostprocessInput<dim> &input,
                            const std::string           &directory,
                            const unsigned int           counter) override;

  private:
    BoundaryProfile<dim> profile;
  };

  /**
   * With dies: `contact_NNNN.csv` (one row per candidate node that is closed or near a die:
   * `die,s,X,Y,x,y,gap,p_n,t_t,R_n,R_t,status`, see contact::ContactOperator::write_csv()) and the
   * VTU nodal fields `contact_pressure`, `contact_traction` (stress, MPa), `contact_status` (a
   * code, 1) and `contact_gap` (length, mm).
   */
  template <int dim>
  class ContactFiles : public Postprocessor<dim>
  {
  public:
    std::string name() const override { return "contact nodes"; }
    void        write_files(const PostprocessInput<dim> &input,
                            const std::string           &directory,
                            const unsigned int           counter) override;
    void        nodal_fields(std::vector<NodalField> &fields) const override;
    Unit        unit(const std::string &name) const override;

  private:
    bool                                  written = false; ///< vectors below hold the last output
    dealii::TrilinosWrappers::MPI::Vector pressure_traction, status_gap; ///< ghosted
  };
} // namespace ausroll::io::postprocess
