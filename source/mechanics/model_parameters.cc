#include <ausroll/core/exceptions.h>
#include <ausroll/mechanics/model_parameters.h>

#include <algorithm>

namespace ausroll::mechanics
{
  using namespace dealii;

  void ModelParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    prm.declare_entry(
        "Kinematics",
        "finite strain",
        Patterns::Selection("small strain|total Lagrangian|updated Lagrangian|finite strain"),
        "Kinematic description: 'small strain' (infinitesimal), 'total Lagrangian' "
        "(Green-Lagrange strain / 2nd Piola-Kirchhoff stress), 'updated Lagrangian' "
        "(hypoelastic-plastic with Jaumann rate, as NOFEAP), 'finite strain' "
        "(multiplicative J2 plasticity with logarithmic elastic strain; the default: forming "
        "processes). "
        "With any kinematics but small strain, pressure loads follow the deformed surface.");
    prm.declare_entry(
        "Planar model",
        "plane strain",
        Patterns::Selection("plane strain|plane stress|axisymmetric|generalized plane strain"),
        "Two-dimensional idealisation. Axisymmetric: x is the radius, y the axis. "
        "Generalized plane strain: the out-of-plane stretch F_zz = lambda is one "
        "unknown of the whole section (uniform eps_zz, as Abaqus' CPE*G elements), "
        "found with the displacements from the axial force on the section, "
        "int sigma_zz da = Axial force (0: free ends; thermal and transformation "
        "strains then expand the section out of plane instead of loading it).");
    prm.declare_entry("Thickness",
                      "1",
                      Patterns::Double(0.),
                      "Out-of-plane thickness of plane strain / plane stress models (mm); reported "
                      "forces are for this thickness. Axisymmetric forces are for the full 2 pi.");
    prm.declare_entry("Axial force",
                      "0",
                      Patterns::Double(),
                      "Generalized plane strain only: the axial force on the cross-section, "
                      "N = int sigma_zz da over the deformed section (N; the force on the whole "
                      "section, not scaled by Thickness). 0: free ends.");
    prm.declare_entry("Polynomial degree",
                      "2",
                      Patterns::Integer(1, 4),
                      "Degree p of the continuous Lagrange (FE_Q) displacement element.");
    prm.declare_entry("Quadrature points",
                      "0",
                      Patterns::Integer(0, 6),
                      "Gauss points per direction; 0 means degree + 1.");
    prm.declare_entry(
        "Volumetric locking treatment",
        "none",
        Patterns::Selection("none|F-bar"),
        "none: standard displacement element; F-bar: the volume change at every Gauss point is "
        "replaced by the one at the cell centre (Q1) or by the cell average (Q2 and higher), "
        "F_bar = (J0/J)^(1/n) F with n = 3 on the whole F (axisymmetric; plane strain with Q2 "
        "and higher) or n = 2 on the in-plane part (plane strain with Q1, plane stress); for "
        "small strain this is B-bar. Cures the locking of Q1 in plastic flow; consistent, "
        "non-symmetric tangent.");
    prm.leave_subsection();
  }

  void ModelParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    kinematics = material::parse_kinematics(prm.get("Kinematics"));
    const std::string planar = prm.get("Planar model");
    planar_model = planar == "plane strain"   ? PlanarModel::plane_strain
                   : planar == "plane stress" ? PlanarModel::plane_stress
                   : planar == "axisymmetric" ? PlanarModel::axisymmetric
                                              : PlanarModel::generalized_plane_strain;
    thickness = prm.get_double("Thickness");
    axial_force = prm.get_double("Axial force");
    degree = prm.get_integer("Polynomial degree");
    quadrature_points = prm.get_integer("Quadrature points");
    volumetric_locking = prm.get("Volumetric locking treatment") == "F-bar"
                             ? VolumetricLocking::f_bar
                             : VolumetricLocking::none;
    prm.leave_subsection();
    require(thickness > 0., "Model/Thickness", "must be positive");
    require(axial_force == 0. || planar_model == PlanarModel::generalized_plane_strain,
            "Model/Axial force",
            "applies to generalized plane strain only (Model/Planar model = '" + planar
                + "' has no axial unknown): leave it at 0 or set Model/Planar model = "
                  "generalized plane strain");
    if (quadrature_points == 0)
      quadrature_points = degree + 1;
    require(volumetric_locking == VolumetricLocking::none || quadrature_points > 1,
            "Model/Volumetric locking treatment",
            "F-bar needs at least 2 quadrature points per direction (Model/Quadrature points); "
            "with one point the volume change is constant per cell already");
    // Fewer points than the degree (one point for Q1) leave zero-energy (hourglass) modes in
    // every cell: the tangent is singular and the linear solver fails.
    const unsigned int minimum = std::max(2u, degree);
    require(quadrature_points >= minimum,
            "Model/Quadrature points",
            std::to_string(quadrature_points)
                + " per direction is too few for Model/Polynomial "
                  "degree = "
                + std::to_string(degree)
                + ": the element stiffness has zero-energy "
                  "(hourglass) modes and the tangent is singular; use at least "
                + std::to_string(minimum) + " (0: degree + 1, the default)");
  }
} // namespace ausroll::mechanics
