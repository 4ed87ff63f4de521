#include <ausroll/core/exceptions.h>
#include <ausroll/io/postprocess/generalized_plane_strain.h>
#include <ausroll/io/postprocess/standard_set.h>

namespace ausroll::io::postprocess
{
  template <int dim>
  void GeneralizedPlaneStrainColumns<dim>::execute(const PostprocessInput<dim> &input,
                                                   HistoryRow                  &row) const
  {
    AssertThrow(input.out_of_plane != nullptr && input.out_of_plane->active,
                dealii::ExcInternalError());
    row.emplace_back("stretch_z", input.out_of_plane->stretch);
    row.emplace_back("axial_force", input.out_of_plane->axial_force());
  }

  template <int dim>
  Unit GeneralizedPlaneStrainColumns<dim>::unit(const std::string &name) const
  {
    if (name == "axial_force")
      return {"force", "N"};
    return {"dimensionless", "1"};
  }

  template class GeneralizedPlaneStrainColumns<2>;
  template class GeneralizedPlaneStrainColumns<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>>
    make_generalized_plane_strain_columns(const PostprocessorContext &c)
    {
      if (!c.generalized_plane_strain)
        return nullptr;
      return std::make_unique<GeneralizedPlaneStrainColumns<dim>>();
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_generalized_plane_strain_columns,
                               "generalized plane strain",
                               150,
                               "the stretch_z and axial_force columns of generalized plane strain")
