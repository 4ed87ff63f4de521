/**
 * @file gear_tooth_mesh.h
 * `Geometry/Type = gear tooth`: coarse quadrilateral mesh of one involute gear tooth (or of a
 * sector of teeth) with its rim, and the manifolds that keep refined boundary vertices on the
 * exact tooth outline.
 *
 * Domain: the sector between the middles of the tooth spaces on either side of the tooth
 * (polar angles axis -/+ pi/z about the gear centre, which is the origin), bounded outside by the
 * tooth outline (root land, root fillet, involute or radial flank, tip land) and inside by the
 * arc of radius r_i = root radius - `Rim thickness`.
 *
 * Boundary ids: 0 tooth outline (candidate contact surface), 1 inner arc, 2 side cuts (radial
 * lines through the middles of the outer tooth spaces). With `Fix root = true` the side cuts get
 * id 1 as well, so that fixing id 1 clamps the whole rim (see GearToothParameters::fix_root).
 *
 * Manifold ids: 1 circles about the gear centre (root and tip lands, inner arc), 2 transfinite
 * interpolation of the interior, 10 + 10 k + {0, 1} positive / negative flank of tooth k
 * (FlankManifold), 10 + 10 k + {2, 3} positive / negative root fillet (circle about the fillet
 * centre).
 */
#pragma once

#include <ausroll/geometry/gear_entries.h>
#include <ausroll/geometry/involute_gear.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

namespace ausroll::geometry
{
  /** Boundary ids of the gear tooth mesh. */
  namespace gear_tooth_ids
  {
    /** Tooth outline: root land, fillet, flank, tip land. */
    constexpr unsigned int outline = 0;
    /** Inner arc of radius root radius - Rim thickness. */
    constexpr unsigned int inner_arc = 1;
    /** Radial side cuts through the middle of the outer tooth spaces. */
    constexpr unsigned int side_cuts = 2;
  } // namespace gear_tooth_ids

  /**
   * Parameters of subsection `Geometry/Gear tooth` (used when `Geometry/Type = gear tooth`).
   * Defaults: the workpiece gear of the NOFEAP thesis, section 4.4 (31 teeth, DP 8.5, PA 22
   * degrees, pitch thickness 0.1848" = half the circular pitch).
   */
  struct GearToothParameters
  {
    /** The gear size entries (`Number of teeth` z of the whole gear, `Diametral pitch`,
        `Module`, `Pressure angle`, `Addendum`, `Dedendum`; gear_entries.h). */
    GearSize size{31};
    double   tooth_thickness = -1.; ///< `Tooth thickness` at the pitch circle (mm; < 0: half pitch)
    double   root_fillet_radius = 0.; ///< `Root fillet radius` (mm)
    double   rim_thickness = -1.; ///< `Rim thickness` below the root circle (mm; < 0: whole depth)
    double   tooth_axis_angle = 90.; ///< `Tooth axis angle` of the middle of the sector (deg)
    unsigned int teeth = 1;          ///< `Teeth` in the meshed sector
    bool         fix_root = false;   ///< `Fix root`: side cuts get the inner arc's id 1

    /**
     * One more than the most `Teeth` a sector may have: half the gear (a sector is bounded by two
     * radial cuts; a whole gear has none and its manifolds fail).
     */
    unsigned int max_sector_teeth() const { return size.teeth / 2 + 1; }

    /** Declare subsection `Gear tooth` (call inside subsection `Geometry`). */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Gear tooth` (inside `Geometry`); throws InputError for bad values. */
    void parse_parameters(dealii::ParameterHandler &prm);

    /** The gear described by these parameters (throws InputError naming the entries). */
    InvoluteGear gear() const;
    /** Inner arc radius r_i = root radius - rim thickness (mm). */
    double inner_radius() const;
    /** Polar angle (rad) of the axis of tooth @p k of the sector (k = 0 .. teeth - 1). */
    double axis_angle(unsigned int k) const;
  };

  /**
   * Build the coarse mesh of the tooth sector into the empty @p coarse: vertices on the exact
   * outline, boundary ids and manifold ids as documented in this file. Every half tooth has 4 rows
   * of 2 cells above the fillet start and up to 4 columns (below the tooth, under the fillet,
   * under the root land) of rows growing by 1.6 towards the inner arc in the rim (56 cells per
   * tooth for the thesis gear with a fillet).
   */
  void create_gear_tooth_mesh(const GearToothParameters &parameters,
                              dealii::Triangulation<2>  &coarse);

  /**
   * Attach the manifold objects to @p tria (a copy of the coarse mesh made by
   * create_gear_tooth_mesh(), possibly distributed); must be called on the final triangulation
   * because the transfinite interpolation refers to it.
   */
  void attach_gear_tooth_manifolds(const GearToothParameters &parameters,
                                   dealii::Triangulation<2>  &tria);

  /**
   * `Geometry/Type = extruded gear tooth`: the coarse tooth sector of create_gear_tooth_mesh()
   * extruded along z over 0 <= z <= @p half_width in @p layers layers of cells, into the empty
   * @p coarse; the layer thicknesses form a geometric progression whose last (face end) over
   * first (symmetry face) thickness is @p layer_ratio (1: uniform layers). Boundary ids: the 2D ids
   * on the lateral faces (0 outline, 1 inner arc, 2 side cuts), 3 face end z = @p half_width, 4
   * symmetry face z = 0. Manifold ids as in 2D on the cells (2 transfinite), on the lateral faces
   * and on the lines in the planes z = const (the 2D line ids); lines along z take the first of: a
   * flank or fillet id, 1, flat, 2.
   */
  void create_extruded_gear_tooth_mesh(const GearToothParameters &parameters,
                                       double                     half_width,
                                       unsigned int               layers,
                                       dealii::Triangulation<3>  &coarse,
                                       double                     layer_ratio = 1.);

  /**
   * The 3D manifolds of the extruded tooth on @p tria (a copy of the coarse mesh made by
   * create_extruded_gear_tooth_mesh()): 1 CylindricalManifold about the z axis, flanks
   * ExtrudedFlankManifold, fillets CylindricalManifold about the fillet centre line, 2
   * transfinite interpolation (call on the final triangulation).
   */
  void attach_extruded_gear_tooth_manifolds(const GearToothParameters &parameters,
                                            dealii::Triangulation<3>  &tria);
} // namespace ausroll::geometry
