#include <ausroll/mechanics/terms/face_loads.h>
#include <ausroll/mechanics/terms/follower_pressure.h>

#include <deal.II/fe/fe_values.h>

#include <mutex>

namespace ausroll::mechanics
{
  using namespace dealii;

  namespace
  {
    /** The face-load term for the hoop entry @p Hoop of the kinematics. */
    template <int dim, typename Hoop>
    class FaceLoadTerm : public AssemblyTerm<dim>
    {
    public:
      using ActiveCell = typename AssemblyTerm<dim>::ActiveCell;

      FaceLoadTerm(const AssemblyLayout          &layout,
                   const Mapping<dim>            &mapping,
                   const FiniteElement<dim>      &fe,
                   const Quadrature<dim - 1>     &quadrature,
                   const PlanarKinematics<dim>   &kinematics,
                   const BoundaryConditions<dim> &boundary_conditions,
                   const bool                     follower)
          : layout(layout)
          , mapping(mapping)
          , fe(fe)
          , quadrature(quadrature)
          , kinematics(kinematics)
          , boundary_conditions(boundary_conditions)
          , follower(follower)
      {
      }

      /** FEFaceValues, and Grad u and u on the face (follower pressure). */
      struct Scratch : TermScratch
      {
        Scratch(const Mapping<dim>        &mapping,
                const FiniteElement<dim>  &fe,
                const Quadrature<dim - 1> &quadrature)
            : fe_face_values(mapping,
                             fe,
                             quadrature,
                             update_values | update_gradients | update_quadrature_points
                                 | update_normal_vectors | update_JxW_values)
            , grad_u_face(quadrature.size())
            , u_face(quadrature.size())
        {
        }

        FEFaceValues<dim>           fe_face_values;
        std::vector<Tensor<2, dim>> grad_u_face;
        std::vector<Tensor<1, dim>> u_face;
      };

      bool cached() const override { return false; }

      std::unique_ptr<TermScratch> create_scratch() const override
      {
        return std::make_unique<Scratch>(mapping, fe, quadrature);
      }

      void execute(const ActiveCell          &cell,
                   const AssemblyInputs<dim> &inputs,
                   TermScratch               &term_scratch,
                   LocalSystem               &local) const override
      {
        Scratch                         &scratch = static_cast<Scratch &>(term_scratch);
        const FEValuesExtractors::Vector displacement(0);
        const std::vector<unsigned int> &component = layout.component;
        const unsigned int               n_dofs = layout.n_dofs;
        FEFaceValues<dim>               &fe_face_values = scratch.fe_face_values;
        Vector<double>                  &cell_external = local.cell_external;

        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && boundary_conditions.has_surface_load(face->boundary_id()))
          {
            fe_face_values.reinit(cell, face);
            if (follower)
            {
              fe_face_values[displacement].get_function_gradients(*inputs.solution,
                                                                  scratch.grad_u_face);
              fe_face_values[displacement].get_function_values(*inputs.solution, scratch.u_face);
            }
            for (unsigned int q = 0; q < layout.n_face_q; ++q)
            {
              const Point<dim>        &X = fe_face_values.quadrature_point(q);
              const Tensor<1, dim>    &N = fe_face_values.normal_vector(q);
              const double             dA = fe_face_values.JxW(q) * kinematics.volume_factor(X);
              const types::boundary_id id = face->boundary_id();
              Tensor<1, dim>           t;
              double                   p = 0.;
              {
                std::lock_guard<std::mutex> lock(load_mutex);
                t = follower ? boundary_conditions.dead_traction(id, X, inputs.time)
                             : boundary_conditions.traction(id, X, N, inputs.time);
                p = follower ? boundary_conditions.pressure(id, X, inputs.time) : 0.;
              }
              AssertThrow(dim == 2 || p == 0.,
                          ExcMessage("follower pressure is implemented for 2D models only"));
              if constexpr (dim == 2)
                if (follower && p != 0.)
                  FollowerPressure<Hoop>::add(p,
                                              q,
                                              fe_face_values,
                                              layout,
                                              X,
                                              N,
                                              scratch.grad_u_face[q],
                                              scratch.u_face[q],
                                              dA,
                                              inputs.need_matrix,
                                              kinematics.out_of_plane_stretch(),
                                              t,
                                              local.cell_matrix,
                                              local.column);
              for (unsigned int i = 0; i < n_dofs; ++i)
                cell_external(i) += t[component[i]]
                                    * fe_face_values.shape_value_component(i, q, component[i]) * dA;
            }
          }
      }

    private:
      const AssemblyLayout          &layout;
      const Mapping<dim>            &mapping;
      const FiniteElement<dim>      &fe;
      const Quadrature<dim - 1>     &quadrature;
      const PlanarKinematics<dim>   &kinematics;
      const BoundaryConditions<dim> &boundary_conditions;
      const bool                     follower; ///< pressure on the deformed surface
      /** the boundary-condition functions keep their time in the object: one thread at a time */
      mutable std::mutex load_mutex;
    };
  } // namespace

  template <int dim>
  std::unique_ptr<AssemblyTerm<dim>>
  FaceLoads<dim>::create(const AssemblyLayout          &layout,
                         const Mapping<dim>            &mapping,
                         const FiniteElement<dim>      &fe,
                         const Quadrature<dim - 1>     &quadrature,
                         const PlanarKinematics<dim>   &kinematics,
                         const BoundaryConditions<dim> &boundary_conditions,
                         const bool                     follower)
  {
    return kinematics.with_hoop_entry(
        [&](auto hoop) -> std::unique_ptr<AssemblyTerm<dim>>
        {
          return std::make_unique<FaceLoadTerm<dim, decltype(hoop)>>(
              layout, mapping, fe, quadrature, kinematics, boundary_conditions, follower);
        });
  }

  template struct FaceLoads<2>;
  template struct FaceLoads<3>;
} // namespace ausroll::mechanics
