#include <ausroll/core/exceptions.h>
#include <ausroll/mechanics/assembler.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_FEVector.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <sstream>

namespace ausroll::mechanics
{
  using namespace dealii;

  template <int dim>
  Assembler<dim>::Assembler(const Mapping<dim>                &mapping,
                            const FiniteElement<dim>          &fe,
                            const unsigned int                 n_q_points_1d,
                            const PlanarKinematics<dim>       &kinematics,
                            const material::ConstitutiveModel &model,
                            const BoundaryConditions<dim>     &boundary_conditions,
                            const VolumetricLocking            locking)
      : mapping(mapping)
      , fe(fe)
      , cell_quadrature(n_q_points_1d)
      , face_quadrature(n_q_points_1d)
      , kinematics(kinematics)
      , model(model)
      , boundary_conditions(boundary_conditions)
      , locking(locking)
  {
  }

  template <int dim>
  Assembler<dim>::~Assembler() = default;

  namespace
  {
    /**
     * d ln J / du_i = tr(F^-1 G_i) of a shape function of component @p c with in-plane gradient
     * @p grad and hoop entry @p hoop (small strain: tr G_i = grad[c] + hoop).
     */
    template <int dim, typename Gradient>
    double volume_change_rate(const bool          small_strain,
                              const Tensor<2, 3> &F_inv,
                              const unsigned int  c,
                              const Gradient     &grad,
                              const double        hoop)
    {
      if (small_strain)
        return grad[c] + hoop;
      double l = F_inv[2][2] * hoop;
      for (unsigned int J = 0; J < dim; ++J)
        l += F_inv[J][c] * grad[J];
      return l;
    }

    /** G_i : M for a 3x3 @p M, G_i the 3D gradient of a shape function of component @p c with
        in-plane gradient @p g and hoop entry @p hoop. */
    template <int dim>
    double contract(const Tensor<2, 3>            &M,
                    const unsigned int             c,
                    const std::array<double, dim> &g,
                    const double                   hoop)
    {
      double sum = M[2][2] * hoop;
      for (unsigned int J = 0; J < dim; ++J)
        sum += M[c][J] * g[J];
      return sum;
    }
  } // namespace

  template <int dim>
  struct Assembler<dim>::Setup
  {
    // inputs of the call
    const TrilinosWrappers::MPI::Vector *solution = nullptr;
    double                               time = 0.;
    MaterialPointStorage<dim>           *material_points = nullptr;
    // the material points by active cell index (AssemblyCache::points), or nullptr
    material::MaterialPoint *const  *point_table = nullptr;
    const AffineConstraints<double> *hanging = nullptr;
    const AffineConstraints<double> *newton = nullptr;
    const RowTransforms<dim>        *row_transforms = nullptr;
    const AssemblyTargets           *targets = nullptr;
    // the cache to read the cell part from (reuse) or to write it to (store)
    AssemblyCache *cache = nullptr;
    bool           reuse = false;
    bool           store = false;
    // the slot tables of the matrix (AssemblyCache::slot_rows) and the local values of the
    // target vectors (same map), or nullptr
    const AssemblyCache *slots = nullptr;
    double *residual_values = nullptr, *external_values = nullptr, *free_values = nullptr,
           *rhs_values = nullptr;

    // flags
    bool need_matrix = false;
    bool small_strain = false;
    bool f_bar = false;
    // J0: value at the cell centre for Q1 (de Souza Neto), cell average for higher degrees (a
    // single centre value leaves volumetric modes of Q2 unconstrained: too soft)
    bool cell_average = false;
    bool follower = false; // pressure on the deformed surface
    bool axisymmetric = false;
    bool check_inversion = false;

    unsigned int n_dofs = 0, n_q = 0, n_face_q = 0, n_base = 0;
    // Component of each shape function and the local DoFs of each support point.
    std::vector<unsigned int>            component;
    std::vector<std::array<unsigned, 3>> node_dofs;
    // n of the F-bar scaling and the in-plane/volumetric projection E (I_n)
    unsigned int n_vol = 2;
    double       alpha = 0.5;
    Tensor<2, 3> E;

    // outcome, gathered by the copier in cell order
    bool        ok = true;
    double      min_jacobian = 1e300;
    std::string message;
    // the boundary-condition functions keep their time in the object: one thread at a time
    mutable std::mutex load_mutex;
    // the copier's work vector (-r of the free equations of one cell)
    Vector<double> cell_rhs;
  };

  template <int dim>
  struct Assembler<dim>::FBarPoint
  {
    Tensor<2, 3> F_material; // F_bar (F without F-bar)
    double       s = 1.;     // F_bar = s F (in the scaled block; 1 for small strain)
    double       kappa = 1.; // P = kappa P(F_bar), kappa = s^(1 - n)
    Tensor<2, 3> F_inv;      // F^-1 (large strain with F-bar; else zero)
  };

  // The scratch data of the parts (WorkStream copies the whole ScratchData once per thread;
  // FEValues cannot be copied, so each part is rebuilt from the element, mapping and quadrature).

  template <int dim>
  struct Assembler<dim>::CellScratch
  {
    CellScratch(const Mapping<dim>       &mapping,
                const FiniteElement<dim> &fe,
                const Quadrature<dim>    &quadrature)
        : fe_values(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_quadrature_points | update_JxW_values)
        , local_u(fe.n_dofs_per_cell())
        , grad_u(quadrature.size())
        , u_values(quadrature.size())
        , g(fe.n_dofs_per_cell())
        , hoop(fe.n_dofs_per_cell(), 0.)
        , h(fe.n_dofs_per_cell())
        , h_hoop(fe.n_dofs_per_cell(), 0.)
    {
    }

    CellScratch(const CellScratch &other)
        : CellScratch(other.fe_values.get_mapping(),
                      other.fe_values.get_fe(),
                      other.fe_values.get_quadrature())
    {
    }

    FEValues<dim>               fe_values;
    std::vector<double>         local_u;  // the cell's DoF values of the solution
    std::vector<Tensor<2, dim>> grad_u;   // Grad u at the quadrature points
    std::vector<Tensor<1, dim>> u_values; // u at the quadrature points
    // The 3D gradient G_i = dF/du_i of each shape function (3x3): row c_i holds the in-plane
    // gradient, g[i][J] = dF[c_i][J] / du_i (J < dim), and axisymmetric models add the hoop entry
    // hoop[i] = dF[2][2] / du_i = phi_i / R for the radial component (c_i = 0).
    std::vector<std::array<double, dim>> g;
    std::vector<double>                  hoop;
    // h[j][c][I] = (A : G_j)[c][I] for c, I < dim and h_hoop[j] = (A : G_j)[2][2]
    std::vector<std::array<std::array<double, dim>, dim>> h;
    std::vector<double>                                   h_hoop;
    // stress P = kappa P(F_bar), the material's stress P(F_bar) and its tangent A
    Tensor<2, 3> P, P_bar;
    Tensor<4, 3> A;
    // the cell's material points when the assembly has no point table
    std::vector<material::MaterialPoint *> points;
  };

  template <int dim>
  struct Assembler<dim>::FBarScratch
  {
    FBarScratch(const Mapping<dim> &mapping, const FiniteElement<dim> &fe)
        : fe_center(mapping,
                    fe,
                    Quadrature<dim>(cell_center()),
                    update_values | update_gradients | update_quadrature_points)
        , grad_u_center(1)
        , u_center(1)
        , dlnJ0(fe.n_dofs_per_cell())
        , dlnJ(fe.n_dofs_per_cell())
        , q_coefficient(fe.n_dofs_per_cell())
    {
    }

    FBarScratch(const FBarScratch &other)
        : FBarScratch(other.fe_center.get_mapping(), other.fe_center.get_fe())
    {
    }

    static Point<dim> cell_center()
    {
      Point<dim> unit_center;
      for (unsigned int d = 0; d < dim; ++d)
        unit_center[d] = 0.5;
      return unit_center;
    }

    FEValues<dim>               fe_center; // values and gradients at the cell centre (Q1)
    std::vector<Tensor<2, dim>> grad_u_center;
    std::vector<Tensor<1, dim>> u_center;
    // d ln J0 / du_j of the reference, d ln J / du_j at the point (tr G for small strain), and
    // the coefficients q_i of the rank-one reference term of the tangent
    std::vector<double> dlnJ0, dlnJ, q_coefficient;
    // the reference of the current cell: J0, tr(F0 - I)
    double J0 = 1., trace_H0 = 0.;
  };

  template <int dim>
  struct Assembler<dim>::FaceScratch
  {
    FaceScratch(const Mapping<dim>        &mapping,
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

    FaceScratch(const FaceScratch &other)
        : FaceScratch(other.fe_face_values.get_mapping(),
                      other.fe_face_values.get_fe(),
                      other.fe_face_values.get_quadrature())
    {
    }

    FEFaceValues<dim>           fe_face_values;
    std::vector<Tensor<2, dim>> grad_u_face; // follower pressure: Grad u and u on the face
    std::vector<Tensor<1, dim>> u_face;
  };

  template <int dim>
  struct Assembler<dim>::ScratchData
  {
    ScratchData(const Mapping<dim>        &mapping,
                const FiniteElement<dim>  &fe,
                const Quadrature<dim>     &cell_quadrature,
                const Quadrature<dim - 1> &face_quadrature)
        : cell(mapping, fe, cell_quadrature)
        , f_bar(mapping, fe)
        , face(mapping, fe, face_quadrature)
    {
    }

    CellScratch cell;
    FBarScratch f_bar;
    FaceScratch face;
  };

  template <int dim>
  struct Assembler<dim>::CopyData
  {
    explicit CopyData(const unsigned int n_dofs)
        : cell_matrix(n_dofs, n_dofs)
        , cell_residual(n_dofs)
        , cell_external(n_dofs)
        , cell_free(n_dofs)
        , dofs(n_dofs)
    {
    }

    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_residual, cell_external, cell_free;
    std::vector<types::global_dof_index> dofs;
    std::size_t                          cell_index = 0; // active cell index
    bool                                 ok = true;
    double                               min_jacobian = 1e300;
    std::string                          message;

    void fail(const std::string &text)
    {
      ok = false;
      message = text;
    }
  };

  // ------------------------------------------------------------------ F-bar helper

  template <int dim>
  bool Assembler<dim>::f_bar_reference(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                       const Setup                                          &setup,
                                       const CellScratch &cell_scratch,
                                       FBarScratch       &scratch,
                                       CopyData          &copy) const
  {
    const FEValuesExtractors::Vector displacement(0);
    const std::vector<unsigned int> &component = setup.component;
    const bool                       small_strain = setup.small_strain;
    const bool                       axisymmetric = setup.axisymmetric;
    std::vector<double>             &dlnJ0 = scratch.dlnJ0;
    double                          &J0 = scratch.J0;
    double                          &trace_H0 = scratch.trace_H0;
    J0 = 1.;
    trace_H0 = 0.;
    if (!setup.cell_average)
    {
      // Q1: the deformation gradient at the cell centre
      FEValues<dim> &fe_center = scratch.fe_center;
      fe_center.reinit(cell);
      // (the cell's DoF values were read once by assemble_cell())
      fe_center[displacement].get_function_gradients_from_local_dof_values(cell_scratch.local_u,
                                                                           scratch.grad_u_center);
      fe_center[displacement].get_function_values_from_local_dof_values(cell_scratch.local_u,
                                                                        scratch.u_center);
      const Point<dim>  &X0 = fe_center.quadrature_point(0);
      const Tensor<2, 3> F0
          = kinematics.deformation_gradient(scratch.grad_u_center[0], scratch.u_center[0], X0);
      J0 = determinant(F0);
      trace_H0 = trace(F0) - 3.;
      if (setup.check_inversion && !(J0 > 0.))
      {
        std::ostringstream msg;
        msg << "inverted element (det F = " << J0 << " at the cell centre " << X0 << ")";
        copy.fail(msg.str());
        return false;
      }
      Tensor<2, 3> F0_inv;
      if (!small_strain)
        F0_inv = invert(F0);
      for (unsigned int j = 0; j < setup.n_dofs; ++j)
      {
        // tr G0_j (small strain) or tr(F0^-1 G0_j) = d ln J0 / du_j
        const unsigned int   c = component[j];
        const Tensor<1, dim> grad = fe_center.shape_grad_component(j, 0, c);
        const double         hoop0
            = (axisymmetric && c == 0) ? fe_center.shape_value_component(j, 0, c) / X0[0] : 0.;
        dlnJ0[j] = volume_change_rate<dim>(small_strain, F0_inv, c, grad, hoop0);
      }
      return true;
    }

    // Q2 and higher: volume average over the cell (mean dilatation), J0 = int J dV / V
    // (small strain: the average of tr(F - I)); d ln J0 / du_j = int J tr(F^-1 G_j) dV / (V J0)
    const FEValues<dim> &fe_values = cell_scratch.fe_values;
    double               volume = 0.;
    J0 = 0.;
    std::fill(dlnJ0.begin(), dlnJ0.end(), 0.);
    for (unsigned int q = 0; q < setup.n_q; ++q)
    {
      const Point<dim>  &X = fe_values.quadrature_point(q);
      const double       dV = fe_values.JxW(q) * kinematics.volume_factor(X);
      const Tensor<2, 3> F
          = kinematics.deformation_gradient(cell_scratch.grad_u[q], cell_scratch.u_values[q], X);
      const double       J = determinant(F);
      const double       weight = small_strain ? dV : J * dV;
      const Tensor<2, 3> F_inv = small_strain ? Tensor<2, 3>() : invert(F);
      volume += dV;
      J0 += J * dV;
      trace_H0 += (trace(F) - 3.) * dV;
      for (unsigned int j = 0; j < setup.n_dofs; ++j)
      {
        const unsigned int   c = component[j];
        const Tensor<1, dim> grad = fe_values.shape_grad_component(j, q, c);
        const double         hoop_j
            = (axisymmetric && c == 0) ? fe_values.shape_value_component(j, q, c) / X[0] : 0.;
        dlnJ0[j] += weight * volume_change_rate<dim>(small_strain, F_inv, c, grad, hoop_j);
      }
    }
    J0 /= volume;
    trace_H0 /= volume;
    for (unsigned int j = 0; j < setup.n_dofs; ++j)
      dlnJ0[j] /= small_strain ? volume : volume * J0;
    if (setup.check_inversion && !(J0 > 0.))
    {
      std::ostringstream msg;
      msg << "inverted element (mean det F = " << J0 << " in the cell at " << cell->center() << ")";
      copy.fail(msg.str());
      return false;
    }
    return true;
  }

  template <int dim>
  typename Assembler<dim>::FBarPoint Assembler<dim>::f_bar_point(const Setup        &setup,
                                                                 const FBarScratch  &scratch,
                                                                 const Tensor<2, 3> &F,
                                                                 const double        J) const
  {
    FBarPoint point;
    point.F_material = F;
    if (setup.small_strain)
      point.F_material += (setup.alpha * (scratch.trace_H0 - (trace(F) - 3.))) * setup.E;
    else
    {
      point.s = std::pow(scratch.J0 / J, setup.alpha);
      point.kappa = std::pow(point.s, 1. - setup.n_vol);
      for (unsigned int a = 0; a < setup.n_vol; ++a)
        for (unsigned int b = 0; b < setup.n_vol; ++b)
          point.F_material[a][b] *= point.s;
      point.F_inv = invert(F);
    }
    return point;
  }

  template <int dim>
  void Assembler<dim>::add_f_bar_tangent(const Setup        &setup,
                                         const FBarPoint    &point,
                                         const Tensor<2, 3> &F,
                                         const double        dV,
                                         const CellScratch  &cell_scratch,
                                         FBarScratch        &scratch,
                                         FullMatrix<double> &cell_matrix) const
  {
    // d F_bar / du_j = s G_j + alpha s (d ln J0 - d ln J) E F (large strain) or
    // G_j + alpha (tr G0_j - tr G_j) E (small strain); d kappa / du_j = (alpha - 1)
    // kappa (d ln J0 - d ln J). The terms in (d ln J0 - d ln J) form the rank-one matrix
    // q_i (dlnJ0_j - dlnJ_j) with q_i = G_i : Qt dV,
    // Qt = kappa [(alpha - 1) P_bar + alpha s A : (E F)] (small strain: alpha A : E).
    const bool          small_strain = setup.small_strain;
    const double        alpha = setup.alpha;
    const double        s = point.s, kappa = point.kappa;
    const Tensor<2, 3> &P_bar = cell_scratch.P_bar;
    const Tensor<4, 3> &A = cell_scratch.A;
    Tensor<2, 3>        Qt;
    const Tensor<2, 3>  EF = small_strain ? setup.E : setup.E * F;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
      {
        double sum = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            sum += A[a][b][k][l] * EF[k][l];
        Qt[a][b]
            = small_strain ? alpha * sum : kappa * ((alpha - 1.) * P_bar[a][b] + alpha * s * sum);
      }
    for (unsigned int i = 0; i < setup.n_dofs; ++i)
    {
      const unsigned int c = setup.component[i];
      scratch.q_coefficient[i] = contract<dim>(Qt, c, cell_scratch.g[i], cell_scratch.hoop[i]) * dV;
      scratch.dlnJ[i] = volume_change_rate<dim>(
          small_strain, point.F_inv, c, cell_scratch.g[i], cell_scratch.hoop[i]);
    }
    for (unsigned int i = 0; i < setup.n_dofs; ++i)
      for (unsigned int j = 0; j < setup.n_dofs; ++j)
        cell_matrix(i, j) += scratch.q_coefficient[i] * (scratch.dlnJ0[j] - scratch.dlnJ[j]);
  }

  // ------------------------------------------------------------------ cell part

  template <int dim>
  void Assembler<dim>::assemble_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                     const Setup                                          &setup,
                                     CellScratch                                          &scratch,
                                     FBarScratch &f_bar_scratch,
                                     CopyData    &copy) const
  {
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n_dofs = setup.n_dofs;
    const std::vector<unsigned int> &component = setup.component;
    const bool                       f_bar = setup.f_bar;
    const bool                       axisymmetric = setup.axisymmetric;
    const bool                       need_matrix = setup.need_matrix;

    FEValues<dim> &fe_values = scratch.fe_values;
    auto          &g = scratch.g;
    auto          &hoop = scratch.hoop;
    auto          &h = scratch.h;
    auto          &h_hoop = scratch.h_hoop;
    Tensor<2, 3>  &P = scratch.P;
    Tensor<2, 3>  &P_bar = scratch.P_bar;
    Tensor<4, 3>  &A = scratch.A;

    fe_values.reinit(cell);
    // one read of the cell's DoF values from the Trilinos vector for all evaluations of the cell
    // (FEValuesViews would read and allocate them for each call)
    cell->get_dof_values(*setup.solution, scratch.local_u.begin(), scratch.local_u.end());
    fe_values[displacement].get_function_gradients_from_local_dof_values(scratch.local_u,
                                                                         scratch.grad_u);
    fe_values[displacement].get_function_values_from_local_dof_values(scratch.local_u,
                                                                      scratch.u_values);
    material::MaterialPoint *const *points;
    if (setup.point_table != nullptr)
      points = setup.point_table + cell->active_cell_index() * setup.n_q;
    else
    {
      const std::vector<std::shared_ptr<material::MaterialPoint>> shared
          = setup.material_points->get_data(cell);
      scratch.points.resize(shared.size());
      for (unsigned int q = 0; q < shared.size(); ++q)
        scratch.points[q] = shared[q].get();
      points = scratch.points.data();
    }

    copy.cell_matrix = 0.;
    copy.cell_residual = 0.;
    copy.cell_external = 0.;
    FullMatrix<double> &cell_matrix = copy.cell_matrix;
    Vector<double>     &cell_residual = copy.cell_residual;

    // F-bar: the reference volume change of the cell and its derivative
    if (f_bar && !f_bar_reference(cell, setup, scratch, f_bar_scratch, copy))
      return;

    for (unsigned int q = 0; q < setup.n_q; ++q)
    {
      const Point<dim>  &X = fe_values.quadrature_point(q);
      const double       dV = fe_values.JxW(q) * kinematics.volume_factor(X);
      const Tensor<2, 3> F
          = kinematics.deformation_gradient(scratch.grad_u[q], scratch.u_values[q], X);
      const double J = determinant(F);
      copy.min_jacobian = std::min(copy.min_jacobian, J);
      if (setup.check_inversion && !(J > 0.))
      {
        std::ostringstream msg;
        msg << "inverted element (det F = " << J << ") at (" << X << ")";
        copy.fail(msg.str());
        return;
      }

      for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const unsigned int   c = component[i];
        const Tensor<1, dim> grad = fe_values.shape_grad_component(i, q, c);
        for (unsigned int J = 0; J < dim; ++J)
          g[i][J] = grad[J];
        if (axisymmetric && c == 0)
          hoop[i] = fe_values.shape_value_component(i, q, c) / X[0];
      }

      // Deformation gradient seen by the material point; residual stress P = kappa P(F_bar)
      // (P(F) without F-bar) and the factor of the material tangent term.
      FBarPoint point;
      if (f_bar)
        point = f_bar_point(setup, f_bar_scratch, F, J);
      else
        point.F_material = F;
      try
      {
        model.evaluate(point.F_material,
                       points[q]->committed,
                       points[q]->trial,
                       P_bar,
                       need_matrix ? &A : nullptr);
      }
      catch (const RunFailure &e)
      {
        copy.fail(e.what());
        return;
      }
      P = point.kappa * P_bar;

      for (unsigned int i = 0; i < n_dofs; ++i)
        cell_residual(i) += contract<dim>(P, component[i], g[i], hoop[i]) * dV;

      if (!need_matrix)
        continue;
      for (unsigned int j = 0; j < n_dofs; ++j)
      {
        const unsigned int cj = component[j];
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int I = 0; I < dim; ++I)
          {
            // (the hoop entry only where there is one: plane models skip its zero products)
            double sum = axisymmetric ? A[c][I][2][2] * hoop[j] : 0.;
            for (unsigned int J = 0; J < dim; ++J)
              sum += A[c][I][cj][J] * g[j][J];
            h[j][c][I] = sum;
          }
        if (axisymmetric)
        {
          double sum = A[2][2][2][2] * hoop[j];
          for (unsigned int J = 0; J < dim; ++J)
            sum += A[2][2][cj][J] * g[j][J];
          h_hoop[j] = sum;
        }
      }
      const double material_factor = point.kappa * point.s * dV;
      for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const unsigned int c = component[i];
        double *const      row = &cell_matrix(i, 0);
        if (axisymmetric)
          for (unsigned int j = 0; j < n_dofs; ++j)
          {
            double sum = hoop[i] * h_hoop[j];
            for (unsigned int I = 0; I < dim; ++I)
              sum += g[i][I] * h[j][c][I];
            row[j] += sum * material_factor;
          }
        else
          for (unsigned int j = 0; j < n_dofs; ++j)
          {
            double sum = 0.;
            for (unsigned int I = 0; I < dim; ++I)
              sum += g[i][I] * h[j][c][I];
            row[j] += sum * material_factor;
          }
      }

      if (f_bar)
        add_f_bar_tangent(setup, point, F, dV, scratch, f_bar_scratch, cell_matrix);
    }
  }

  // ------------------------------------------------------------------ face-load part

  template <int dim>
  void
  Assembler<dim>::assemble_face_loads(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                      const Setup                                          &setup,
                                      FaceScratch                                          &scratch,
                                      CopyData &copy) const
  {
    const FEValuesExtractors::Vector displacement(0);
    const std::vector<unsigned int> &component = setup.component;
    const unsigned int               n_dofs = setup.n_dofs;
    const bool                       follower = setup.follower;
    const bool                       axisymmetric = setup.axisymmetric;
    const bool                       need_matrix = setup.need_matrix;
    FEFaceValues<dim>               &fe_face_values = scratch.fe_face_values;
    FullMatrix<double>              &cell_matrix = copy.cell_matrix;
    Vector<double>                  &cell_external = copy.cell_external;

    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && boundary_conditions.has_surface_load(face->boundary_id()))
      {
        fe_face_values.reinit(cell, face);
        if (follower)
        {
          fe_face_values[displacement].get_function_gradients(*setup.solution, scratch.grad_u_face);
          fe_face_values[displacement].get_function_values(*setup.solution, scratch.u_face);
        }
        for (unsigned int q = 0; q < setup.n_face_q; ++q)
        {
          const Point<dim>        &X = fe_face_values.quadrature_point(q);
          const Tensor<1, dim>    &N = fe_face_values.normal_vector(q);
          const double             dA = fe_face_values.JxW(q) * kinematics.volume_factor(X);
          const types::boundary_id id = face->boundary_id();
          Tensor<1, dim>           t;
          double                   p = 0.;
          {
            std::lock_guard<std::mutex> lock(setup.load_mutex);
            t = follower ? boundary_conditions.dead_traction(id, X, setup.time)
                         : boundary_conditions.traction(id, X, N, setup.time);
            p = follower ? boundary_conditions.pressure(id, X, setup.time) : 0.;
          }
          AssertThrow(dim == 2 || p == 0.,
                      ExcMessage("follower pressure is implemented for 2D models only"));
          if constexpr (dim == 2)
            if (follower && p != 0.)
            {
              // deformed tangent a = F T (T = N rotated by +90 degrees), deformed normal times
              // dl/dL = (a_y, -a_x); axisymmetric: times the hoop stretch r / R
              const Tensor<1, 2> T({-N[1], N[0]});
              const Tensor<1, 2> a = T + scratch.grad_u_face[q] * T;
              const Tensor<1, 2> n_scaled({a[1], -a[0]});
              const double hoop_stretch = axisymmetric ? 1. + scratch.u_face[q][0] / X[0] : 1.;
              t -= (p * hoop_stretch) * n_scaled;
              if (need_matrix)
                for (unsigned int j = 0; j < n_dofs; ++j)
                {
                  // d t0 / du_j = -p (r/R d n_scaled + d(r/R) n_scaled), d a = (grad phi_j . T)
                  // e_cj
                  const unsigned int cj = component[j];
                  const double       da = fe_face_values.shape_grad_component(j, q, cj) * T;
                  Tensor<1, 2>       dt;
                  if (cj == 0)
                    dt[1] = -hoop_stretch * da;
                  else
                    dt[0] = hoop_stretch * da;
                  if (axisymmetric && cj == 0)
                    dt += (fe_face_values.shape_value_component(j, q, cj) / X[0]) * n_scaled;
                  dt *= -p * dA;
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    cell_matrix(i, j) -= dt[component[i]]
                                         * fe_face_values.shape_value_component(i, q, component[i]);
                }
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            cell_external(i)
                += t[component[i]] * fe_face_values.shape_value_component(i, q, component[i]) * dA;
        }
      }
  }

  // ------------------------------------------------------------------ row-transform part

  template <int dim>
  void Assembler<dim>::apply_row_transforms(const Setup &setup, CopyData &copy) const
  {
    // Row transforms (friction) act on the equations of whole nodes.
    copy.cell_free = copy.cell_residual;
    const RowTransforms<dim> *row_transforms = setup.row_transforms;
    if (row_transforms == nullptr || row_transforms->empty())
      return;
    const auto &node_dofs = setup.node_dofs;
    for (unsigned int b = 0; b < setup.n_base; ++b)
    {
      const auto it = row_transforms->find(copy.dofs[node_dofs[b][0]]);
      if (it == row_transforms->end())
        continue;
      const Tensor<2, dim>   &T = it->second.matrix;
      std::array<double, dim> old_r;
      for (unsigned int c = 0; c < dim; ++c)
        old_r[c] = copy.cell_residual(node_dofs[b][c]);
      for (unsigned int c = 0; c < dim; ++c)
      {
        double s = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          s += T[c][d] * old_r[d];
        copy.cell_free(node_dofs[b][c]) = s;
      }
      if (setup.need_matrix)
        for (unsigned int j = 0; j < setup.n_dofs; ++j)
        {
          std::array<double, dim> old_k;
          for (unsigned int c = 0; c < dim; ++c)
            old_k[c] = copy.cell_matrix(node_dofs[b][c], j);
          for (unsigned int c = 0; c < dim; ++c)
          {
            double s = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              s += T[c][d] * old_k[d];
            copy.cell_matrix(node_dofs[b][c], j) = s;
          }
        }
    }
  }

  template <int dim>
  void Assembler<dim>::add_row_transform_offsets(const DoFHandler<dim> &dof_handler,
                                                 const Setup           &setup) const
  {
    // Constant parts of the row transforms (shear friction), once per node by its owner.
    const RowTransforms<dim> *row_transforms = setup.row_transforms;
    const AssemblyTargets    &targets = *setup.targets;
    if (row_transforms == nullptr || (targets.free_residual == nullptr && !setup.need_matrix))
      return;
    const IndexSet                      &owned = dof_handler.locally_owned_dofs();
    Vector<double>                       node_offset(dim);
    std::vector<types::global_dof_index> node_dofs_global(dim);
    for (const auto &[key, transform] : *row_transforms)
    {
      if (transform.offset.norm_square() == 0. || !owned.is_element(key))
        continue;
      for (unsigned int c = 0; c < dim; ++c)
      {
        node_offset(c) = transform.offset[c];
        node_dofs_global[c] = transform.dofs[c];
      }
      if (targets.free_residual != nullptr)
        setup.newton->distribute_local_to_global(
            node_offset, node_dofs_global, *targets.free_residual);
      if (setup.need_matrix)
      {
        node_offset *= -1.;
        setup.newton->distribute_local_to_global(node_offset, node_dofs_global, *targets.rhs);
      }
    }
  }

  // ------------------------------------------------------------------ copier

  template <int dim>
  void Assembler<dim>::copy_local_to_global(const CopyData &copy, Setup &setup) const
  {
    // The copier runs serially and in cell order: it owns the outcome in Setup.
    if (!setup.ok)
      return; // after a failure nothing more is added (the assembly is discarded)
    setup.min_jacobian = std::min(setup.min_jacobian, copy.min_jacobian);
    if (!copy.ok)
    {
      setup.ok = false;
      setup.message = copy.message;
      return;
    }
    const AssemblyTargets &targets = *setup.targets;
    if (setup.slots != nullptr)
    {
      // A cell without constrained DoFs whose rows are all owned here: its entries straight into
      // the value arrays of the vectors and the matrix (what distribute_local_to_global adds for
      // such a cell, one sum per entry in the same cell order, without its row sorting and
      // Epetra's searches).
      const AssemblyCache &slots = *setup.slots;
      const std::size_t    n = setup.n_dofs;
      const std::size_t    base = copy.cell_index * n;
      bool                 direct = slots.slot_rows[base] != nullptr;
      for (unsigned int i = 0; direct && i < n; ++i)
        direct = !setup.newton->is_constrained(copy.dofs[i]);
      if (direct)
      {
        for (unsigned int i = 0; i < n; ++i)
        {
          const std::int32_t k = slots.slot_rhs[base + i];
          setup.residual_values[k] += copy.cell_residual(i);
          setup.external_values[k] += copy.cell_external(i);
          if (setup.free_values != nullptr)
            setup.free_values[k] += copy.cell_free(i);
          if (!setup.need_matrix)
            continue;
          double *const             row = slots.slot_rows[base + i];
          const std::int32_t *const position = &slots.slot_columns[(base + i) * n];
          const double *const       local = &copy.cell_matrix(i, 0);
          for (unsigned int j = 0; j < n; ++j)
            row[position[j]] += local[j];
          setup.rhs_values[k] += -copy.cell_free(i);
        }
        return;
      }
    }
    setup.hanging->distribute_local_to_global(copy.cell_residual, copy.dofs, *targets.residual);
    setup.hanging->distribute_local_to_global(
        copy.cell_external, copy.dofs, *targets.external_force);
    if (targets.free_residual != nullptr)
      setup.newton->distribute_local_to_global(copy.cell_free, copy.dofs, *targets.free_residual);
    if (setup.need_matrix)
    {
      // -r of the free equations (the copier's own work vector: copies run one at a time)
      Vector<double> &cell_rhs = setup.cell_rhs;
      cell_rhs = copy.cell_free;
      cell_rhs *= -1.;
      setup.newton->distribute_local_to_global(
          copy.cell_matrix, cell_rhs, copy.dofs, *targets.matrix, *targets.rhs, true);
    }
  }

  // ------------------------------------------------------------------ driver

  template <int dim>
  void Assembler<dim>::fill_setup(Setup &setup) const
  {
    setup.small_strain = model.is_small_strain();
    setup.f_bar = locking == VolumetricLocking::f_bar;
    setup.cell_average = fe.degree > 1;
    setup.follower = !setup.small_strain;
    setup.axisymmetric = kinematics.is_axisymmetric();
    setup.check_inversion = !setup.small_strain;
    setup.n_dofs = fe.n_dofs_per_cell();
    setup.n_q = cell_quadrature.size();
    setup.n_face_q = face_quadrature.size();
    setup.n_base = setup.n_dofs / dim; // support points of the FE_Q base element
    setup.component.resize(setup.n_dofs);
    setup.node_dofs.resize(setup.n_base);
    for (unsigned int i = 0; i < setup.n_dofs; ++i)
    {
      const auto ci = fe.system_to_component_index(i);
      setup.component[i] = ci.first;
      setup.node_dofs[ci.second][ci.first] = i;
    }
    // n of the F-bar scaling (Q2 and higher in plane strain scale the whole F: see
    // PlanarKinematics::volumetric_dimensions)
    setup.n_vol = kinematics.volumetric_dimensions(setup.cell_average);
    setup.alpha = 1. / setup.n_vol;
    for (unsigned int d = 0; d < setup.n_vol; ++d)
      setup.E[d][d] = 1.;
    setup.cell_rhs.reinit(setup.n_dofs);
  }

  template <int dim>
  void Assembler<dim>::assemble_one_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                         const Setup &setup,
                                         ScratchData &scratch,
                                         CopyData    &copy) const
  {
    copy.ok = true;
    copy.min_jacobian = 1e300;
    cell->get_dof_indices(copy.dofs);
    const std::size_t n_dofs = setup.n_dofs;
    const std::size_t index = cell->active_cell_index();
    copy.cell_index = index;
    if (setup.reuse)
    {
      // the cell part of the cached assembly at this very state (AssemblyCache)
      const AssemblyCache &cache = *setup.cache;
      if (setup.need_matrix)
        std::copy_n(cache.matrices.begin() + index * n_dofs * n_dofs,
                    n_dofs * n_dofs,
                    &copy.cell_matrix(0, 0));
      std::copy_n(cache.residuals.begin() + index * n_dofs, n_dofs, copy.cell_residual.begin());
      copy.cell_external = 0.;
      copy.min_jacobian = cache.min_jacobian[index];
    }
    else
    {
      assemble_cell(cell, setup, scratch.cell, scratch.f_bar, copy);
      if (!copy.ok)
        return;
      if (setup.store)
      {
        // each cell writes its own slots: safe on WorkStream's threads
        AssemblyCache &cache = *setup.cache;
        if (setup.need_matrix)
          std::copy_n(&copy.cell_matrix(0, 0),
                      n_dofs * n_dofs,
                      cache.matrices.begin() + index * n_dofs * n_dofs);
        std::copy_n(copy.cell_residual.begin(), n_dofs, cache.residuals.begin() + index * n_dofs);
        cache.min_jacobian[index] = copy.min_jacobian;
      }
    }
    assemble_face_loads(cell, setup, scratch.face, copy);
    copy.cell_residual -= copy.cell_external;
    apply_row_transforms(setup, copy);
  }

  template <int dim>
  AssemblyStatus Assembler<dim>::assemble(const DoFHandler<dim>               &dof_handler,
                                          const TrilinosWrappers::MPI::Vector &solution,
                                          const double                         time,
                                          MaterialPointStorage<dim>           &material_points,
                                          const AffineConstraints<double>     &hanging,
                                          const AffineConstraints<double>     &newton,
                                          const RowTransforms<dim>            *row_transforms,
                                          const AssemblyTargets               &targets,
                                          AssemblyCache                       *cache) const
  {
    Assert(targets.residual != nullptr && targets.external_force != nullptr, ExcInternalError());

    Setup setup;
    fill_setup(setup);
    setup.solution = &solution;
    setup.time = time;
    setup.material_points = &material_points;
    setup.hanging = &hanging;
    setup.newton = &newton;
    setup.row_transforms = row_transforms;
    setup.targets = &targets;
    setup.need_matrix = targets.matrix != nullptr;
    prepare_cache(dof_handler, solution, time, cache, setup);
    if (cache != nullptr)
    {
      // the owner changes `state` whenever the material points may have been replaced
      const std::size_t n_cells = dof_handler.get_triangulation().n_active_cells();
      if (!cache->points_valid || cache->points_state != cache->state
          || cache->points.size() != n_cells * setup.n_q)
      {
        cache->points.assign(n_cells * setup.n_q, nullptr);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
          {
            const auto shared = material_points.get_data(cell);
            AssertDimension(shared.size(), setup.n_q);
            for (unsigned int q = 0; q < setup.n_q; ++q)
              cache->points[cell->active_cell_index() * setup.n_q + q] = shared[q].get();
          }
        cache->points_state = cache->state;
        cache->points_valid = true;
      }
      setup.point_table = cache->points.data();
    }

    prepare_slots(dof_handler, cache, setup);

    // The cell loop on the threads of DEAL_II_NUM_THREADS (step-44): the worker fills one cell's
    // CopyData, the copier adds it to the targets in cell order. On one thread the same in a
    // plain loop with the kept scratch (what WorkStream does then, without building the scratch
    // and its three FEValues anew for every assembly).
    if (MultithreadInfo::n_threads() == 1)
    {
      if (!kept_scratch)
      {
        kept_scratch = std::make_unique<ScratchData>(mapping, fe, cell_quadrature, face_quadrature);
        kept_copy = std::make_unique<CopyData>(setup.n_dofs);
      }
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          assemble_one_cell(cell, setup, *kept_scratch, *kept_copy);
          copy_local_to_global(*kept_copy, setup);
        }
    }
    else
    {
      using CellFilter = FilteredIterator<typename DoFHandler<dim>::active_cell_iterator>;
      WorkStream::run(
          CellFilter(IteratorFilters::LocallyOwnedCell(), dof_handler.begin_active()),
          CellFilter(IteratorFilters::LocallyOwnedCell(), dof_handler.end()),
          [this, &setup](const typename DoFHandler<dim>::active_cell_iterator &cell,
                         ScratchData                                          &scratch,
                         CopyData &copy) { assemble_one_cell(cell, setup, scratch, copy); },
          [this, &setup](const CopyData &copy) { copy_local_to_global(copy, setup); },
          ScratchData(mapping, fe, cell_quadrature, face_quadrature),
          CopyData(setup.n_dofs));
    }

    add_row_transform_offsets(dof_handler, setup);
    if (setup.store)
    {
      // a failed assembly is never reused; a successful one is the state of the next reuse
      cache->valid = setup.ok;
      cache->with_matrix = setup.need_matrix;
    }

    targets.residual->compress(VectorOperation::add);
    targets.external_force->compress(VectorOperation::add);
    if (targets.free_residual != nullptr)
      targets.free_residual->compress(VectorOperation::add);
    if (setup.need_matrix)
    {
      targets.matrix->compress(VectorOperation::add);
      targets.rhs->compress(VectorOperation::add);
    }

    // Agree on the outcome across ranks; the message comes from the lowest failing rank.
    const MPI_Comm     comm = dof_handler.get_communicator();
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int bad_rank = Utilities::MPI::min(setup.ok ? n_ranks : my_rank, comm);
    AssemblyStatus     status;
    status.min_jacobian = Utilities::MPI::min(setup.min_jacobian, comm);
    if (bad_rank < n_ranks)
    {
      status.ok = false;
      status.message = Utilities::MPI::broadcast(comm, setup.message, bad_rank);
    }
    return status;
  }

  template <int dim>
  void Assembler<dim>::prepare_cache(const DoFHandler<dim>               &dof_handler,
                                     const TrilinosWrappers::MPI::Vector &solution,
                                     const double                         time,
                                     AssemblyCache                       *cache,
                                     Setup                               &setup) const
  {
    setup.cache = cache;
    if (cache == nullptr)
      return;
    const std::size_t n_cells = dof_handler.get_triangulation().n_active_cells();
    const std::size_t n_dofs = setup.n_dofs;
    if (n_cells * (n_dofs * n_dofs + n_dofs + 1) * sizeof(double) > cache->max_bytes)
    {
      cache->valid = false;
      cache->solution = {};
      cache->matrices = {};
      cache->residuals = {};
      cache->min_jacobian = {};
      return;
    }
    // the displacement with its ghost entries, compared bit for bit
    const Epetra_MultiVector &values = solution.trilinos_vector();
    const std::size_t         n_values = values.MyLength();
    const double             *first = values[0];
    setup.reuse = cache->valid && cache->cached_state == cache->state
                  && cache->min_jacobian.size() == n_cells && cache->time == time
                  && (cache->with_matrix || !setup.need_matrix)
                  && cache->solution.size() == n_values
                  && std::memcmp(cache->solution.data(), first, n_values * sizeof(double)) == 0;
    if (setup.reuse)
    {
      ++cache->hits;
      return;
    }
    ++cache->misses;
    setup.store = true;
    cache->valid = false;
    cache->cached_state = cache->state;
    cache->time = time;
    cache->solution.assign(first, first + n_values);
    cache->residuals.resize(n_cells * n_dofs);
    cache->min_jacobian.resize(n_cells);
    cache->matrices.resize(setup.need_matrix ? n_cells * n_dofs * n_dofs : 0);
  }

  template <int dim>
  void Assembler<dim>::prepare_slots(const DoFHandler<dim> &dof_handler,
                                     AssemblyCache         *cache,
                                     Setup                 &setup) const
  {
    if (cache == nullptr)
      return;
    const AssemblyTargets &targets = *setup.targets;
    const std::size_t      n_cells = dof_handler.get_triangulation().n_active_cells();
    const std::size_t      n = setup.n_dofs;
    Epetra_FEVector       &residual = targets.residual->trilinos_vector();
    // the target vectors share one map (their local indices are those of the table)
    const auto same_map = [&](const TrilinosWrappers::MPI::Vector *v)
    { return v == nullptr || v->trilinos_vector().Map().SameAs(residual.Map()); };
    if (!same_map(targets.external_force) || !same_map(targets.free_residual)
        || !same_map(targets.rhs))
      return;
    if (!setup.need_matrix)
    {
      // residual only: the tables of the last matrix assembly on this pattern, if any
      if (!cache->slots_valid || cache->slots_pattern != cache->pattern
          || cache->slot_rows.size() != n_cells * n)
        return;
      setup.slots = cache;
      setup.residual_values = residual[0];
      setup.external_values = targets.external_force->trilinos_vector()[0];
      setup.free_values = targets.free_residual != nullptr
                              ? targets.free_residual->trilinos_vector()[0]
                              : nullptr;
      return;
    }
    const Epetra_CrsMatrix &matrix = targets.matrix->trilinos_matrix();
    Epetra_FEVector        &rhs = targets.rhs->trilinos_vector();
    if (!cache->slots_valid || cache->slots_pattern != cache->pattern
        || cache->slots_matrix != &matrix || cache->slot_rows.size() != n_cells * n)
    {
      cache->slots_valid = false;
      cache->slot_rows = {};
      cache->slot_columns = {};
      cache->slot_rhs = {};
      const std::size_t bytes
          = n_cells * n * (sizeof(double *) + 2 * sizeof(std::int32_t) * (1 + n));
      if (bytes > cache->max_bytes || !matrix.Filled())
        return;
      cache->slot_rows.assign(n_cells * n, nullptr);
      cache->slot_columns.assign(n_cells * n * n, 0);
      cache->slot_rhs.assign(n_cells * n, 0);
      using IndexType = TrilinosWrappers::types::int_type;
      std::vector<types::global_dof_index> dofs(n);
      std::vector<int>                     columns(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          const std::size_t base = cell->active_cell_index() * n;
          bool              found = true;
          for (unsigned int j = 0; found && j < n; ++j)
          {
            columns[j] = matrix.ColMap().LID(static_cast<IndexType>(dofs[j]));
            found = columns[j] >= 0;
          }
          for (unsigned int i = 0; found && i < n; ++i)
          {
            const int row = matrix.RowMap().LID(static_cast<IndexType>(dofs[i]));
            const int rhs_row = rhs.Map().LID(static_cast<IndexType>(dofs[i]));
            int       n_entries = 0;
            double   *values = nullptr;
            int      *indices = nullptr;
            found = row >= 0 && rhs_row >= 0
                    && matrix.ExtractMyRowView(row, n_entries, values, indices) == 0;
            if (!found)
              break;
            cache->slot_rows[base + i] = values;
            cache->slot_rhs[base + i] = rhs_row;
            int *const end = indices + n_entries;
            const bool sorted = std::is_sorted(indices, end);
            for (unsigned int j = 0; found && j < n; ++j)
            {
              const int *const at = sorted ? std::lower_bound(indices, end, columns[j])
                                           : std::find(indices, end, columns[j]);
              found = at != end && *at == columns[j];
              cache->slot_columns[(base + i) * n + j] = static_cast<std::int32_t>(at - indices);
            }
          }
          if (!found)
            std::fill_n(cache->slot_rows.begin() + base, n, nullptr); // deal.II's path
        }
      cache->slots_pattern = cache->pattern;
      cache->slots_matrix = &matrix;
      cache->slots_valid = true;
    }
    setup.slots = cache;
    setup.residual_values = residual[0];
    setup.external_values = targets.external_force->trilinos_vector()[0];
    setup.free_values
        = targets.free_residual != nullptr ? targets.free_residual->trilinos_vector()[0] : nullptr;
    setup.rhs_values = rhs[0];
  }

  template <int dim>
  std::vector<Tensor<2, 3>> Assembler<dim>::material_deformation_gradients(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const TrilinosWrappers::MPI::Vector                  &solution) const
  {
    Setup setup;
    fill_setup(setup);
    setup.solution = &solution;
    setup.check_inversion = false;
    ScratchData                      scratch(mapping, fe, cell_quadrature, face_quadrature);
    CopyData                         copy(setup.n_dofs);
    const FEValuesExtractors::Vector displacement(0);
    FEValues<dim>                   &fe_values = scratch.cell.fe_values;
    fe_values.reinit(cell);
    cell->get_dof_values(solution, scratch.cell.local_u.begin(), scratch.cell.local_u.end());
    fe_values[displacement].get_function_gradients_from_local_dof_values(scratch.cell.local_u,
                                                                         scratch.cell.grad_u);
    fe_values[displacement].get_function_values_from_local_dof_values(scratch.cell.local_u,
                                                                      scratch.cell.u_values);
    std::vector<Tensor<2, 3>> F(setup.n_q);
    for (unsigned int q = 0; q < setup.n_q; ++q)
      F[q] = kinematics.deformation_gradient(
          scratch.cell.grad_u[q], scratch.cell.u_values[q], fe_values.quadrature_point(q));
    if (!setup.f_bar)
      return F;

    // the F-bar reference and point scaling of assemble_cell()
    f_bar_reference(cell, setup, scratch.cell, scratch.f_bar, copy);
    for (unsigned int q = 0; q < setup.n_q; ++q)
      F[q] = f_bar_point(setup, scratch.f_bar, F[q], determinant(F[q])).F_material;
    return F;
  }

  template class Assembler<2>;
  template class Assembler<3>;
} // namespace ausroll::mechanics
