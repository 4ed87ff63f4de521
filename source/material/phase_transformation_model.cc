#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/material/phase_transformation_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace ausroll::material
{
  using namespace dealii;

  void PhaseParameters::declare_parameters(ParameterHandler &prm)
  {
    const PhaseParameters defaults;
    prm.enter_subsection("Phases");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Track the martensitic transformation of metastable austenite on cooling "
                      "(needs Thermal/Enabled): martensite fraction by Koistinen-Marburger below "
                      "Ms(C), and its volume change as a transformation strain. The material "
                      "starts as austenite (see Initial state).");
    prm.declare_entry("Initial state",
                      "austenite",
                      Patterns::Selection("austenite|quenched|undercooled austenite"),
                      "The phases at t = 0. austenite: all austenite, which needs Ms(C) below "
                      "Thermal/Initial temperature at every material point. quenched: the run "
                      "starts after a quench to Thermal/Initial temperature (e.g. into the bath "
                      "of ausrolling): where Ms(C) lies above it (a low-carbon core) the point "
                      "holds the Koistinen-Marburger fraction 1 - exp(-b (Ms(C) - T_0)) of "
                      "martensite, in the stress-free reference (the transformation strain "
                      "counts from it; the quench's own stresses and distortion are not modelled); "
                      "the rest is metastable austenite. undercooled austenite: all austenite "
                      "even below Ms(C): the martensite of the undercooling forms in the first "
                      "step (an instantaneous quench).");
    prm.declare_entry("Carbon content",
                      defaults.carbon_content,
                      Patterns::Anything(),
                      "Carbon content in wt% (0 to 2.1): an expression of x, y (z in 3D) and "
                      "depth, the distance (mm) below the initial surface of the Case boundaries "
                      "measured along its normal (exact on curved outlines: the involute flank, "
                      "the circles), e.g. the carburized case '0.2 + 0.7 * erfc(depth / 0.6)'; or "
                      "'file: NAME.csv', a table of two columns depth, C (depths increasing; "
                      "linear between the rows, constant beyond them).");
    prm.declare_entry("Case boundaries",
                      "",
                      Patterns::Anything(),
                      "Boundary ids of the workpiece whose initial outline the depth of Carbon "
                      "content is measured from (the carburized surface). Empty: the Candidate "
                      "boundaries of all dies (the surface the dies roll); used only if the "
                      "carbon content uses the depth.");
    prm.declare_entry("Martensite start temperature",
                      defaults.martensite_start,
                      Patterns::Anything(),
                      "Ms(C) in degrees C, an expression of the carbon content C (wt%). Default: "
                      "Andrews' linear relation (J. Iron Steel Inst. 203, 1965) with the other "
                      "elements of AISI 9310 (0.55 Mn, 3.25 Ni, 1.2 Cr, 0.12 Mo).");
    prm.declare_entry("Koistinen-Marburger coefficient",
                      "0.011",
                      Patterns::Double(0.),
                      "b in f = 1 - exp(-b (Ms - T)) (1/K; Koistinen and Marburger, Acta Metall. "
                      "7, 1959: 0.011 for plain carbon steels).");
    prm.declare_entry("Transformation volume change",
                      defaults.volume_change,
                      Patterns::Anything(),
                      "Volume change austenite to martensite in per cent, an expression of C "
                      "(default the dilatometric relation of the ASM Handbook vol. 4, Heat "
                      "Treating: 4.64 - 0.53 C).");
    prm.declare_entry("Bainite start times",
                      "",
                      Patterns::Anything(),
                      "Bainite from the TTT diagram: the times t_s(T) (s) at which 1 % of the "
                      "austenite has transformed in an isothermal hold, as a table 'T1: t1, T2: "
                      "t2, ...' (or 'file: NAME.csv') over the bainite range (between Ms and the "
                      "bainite start temperature; nothing forms outside the rows). Empty: no "
                      "bainite. JMAK through (t_s, 1 %) and (t_f, 99 %), the additivity rule for "
                      "changing temperatures.");
    prm.declare_entry("Bainite finish times",
                      "",
                      Patterns::Anything(),
                      "The times t_f(T) (s) of 99 % bainite, at the temperatures of the start "
                      "times, each later than its start time.");
    prm.declare_entry("Bainite volume change",
                      defaults.bainite_volume_change,
                      Patterns::Anything(),
                      "Volume change austenite to bainite in per cent, an expression of C "
                      "(default lower bainite, 4.64 - 1.43 C; upper bainite 4.64 - 2.21 C: the "
                      "dilatometric relations of the ASM Handbook vol. 4, after Lement 1959).");
    TransformationPlasticityParameters::declare_parameters(prm);
    prm.declare_entry("TRIP heating",
                      "false",
                      Patterns::Bool(),
                      "Count the TRIP dissipation sigma : Delta eps_tp = kappa |dev sigma|^2 of "
                      "every step as plastic work: it heats the workpiece with Thermal/Taylor-"
                      "Quinney coefficient, as the plastic work does (needs TRIP coefficient > 0). "
                      "false: only the plastic flow heats.");
    prm.declare_entry("Latent heat",
                      "0",
                      Patterns::Double(),
                      "Heat released per unit mass of martensite formed, in the unit of "
                      "Thermal/Specific heat times K (mm^2/s^2: 1 J/g = 1e9), the source rho L "
                      "df_M/dt of the heat equation (doc/theory.md section 8 on values). 0: none.");
    prm.declare_entry("Bainite latent heat",
                      "0",
                      Patterns::Double(),
                      "Heat released per unit mass of bainite formed (mm^2/s^2, as Latent heat), "
                      "the source rho L_B df_B/dt. 0: none.");
    prm.declare_entry("Mechanical stabilisation",
                      "false",
                      Patterns::Bool(),
                      "Prior plastic strain of the austenite lowers Ms (the ausforming effect): "
                      "Ms(C, alpha) = Ms(C) - G_0 / S (sqrt(1 + alpha / eps_0) - 1), alpha the "
                      "accumulated equivalent plastic strain at the start of the step (Chatterjee, "
                      "Wang and Bhadeshia, Mater. Sci. Technol. 22, 2006, as the MUCG46 program "
                      "computes it; doc/theory.md section 8).");
    prm.declare_entry("Stabilisation energy",
                      "35.11",
                      Patterns::Double(),
                      "G_0 = mu b sqrt(rho_0) V_m / (8 pi (1 - nu)) (J/mol) of Mechanical "
                      "stabilisation; default MUCG46's mu = 80 GPa, b = 0.252 nm, nu = 0.27, "
                      "rho_0 = 2e13 1/m^2, V_m = 55.8 g/mol / 7.81 g/cm^3.");
    prm.declare_entry("Stabilisation strain",
                      "0.1",
                      Patterns::Double(),
                      "eps_0 = rho_0 / (d rho / d eps) of Mechanical stabilisation (positive; "
                      "default MUCG46's rho = 2e13 + 2e14 eps 1/m^2).");
    prm.declare_entry("Driving force slope",
                      "6.94",
                      Patterns::Double(),
                      "S = -d Delta G / dT near Ms (J/(mol K), positive) that turns the "
                      "stabilisation energy into the shift of Ms; default the slope of the "
                      "gamma-alpha free energy of iron in MUCG46 between 300 and 700 K (1.658 "
                      "cal/(mol K)).");
    prm.leave_subsection();
  }

  void PhaseParameters::parse_parameters(ParameterHandler  &prm,
                                         const bool         thermal,
                                         const std::string &directory)
  {
    input_directory = directory;
    prm.enter_subsection("Phases");
    enabled = prm.get_bool("Enabled");
    quenched = prm.get("Initial state") == "quenched";
    undercooled = prm.get("Initial state") == "undercooled austenite";
    carbon_content = prm.get("Carbon content");
    case_boundaries = parse_unsigned_list(prm.get("Case boundaries"), "Phases/Case boundaries");
    martensite_start = prm.get("Martensite start temperature");
    koistinen_marburger = prm.get_double("Koistinen-Marburger coefficient");
    volume_change = prm.get("Transformation volume change");
    bainite_start = prm.get("Bainite start times");
    bainite_finish = prm.get("Bainite finish times");
    bainite_volume_change = prm.get("Bainite volume change");
    mechanics.parse_parameters(prm, input_directory);
    trip_heating = prm.get_bool("TRIP heating");
    latent_heat = prm.get_double("Latent heat");
    bainite_latent_heat = prm.get_double("Bainite latent heat");
    mechanical_stabilisation = prm.get_bool("Mechanical stabilisation");
    stabilisation_energy = prm.get_double("Stabilisation energy");
    stabilisation_strain = prm.get_double("Stabilisation strain");
    driving_force_slope = prm.get_double("Driving force slope");
    prm.leave_subsection();
    require(latent_heat >= 0., "Phases/Latent heat", "must not be negative");
    require(bainite_latent_heat >= 0., "Phases/Bainite latent heat", "must not be negative");
    require(stabilisation_energy >= 0., "Phases/Stabilisation energy", "must not be negative");
    require(stabilisation_strain > 0.,
            "Phases/Stabilisation strain",
            "must be positive (rho_0 / (d rho / d eps))");
    require(driving_force_slope > 0.,
            "Phases/Driving force slope",
            "must be positive (the driving force grows with undercooling)");
    require(enabled || (!quenched && !undercooled),
            "Phases/Initial state",
            "describes the phases at t = 0: set Phases/Enabled = true");
    require(enabled || !mechanical_stabilisation,
            "Phases/Mechanical stabilisation",
            "acts on the transformation: set Phases/Enabled = true");
    require(!trip_heating || mechanics.trip_coefficient > 0.,
            "Phases/TRIP heating",
            "heats by the TRIP dissipation: set Phases/TRIP coefficient > 0 too");
    require(enabled || (!trip_heating && latent_heat == 0. && bainite_latent_heat == 0.),
            trip_heating       ? "Phases/TRIP heating"
            : latent_heat > 0. ? "Phases/Latent heat"
                               : "Phases/Bainite latent heat",
            "heats by the transformation: set Phases/Enabled = true");
    require(enabled || !mechanics.active(),
            mechanics.trip_coefficient > 0.    ? "Phases/TRIP coefficient"
            : mechanics.martensite_yield_given ? "Phases/Martensite yield stress"
                                               : "Phases/Bainite yield stress",
            "acts on the transformation: set Phases/Enabled = true");
    require(!enabled || thermal,
            "Phases/Enabled",
            "the transformation follows the temperature: set Thermal/Enabled = true");
    if (enabled)
    {
      CarbonFunction(martensite_start, "Phases/Martensite start temperature");
      CarbonFunction(volume_change, "Phases/Transformation volume change");
      require_expression_length(carbon_content, "Phases/Carbon content");
      const BainiteKinetics check(bainite_start,
                                  bainite_finish,
                                  "Phases/Bainite start times",
                                  "Phases/Bainite finish times",
                                  input_directory);
      if (check.active())
        CarbonFunction(bainite_volume_change, "Phases/Bainite volume change");
    }
  }

  PhaseTransformationModel::PhaseTransformationModel(std::unique_ptr<ConstitutiveModel> model,
                                                     const PhaseParameters             &prm)
      : WrappedModel(std::move(model))
      , b(prm.koistinen_marburger)
      , ms(prm.martensite_start, "Phases/Martensite start temperature")
      , dv(prm.volume_change, "Phases/Transformation volume change")
      , bainite(prm.bainite_start,
                prm.bainite_finish,
                "Phases/Bainite start times",
                "Phases/Bainite finish times",
                prm.input_directory)
  {
    if (bainite.active())
      dv_bainite.emplace(prm.bainite_volume_change, "Phases/Bainite volume change");
    if (prm.trip_heating && prm.mechanics.trip_coefficient > 0.)
      trip_heat.emplace(prm.mechanics);
    if (prm.mechanical_stabilisation)
    {
      stabilised = true;
      stabilisation_shift = prm.stabilisation_energy / prm.driving_force_slope;
      stabilisation_strain = prm.stabilisation_strain;
    }
  }

  double PhaseTransformationModel::martensite_start(const double C, const double alpha) const
  {
    if (!stabilised)
      return ms.value(C);
    return ms.value(C)
           - stabilisation_shift
                 * (std::sqrt(1. + std::max(alpha, 0.) / stabilisation_strain) - 1.);
  }

  double PhaseTransformationModel::martensite_fraction(const double f_old,
                                                       const double C,
                                                       const double T,
                                                       const double bainite_fraction,
                                                       const double alpha) const
  {
    const double Ms = martensite_start(C, alpha);
    if (T >= Ms)
      return f_old;
    return std::max(f_old, (1. - bainite_fraction) * (1. - std::exp(-b * (Ms - T))));
  }

  double PhaseTransformationModel::bainite_fraction(const double f_old,
                                                    const double martensite,
                                                    const double T,
                                                    const double dt) const
  {
    const double available = 1. - martensite; // austenite and bainite
    if (!bainite.in_range(T) || !(available > 0.))
      return f_old;
    const double xi = bainite.advance(std::min(1., f_old / available), T, dt);
    return std::max(f_old, xi * available);
  }

  double PhaseTransformationModel::transformation_stretch(const double f,
                                                          const double C,
                                                          const double f_b,
                                                          const double f_0) const
  {
    if (f_b > 0.)
      return std::cbrt((1. + f * dv.value(C) / 100. + f_b * dv_bainite->value(C) / 100.)
                       / (1. + f_0 * dv.value(C) / 100.));
    if (f_0 > 0.)
      return std::cbrt((1. + f * dv.value(C) / 100.) / (1. + f_0 * dv.value(C) / 100.));
    return f > 0. ? std::cbrt(1. + f * dv.value(C) / 100.) : 1.;
  }

  void PhaseTransformationModel::evaluate(const Tensor<2, 3>  &F,
                                          const MaterialState &old,
                                          MaterialState       &state,
                                          Tensor<2, 3>        &P,
                                          Tensor<4, 3>        *tangent) const
  {
    const double f_b = bainite_fraction(old.bainite, old.martensite, old.temperature, step_length);
    const double f = martensite_fraction(
        old.martensite, old.carbon, old.temperature, f_b, old.equivalent_plastic_strain);
    const double theta = transformation_stretch(f, old.carbon, f_b, old.initial_martensite);
    // the fractions at the end of the step first: the inner return map reads them (TRIP, mixture)
    state.martensite = f;
    state.bainite = f_b;
    state.carbon = old.carbon;
    state.initial_martensite = old.initial_martensite;
    inner->evaluate(remove_stretch(F, theta), old, state, P, tangent);
    scale_response(P, tangent, theta);
    if (trip_heat)
    {
      // the TRIP dissipation of the step, kappa dev(sigma) : dev(sigma) per unit volume (per
      // reference volume with J, as the plastic work of ThermalExpansionModel)
      const double kappa = trip_heat->trip_compliance(PhaseStep::of(old, state));
      if (kappa > 0.)
      {
        const SymmetricTensor<2, 3> s = deviator(state.stress);
        const double                J = inner->is_small_strain() ? 1. : determinant(F);
        state.plastic_work += J * kappa * (s * s);
      }
    }
  }

  void PhaseTransformationModel::make_admissible(MaterialState &state) const
  {
    // the transfer interpolates every component of the state alike: a steep front of the
    // fractions (the martensite below the case, the carbon profile) overshoots
    state.martensite = std::clamp(state.martensite, 0., 1.);
    state.bainite = std::clamp(state.bainite, 0., 1. - state.martensite);
    state.initial_martensite = std::clamp(state.initial_martensite, 0., state.martensite);
    state.carbon = std::max(state.carbon, 0.);
    inner->make_admissible(state);
  }

  void PhaseTransformationModel::rebase(MaterialState &state, const Tensor<2, 3> &F) const
  {
    inner->rebase(state,
                  remove_stretch(F,
                                 transformation_stretch(state.martensite,
                                                        state.carbon,
                                                        state.bainite,
                                                        state.initial_martensite)));
  }

  template <int dim>
  void initialize_phase_state(
      const PhaseParameters                                                      &parameters,
      const Triangulation<dim>                                                   &triangulation,
      CellDataStorage<typename Triangulation<dim>::cell_iterator, MaterialPoint> &points,
      const MPI_Comm                                                              comm)
  {
    const CarbonFunction ms(parameters.martensite_start, "Phases/Martensite start temperature");
    const double         b = parameters.koistinen_marburger;
    // the points that lie below Ms(C) at the initial temperature: how many, by how much, and the
    // lowest carbon content among them (the highest Ms)
    unsigned long long below = 0;
    double             excess = 0., lowest_carbon = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : points.get_data(cell))
        {
          MaterialState &state = point->committed;
          const double   undercooling = ms.value(state.carbon) - state.temperature;
          const double   f_0 = undercooling > 0. ? 1. - std::exp(-b * undercooling) : 0.;
          if (undercooling > 0.)
          {
            ++below;
            excess = std::max(excess, undercooling);
            lowest_carbon = std::min(lowest_carbon, state.carbon);
          }
          if (!parameters.quenched)
            continue;
          state.martensite = state.initial_martensite = f_0;
          state.bainite = 0.;
          point->trial = state;
        }
    // collective, so that every rank stops with the same message
    below = Utilities::MPI::sum(below, comm);
    if (parameters.quenched || parameters.undercooled || below == 0)
      return;
    excess = Utilities::MPI::max(excess, comm);
    lowest_carbon = Utilities::MPI::min(lowest_carbon, comm);
    std::ostringstream text;
    text << "the material starts as austenite, but Thermal/Initial temperature lies below "
            "Phases/Martensite start temperature at "
         << below << " material points (by up to " << excess
         << " K; Ms = " << ms.value(lowest_carbon) << " C at the lowest carbon content there, "
         << lowest_carbon
         << " wt%): start above Ms, or set Initial state = quenched (the martensite of the quench "
            "to the initial temperature in the stress-free reference) or undercooled austenite "
            "(it transforms in the first step)";
    throw InputError("Phases/Initial state: " + text.str());
  }

  template void
  initialize_phase_state<2>(const PhaseParameters &,
                            const Triangulation<2> &,
                            CellDataStorage<Triangulation<2>::cell_iterator, MaterialPoint> &,
                            const MPI_Comm);
  template void
  initialize_phase_state<3>(const PhaseParameters &,
                            const Triangulation<3> &,
                            CellDataStorage<Triangulation<3>::cell_iterator, MaterialPoint> &,
                            const MPI_Comm);
} // namespace ausroll::material
