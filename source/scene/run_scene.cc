#include <ausroll/scene/scene.h>

#include <ausroll/core/exceptions.h>

#include <exception>
#include <iostream>
#include <memory>
#include <string>

namespace ausroll::scene
{
  namespace
  {
    /** InputError naming the first entry of @p parameters that has no meaning in 3D. */
    void require_three_dimensional_settings(const SceneParameters &parameters)
    {
      const std::string why = " is planar (2D only); with a three-dimensional Geometry/Type ";
      if (parameters.model.planar_model != mechanics::PlanarModel::plane_strain)
        throw InputError("Model/Planar model" + why
                         + "leave it at its default 'plane strain' (it is ignored in 3D)");
      if (!parameters.postprocess.boundary_profile.boundary_ids.empty())
        throw InputError("Postprocess/Boundary profile/Boundary ids" + why
                         + "leave it empty (no 3D profile yet)");
      // The follower pressure (a pressure on the deformed surface) is planar; with small-strain
      // kinematics a pressure is a dead load on the reference surface and works in 3D.
      const auto &conditions = parameters.boundary_conditions.conditions;
      if (parameters.model.kinematics != material::KinematicsType::small_strain)
        for (unsigned int i = 0; i < conditions.size(); ++i)
          if (conditions[i].type == mechanics::BoundaryConditionType::pressure)
            throw InputError("Boundary conditions/Condition " + std::to_string(i)
                             + "/Type = pressure: a follower pressure (on the deformed surface, "
                               "Model/Kinematics other than 'small strain')"
                             + why
                             + "use Type = traction (a dead load per reference area) or "
                               "Model/Kinematics = small strain");
    }

    template <int dim>
    void run_scene_in(const SceneParameters &parameters,
                      const MPI_Comm         comm,
                      const bool             resume,
                      const bool             check_only)
    {
      std::unique_ptr<Scene<dim>> scene
          = std::make_unique<Scene<dim>>(parameters, comm, resume, check_only);
      if (check_only)
      {
        scene->print_sizes(std::cout);
        return;
      }
      try
      {
        scene->run();
      }
      catch (...)
      {
        // Destroy the scene while the exception is handled (not in flight), so that its timers
        // and output close normally; then pass the error on.
        const std::exception_ptr error = std::current_exception();
        scene.reset();
        std::rethrow_exception(error);
      }
    }
  } // namespace

  void run_scene(const std::string                    &parameter_file,
                 const MPI_Comm                        comm,
                 const bool                            resume,
                 const std::vector<ParameterOverride> &overrides,
                 const bool                            check_only)
  {
    const SceneParameters parameters = read_parameter_file(parameter_file, overrides);
    // A three-dimensional `Geometry/Type` runs Scene<3>; the planar shapes (and a mesh file)
    // run Scene<2>.
    if (parameters.geometry.dimension() == 3)
    {
      require_three_dimensional_settings(parameters);
      run_scene_in<3>(parameters, comm, resume, check_only);
    }
    else
      run_scene_in<2>(parameters, comm, resume, check_only);
  }

} // namespace ausroll::scene
