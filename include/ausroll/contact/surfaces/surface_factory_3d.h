/**
 * @file surface_factory_3d.h
 * Parameters and factory of the 3D rigid surfaces: one plain struct per `.prm` subsection
 * (`Plane`, `Cylinder`, `Torus`, `Revolved profile`, `Extruded profile`; the last two with a
 * nested `Profile` subsection describing the 2D chain), each with declare/parse and a create().
 *
 * The subsections are declared inside whatever subsection the caller has entered (e.g.
 * `Contact/Die 0`); parse_parameters() takes that subsection's full path with a trailing slash
 * (e.g. "Contact/Die 0/") so that every InputError names the full entry path, e.g.
 * "Contact/Die 0/Cylinder/Edge radius: must lie in [0, min(Radius, Width / 2)]".
 * All coordinates are in the die's local frame (the die's pose maps them to global coordinates).
 */
#pragma once

#include <ausroll/contact/die_surface.h>
#include <ausroll/contact/rigid_surface.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace ausroll::contact::surfaces
{
  /** The 2D chain of a revolved or extruded profile (subsection `Profile`). */
  struct ProfileParameters
  {
    /** `Type` of the chain. */
    enum class Type
    {
      polyline,     ///< straight segments through `Points`
      arc_line,     ///< polygon through `Points` with tangent fillets (`Fillet radii`)
      circle,       ///< full circle (`Center`, `Radius`, `Material inside`)
      involute_gear ///< external gear die (extruded profile only: a spur-gear die)
    };
    Type                          type = Type::polyline; ///< `Type`
    std::vector<dealii::Point<2>> points;                ///< `Points`
    std::string                   points_file;    ///< `Points file` (resolved; read by create())
    std::vector<double>           fillet_radii;   ///< `Fillet radii`
    bool                          closed = false; ///< `Closed`
    bool                          extend_ends = false;     ///< `Extend ends`
    dealii::Point<2>              center;                  ///< `Center`
    double                        radius = 1.;             ///< `Radius`
    bool                          material_inside = true;  ///< `Material inside`
    unsigned int                  teeth = 20;              ///< `Number of teeth`
    double                        diametral_pitch = 0.;    ///< `Diametral pitch` (0: Module)
    double                        module = 1.;             ///< `Module`
    double                        pressure_angle = 20.;    ///< `Pressure angle` (degrees)
    double                        addendum = -1.;          ///< `Addendum` (< 0: 1 module)
    double                        dedendum = -1.;          ///< `Dedendum` (< 0: 1.25 module)
    double                        tooth_thickness = -1.;   ///< `Tooth thickness` (< 0: half pitch)
    double                        root_fillet_radius = 0.; ///< `Root fillet radius`
    double                        tip_radius = 0.;         ///< `Tip radius`
    double                        tooth_axis_angle = 0.;   ///< `Tooth axis angle` (degrees)
    unsigned int                  sector_teeth = 0;        ///< `Teeth in sector` (0: whole gear)
    std::string                   path; ///< full path of the subsection (set by parse_parameters())

    /**
     * Declare subsection `Profile`; @p coordinates names the 2D coordinates for the help texts
     * ("r, z" or "x, y"); @p allow_gear offers Type = involute gear.
     */
    static void declare_parameters(dealii::ParameterHandler &prm,
                                   const std::string        &coordinates,
                                   bool                      allow_gear);
    /** Read subsection `Profile`; @p parent_path is the enclosing path ("…/Revolved profile/"). */
    void parse_parameters(dealii::ParameterHandler &prm,
                          const std::string        &parent_path,
                          const std::string        &input_directory);
    /** Build the chain; InputError naming the entry if it cannot be built. */
    DieSurface create() const;
  };

  /** Subsection `Plane`. */
  struct PlaneParameters
  {
    dealii::Point<3>     point;              ///< `Point`
    dealii::Tensor<1, 3> normal;             ///< `Normal` (outward, towards the workpiece)
    dealii::Tensor<1, 3> first_tangent;      ///< `First tangent` (zero: chosen)
    double               half_length_1 = 0.; ///< `Half length 1` (0: infinite)
    double               half_length_2 = 0.; ///< `Half length 2` (0: infinite)
    std::string          path;               ///< full path of the subsection

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm, const std::string &parent_path);
    std::unique_ptr<RigidSurface<3>> create() const;
  };

  /** Subsection `Cylinder` (FiniteCylinder). */
  struct CylinderParameters
  {
    dealii::Point<3>     center;           ///< `Center` (mid-plane of the width)
    dealii::Tensor<1, 3> axis;             ///< `Axis`
    dealii::Tensor<1, 3> reference;        ///< `Reference direction` (theta = 0)
    double               radius = 1.;      ///< `Radius`
    double               width = 1.;       ///< `Width`
    double               edge_radius = 0.; ///< `Edge radius`
    std::string          path;             ///< full path of the subsection

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm, const std::string &parent_path);
    std::unique_ptr<RigidSurface<3>> create() const;
  };

  /** Subsection `Torus`. */
  struct TorusParameters
  {
    dealii::Point<3>     center;            ///< `Center`
    dealii::Tensor<1, 3> axis;              ///< `Axis`
    dealii::Tensor<1, 3> reference;         ///< `Reference direction` (theta = 0)
    double               major_radius = 2.; ///< `Major radius` R
    double               minor_radius = 1.; ///< `Minor radius` rho (face profile radius)
    std::string          path;              ///< full path of the subsection

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm, const std::string &parent_path);
    std::unique_ptr<RigidSurface<3>> create() const;
  };

  /** Subsection `Revolved profile`. */
  struct RevolvedProfileParameters
  {
    dealii::Point<3>     center;    ///< `Center`
    dealii::Tensor<1, 3> axis;      ///< `Axis`
    dealii::Tensor<1, 3> reference; ///< `Reference direction` (theta = 0)
    ProfileParameters    profile;   ///< subsection `Profile`, coordinates (r, z)
    std::string          path;      ///< full path of the subsection

    static void                      declare_parameters(dealii::ParameterHandler &prm);
    void                             parse_parameters(dealii::ParameterHandler &prm,
                                                      const std::string        &parent_path,
                                                      const std::string        &input_directory);
    std::unique_ptr<RigidSurface<3>> create() const;
  };

  /** Subsection `Extruded profile`. */
  struct ExtrudedProfileParameters
  {
    /** `Extent` along the axis. */
    enum class Extent
    {
      infinite,        ///< z unbounded
      finite,          ///< [Start z, End z], open ends
      finite_with_caps ///< [Start z, End z] closed by flat end caps
    };
    dealii::Point<3>     origin;                    ///< `Origin`
    dealii::Tensor<1, 3> axis;                      ///< `Axis` (extrusion direction)
    dealii::Tensor<1, 3> reference;                 ///< `Reference direction` (profile x)
    Extent               extent = Extent::infinite; ///< `Extent`
    double               z0 = 0.;                   ///< `Start z`
    double               z1 = 1.;                   ///< `End z`
    ProfileParameters    profile;                   ///< subsection `Profile`, coordinates (x, y)
    std::string          path;                      ///< full path of the subsection

    static void                      declare_parameters(dealii::ParameterHandler &prm);
    void                             parse_parameters(dealii::ParameterHandler &prm,
                                                      const std::string        &parent_path,
                                                      const std::string        &input_directory);
    std::unique_ptr<RigidSurface<3>> create() const;
  };

  /**
   * All five shape subsections (declared together) and a factory by shape name ("plane",
   * "cylinder", "torus", "revolved profile", "extruded profile"), for the caller that owns the
   * shape selection entry.
   */
  struct Surface3DParameters
  {
    PlaneParameters           plane;            ///< subsection `Plane`
    CylinderParameters        cylinder;         ///< subsection `Cylinder`
    TorusParameters           torus;            ///< subsection `Torus`
    RevolvedProfileParameters revolved_profile; ///< subsection `Revolved profile`
    ExtrudedProfileParameters extruded_profile; ///< subsection `Extruded profile`

    /** The shape names, '|'-separated, for a Patterns::Selection. */
    static std::string shape_names();
    static void        declare_parameters(dealii::ParameterHandler &prm);
    /** Read all five subsections (each is checked when its surface is created). */
    void parse_parameters(dealii::ParameterHandler &prm,
                          const std::string        &parent_path,
                          const std::string        &input_directory);
    /** The surface named @p shape (one of shape_names()); InputError naming the entry if invalid.
     */
    std::unique_ptr<RigidSurface<3>> create(const std::string &shape) const;
  };
} // namespace ausroll::contact::surfaces
