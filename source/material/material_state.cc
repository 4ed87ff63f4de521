#include <ausroll/material/material_state.h>

#include <cmath>

namespace ausroll::material
{
  MaterialState::MaterialState()
      : elastic_left_cauchy_green(dealii::unit_symmetric_tensor<3>())
      , deformation_gradient(dealii::unit_symmetric_tensor<3>())
  {
  }

  namespace
  {
    void pack_symmetric(const dealii::SymmetricTensor<2, 3> &t, std::vector<double> &data)
    {
      for (unsigned int i = 0; i < 6; ++i)
        data.push_back(t.access_raw_entry(i));
    }

    const double *unpack_symmetric(const double *data, dealii::SymmetricTensor<2, 3> &t)
    {
      for (unsigned int i = 0; i < 6; ++i)
        t.access_raw_entry(i) = *data++;
      return data;
    }
  } // namespace

  void MaterialState::pack(std::vector<double> &data) const
  {
    pack_symmetric(stress, data);
    pack_symmetric(plastic_strain, data);
    pack_symmetric(back_stress, data);
    pack_symmetric(elastic_left_cauchy_green, data);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        data.push_back(deformation_gradient[i][j]);
    data.push_back(equivalent_plastic_strain);
    data.push_back(temperature);
    data.push_back(evaluation_temperature);
    data.push_back(plastic_work);
    data.push_back(martensite);
    data.push_back(carbon);
    data.push_back(bainite);
    data.push_back(initial_martensite);
  }

  void MaterialState::unpack(const double *data)
  {
    data = unpack_symmetric(data, stress);
    data = unpack_symmetric(data, plastic_strain);
    data = unpack_symmetric(data, back_stress);
    data = unpack_symmetric(data, elastic_left_cauchy_green);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        deformation_gradient[i][j] = *data++;
    equivalent_plastic_strain = *data++;
    temperature = *data++;
    evaluation_temperature = *data++;
    plastic_work = *data++;
    martensite = *data++;
    carbon = *data++;
    bainite = *data++;
    initial_martensite = *data;
  }

  double MaterialState::von_mises_stress() const
  {
    const dealii::SymmetricTensor<2, 3> s = dealii::deviator(stress);
    return std::sqrt(1.5 * (s * s));
  }
} // namespace ausroll::material
