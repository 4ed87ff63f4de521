/**
 * @file interface.h
 * The interface of the terms of the mechanical assembly (mechanics/terms/) and what the
 * Assembler hands them: the element layout, the inputs of one assembly call, the local system
 * of one cell.
 */
#pragma once

#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/material_point_storage.h>

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ausroll::mechanics
{
  /** The call-independent tables of the element, built once by the Assembler. */
  struct AssemblyLayout
  {
    /** Layout of the vector-valued element @p fe (FESystem of dim FE_Q) with @p n_q cell and
        @p n_face_q face quadrature points. */
    template <int dim>
    AssemblyLayout(const dealii::FiniteElement<dim> &fe,
                   const unsigned int                n_q,
                   const unsigned int                n_face_q);

    unsigned int n_dofs = 0, n_q = 0, n_face_q = 0, n_base = 0;
    /** Component of each shape function. */
    std::vector<unsigned int> component;
    /** The local DoFs of each support point of the FE_Q base element (by component). */
    std::vector<std::array<unsigned int, 3>> node_dofs;
  };

  /** The inputs of one assembly call that the terms read. */
  template <int dim>
  struct AssemblyInputs
  {
    const dealii::TrilinosWrappers::MPI::Vector *solution = nullptr; ///< displacement (ghosted)
    double                                       time = 0.;
    MaterialPointStorage<dim>                   *material_points = nullptr;
    /** The material points by active cell index (AssemblyCache::points), or nullptr. */
    material::MaterialPoint *const *point_table = nullptr;
    bool                            need_matrix = false;
    /** Fail the cell for det F <= 0 (large strain assemblies). */
    bool check_inversion = false;
  };

  /** The local matrix and vectors of one cell and its failure (the WorkStream copy data). */
  struct LocalSystem
  {
    /** A local system of @p n_dofs DoFs; with @p out_of_plane the border of generalized plane
        strain too. */
    explicit LocalSystem(const unsigned int n_dofs, const bool out_of_plane = false)
        : cell_matrix(n_dofs, n_dofs)
        , cell_residual(n_dofs)
        , cell_external(n_dofs)
        , cell_free(n_dofs)
        , dofs(n_dofs)
        , column(out_of_plane ? n_dofs : 0)
        , row(out_of_plane ? n_dofs : 0)
    {
    }

    dealii::FullMatrix<double> cell_matrix;   ///< tangent
    dealii::Vector<double>     cell_residual; ///< internal force (then minus the external one)
    dealii::Vector<double>     cell_external; ///< external force (surface loads)
    dealii::Vector<double>     cell_free;     ///< residual of the free equations (row transforms)
    std::vector<dealii::types::global_dof_index> dofs;
    /** Generalized plane strain (GeneralizedPlaneStrain; empty otherwise): the cell's part of
        k_ue = dr/dlambda (column) and of k_eu = d(int P_zz dV)/du (row). */
    dealii::Vector<double> column, row;
    double                 axial_work = 0.;      ///< ... int P_zz dV over the cell
    double                 axial_stiffness = 0.; ///< ... k_ee of the cell
    std::size_t            cell_index = 0;       ///< active cell index
    bool                   ok = true;
    double                 min_jacobian = 1e300;
    std::string            message;

    /** Mark the cell failed with the reason @p text. */
    void fail(const std::string &text)
    {
      ok = false;
      message = text;
    }
  };

  /** A term's own scratch data (one per thread, made by AssemblyTerm::create_scratch()). */
  struct TermScratch
  {
    virtual ~TermScratch() = default;
  };

  /**
   * One term of the mechanical assembly (internal force, face loads, ...): adds its contribution
   * of one cell to the LocalSystem. The Assembler builds its list of terms once and calls each
   * term once per cell (the dispatch is per cell, never per quadrature point); a term keeps its
   * per-thread data in the TermScratch it creates. Terms are const and shared by the threads:
   * what they change lives in their scratch or, under their own lock, in mutable members.
   */
  template <int dim>
  class AssemblyTerm
  {
  public:
    using ActiveCell = typename dealii::DoFHandler<dim>::active_cell_iterator;

    virtual ~AssemblyTerm() = default;

    /** True for a term of the cell part that AssemblyCache keeps: its contribution depends only
        on the displacement and the material states (computed before the other terms). */
    virtual bool cached() const = 0;

    /** A new scratch object of this term (WorkStream: one per thread). */
    virtual std::unique_ptr<TermScratch> create_scratch() const = 0;

    /** Add the contribution of @p cell to @p local (set its failure when it fails). */
    virtual void execute(const ActiveCell          &cell,
                         const AssemblyInputs<dim> &inputs,
                         TermScratch               &scratch,
                         LocalSystem               &local) const = 0;
  };

  /**
   * G_i : M for a 3x3 @p M, G_i the 3D gradient of a shape function of component @p c with
   * in-plane gradient @p g and hoop entry @p hoop (0 where the kinematics has none).
   */
  template <int dim>
  double contract(const dealii::Tensor<2, 3>    &M,
                  const unsigned int             c,
                  const std::array<double, dim> &g,
                  const double                   hoop)
  {
    double sum = M[2][2] * hoop;
    for (unsigned int J = 0; J < dim; ++J)
      sum += M[c][J] * g[J];
    return sum;
  }

  /**
   * d ln J / du_i = tr(F^-1 G_i) of a shape function of component @p c with in-plane gradient
   * @p grad and hoop entry @p hoop (small strain: tr G_i = grad[c] + hoop).
   */
  template <int dim, typename Gradient>
  double volume_change_rate(const bool                  small_strain,
                            const dealii::Tensor<2, 3> &F_inv,
                            const unsigned int          c,
                            const Gradient             &grad,
                            const double                hoop)
  {
    if (small_strain)
      return grad[c] + hoop;
    double l = F_inv[2][2] * hoop;
    for (unsigned int J = 0; J < dim; ++J)
      l += F_inv[J][c] * grad[J];
    return l;
  }
} // namespace ausroll::mechanics
