#include <ausroll/core/exceptions.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/material/finite_strain_log_model.h>
#include <ausroll/material/phase_transformation_model.h>
#include <ausroll/material/plane_stress_driver.h>
#include <ausroll/material/small_strain_model.h>
#include <ausroll/material/thermal_expansion_model.h>
#include <ausroll/material/total_lagrangian_model.h>
#include <ausroll/material/updated_lagrangian_jaumann_model.h>

namespace ausroll::material
{
  KinematicsType parse_kinematics(const std::string &name)
  {
    if (name == "small strain")
      return KinematicsType::small_strain;
    if (name == "total Lagrangian")
      return KinematicsType::total_lagrangian;
    if (name == "updated Lagrangian")
      return KinematicsType::updated_lagrangian;
    if (name == "finite strain")
      return KinematicsType::finite_strain;
    throw InputError("Model/Kinematics: unknown kinematics '" + name + "'");
  }

  std::string to_string(const KinematicsType type)
  {
    switch (type)
    {
      case KinematicsType::small_strain:
        return "small strain";
      case KinematicsType::total_lagrangian:
        return "total Lagrangian";
      case KinematicsType::updated_lagrangian:
        return "updated Lagrangian";
      case KinematicsType::finite_strain:
        return "finite strain";
    }
    return "";
  }

  std::unique_ptr<ConstitutiveModel>
  create_constitutive_model(const KinematicsType              kinematics,
                            const MaterialParameters         &material,
                            const bool                        plane_stress,
                            const ThermalExpansionParameters *thermal,
                            const PhaseParameters            *phases)
  {
    // TRIP and the mixture rule of the yield stress act in the return map (`Phases` entries)
    const TransformationPlasticityParameters *mechanics
        = phases != nullptr ? &phases->mechanics : nullptr;
    std::unique_ptr<ConstitutiveModel> model;
    switch (kinematics)
    {
      case KinematicsType::small_strain:
        model = std::make_unique<SmallStrainModel>(create_plasticity_model(material, mechanics));
        break;
      case KinematicsType::total_lagrangian:
        model
            = std::make_unique<TotalLagrangianModel>(create_plasticity_model(material, mechanics));
        break;
      case KinematicsType::updated_lagrangian:
        model = std::make_unique<UpdatedLagrangianJaumannModel>(
            create_plasticity_model(material, mechanics));
        break;
      case KinematicsType::finite_strain:
        model
            = std::make_unique<FiniteStrainLogModel>(create_plasticity_model(material, mechanics));
        break;
    }
    if (!model)
      throw InputError("Model/Kinematics: unknown kinematics");
    if (thermal != nullptr)
      model = std::make_unique<ThermalExpansionModel>(
          std::move(model), thermal->expansion, thermal->reference_temperature);
    if (phases != nullptr)
      model = std::make_unique<PhaseTransformationModel>(std::move(model), *phases);
    if (plane_stress)
      model = std::make_unique<PlaneStressDriver>(std::move(model));
    return model;
  }
} // namespace ausroll::material
