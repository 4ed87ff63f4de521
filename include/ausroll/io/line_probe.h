/**
 * @file line_probe.h
 * Fields sampled along straight lines, written as CSV (`Postprocess/Line probes`).
 */
#pragma once

#include <ausroll/mechanics/material_point_storage.h>
#include <ausroll/mechanics/quadrature_interpolation.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace ausroll::io
{
  /** Most points of one line probe (`Postprocess/Line probes`). */
  constexpr unsigned int max_probe_points = 1000000;

  /** One line of `Postprocess/Line probes` as written: "name: x0, y0[, z0], x1, y1[, z1], n". */
  struct LineProbeSpecification
  {
    std::string         name;     ///< a label (core's require_label())
    std::vector<double> start;    ///< dim coordinates
    std::vector<double> end;      ///< dim coordinates
    unsigned int        n_points; ///< 2 to max_probe_points
    /** A unit normal of the surface the line starts on (dim entries; a depth probe), or empty.
        With it the stress is also written in the frame of that surface (stress_nn, ...). */
    std::vector<double> normal;
  };

  /** One line of `Postprocess/Depth probes` as written: "name: x, y[, z], depth, n". */
  struct DepthProbeSpecification
  {
    std::string         name;     ///< a label (core's require_label())
    std::vector<double> point;    ///< dim coordinates: a point at or near the surface
    double              depth;    ///< length of the probe below the surface (mm, > 0)
    unsigned int        n_points; ///< 2 to max_probe_points
  };

  /**
   * Parse `Postprocess/Depth probes` for @p dim dimensions without allocating any sample:
   * InputError naming the entry for a malformed item, a bad or repeated name (also one used by a
   * line probe, @p line_probe_names), a depth that is not positive, or more than
   * max_probe_points points.
   */
  std::vector<DepthProbeSpecification>
  parse_depth_probes(const std::string              &specification,
                     unsigned int                    dim,
                     const std::vector<std::string> &line_probe_names = {});

  /**
   * Parse `Postprocess/Line probes` for @p dim dimensions without allocating any sample:
   * InputError naming the entry for a malformed item, a bad or repeated name, or more than
   * max_probe_points points (the set-up's memory estimate counts the points before the probes
   * are built).
   */
  std::vector<LineProbeSpecification> parse_line_probes(const std::string &specification,
                                                        unsigned int       dim);

  /**
   * Samples displacement (FE interpolation) and Cauchy stress and equivalent plastic strain
   * (Lagrange interpolation of the material points of the containing cell) at equally spaced
   * points of straight lines in the reference configuration. Each output writes
   * `<dir>/probe_<name>_NNNN.csv` with columns
   * `time,s,x,y,ux,uy,stress_xx,stress_yy,stress_zz,stress_xy,von_mises_stress,equivalent_plastic_strain`
   * (3D: z and uz after y and uy), then (3D) `stress_xz,stress_yz` and the strain tensor
   * `strain_xx,strain_yy,strain_zz,strain_xy` (3D: `strain_xz,strain_yz`; see
   * postprocess::strain_tensor()); s = distance from the line's start; lengths in mm, stresses in
   * MPa, strains dimensionless.
   * Set by `Postprocess/Line probes` = "name: x0, y0, x1, y1, n; ...".
   */
  template <int dim>
  class LineProbes
  {
  public:
    /** Probes described by @p specification; InputError names `Postprocess/Line probes`. */
    LineProbes(const std::string &specification, const unsigned int n_q_points_1d);
    /**
     * Probes @p lines (made elsewhere: the depth probes), written as `<prefix>_<name>_NNNN.csv`;
     * InputError names @p entry.
     */
    LineProbes(const std::vector<LineProbeSpecification> &lines,
               const unsigned int                         n_q_points_1d,
               const std::string                         &entry,
               const std::string                         &prefix);

    /** Locate the sample points in the mesh (call after every mesh change). */
    void locate(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler);

    /** Write every probe for output number @p counter at pseudo-time @p time into @p directory
        (@p small_strain: the model's kinematics, for the strain measure; @p state_columns: also
        the material points' temperature, martensite and bainite fractions and carbon content,
        for thermal scenes). */
    void write(const std::string                           &directory,
               const unsigned int                           counter,
               const double                                 time,
               const dealii::Mapping<dim>                  &mapping,
               const dealii::DoFHandler<dim>               &dof_handler,
               const dealii::TrilinosWrappers::MPI::Vector &solution,
               const mechanics::MaterialPointStorage<dim>  &material_points,
               const bool                                   small_strain,
               const bool                                   state_columns = false) const;

    /** True if no probe is defined. */
    bool empty() const { return probes.empty(); }

  private:
    struct Sample
    {
      dealii::Point<dim>                                     position;
      bool                                                   local = false;
      typename dealii::DoFHandler<dim>::active_cell_iterator cell;
      dealii::Point<dim>                                     unit_point;
    };
    struct Probe
    {
      std::string          name;
      dealii::Point<dim>   start, end;
      std::vector<Sample>  samples;
      bool                 framed = false; ///< the stress also in the surface frame
      dealii::Tensor<1, 3> n, t, w;        ///< that frame: normal, tangents (3D: t in x-y)
    };
    std::vector<Probe>                      probes;
    std::string                             entry;  ///< the entry named in messages
    std::string                             prefix; ///< file name prefix: probe or depth
    mechanics::QuadratureInterpolation<dim> interpolation;
  };
} // namespace ausroll::io
