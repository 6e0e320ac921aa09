#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/grid/filtered_iterator.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/problem.h>

#include <cmath>

namespace rollnip
{
  namespace
  {
    /// Per-thread FEValues and work arrays of the cell integrals.
    struct AssemblyScratch
    {
      AssemblyScratch(const Mapping<dim>                &mapping,
                      const FiniteElement<dim>          &fe,
                      const Quadrature<dim>             &quadrature,
                      std::unique_ptr<FEFaceValues<dim>> face_values)
          : fe_values(mapping,
                      fe,
                      quadrature,
                      update_values | update_gradients | update_JxW_values)
          , fe_face_values(std::move(face_values))
          , grad_u(quadrature.size())
          , q_values(quadrature.size())
          , grad_phi(fe.n_dofs_per_cell())
          , psi(fe.n_dofs_per_cell())
          , face_grad_u(fe_face_values->n_quadrature_points)
          , face_phi(fe.n_dofs_per_cell())
          , face_grad_phi(fe.n_dofs_per_cell())
          , dP(fe.n_dofs_per_cell())
      {}

      // WorkStream copies the scratch object once per thread.
      AssemblyScratch(const AssemblyScratch &other)
          : fe_values(other.fe_values.get_mapping(),
                      other.fe_values.get_fe(),
                      other.fe_values.get_quadrature(),
                      other.fe_values.get_update_flags())
          , fe_face_values(std::make_unique<FEFaceValues<dim>>(
              other.fe_face_values->get_mapping(),
              other.fe_face_values->get_fe(),
              other.fe_face_values->get_quadrature(),
              other.fe_face_values->get_update_flags()))
          , grad_u(other.grad_u)
          , q_values(other.q_values)
          , grad_phi(other.grad_phi)
          , psi(other.psi)
          , face_grad_u(other.face_grad_u)
          , face_phi(other.face_phi)
          , face_grad_phi(other.face_grad_phi)
          , dP(other.dP)
      {}

      FEValues<dim>                      fe_values;
      std::unique_ptr<FEFaceValues<dim>> fe_face_values;
      std::vector<Tensor<2, dim>>        grad_u;
      std::vector<double>                q_values;
      std::vector<Tensor<2, dim>>        grad_phi;
      std::vector<double>                psi;
      std::vector<Tensor<2, dim>>        face_grad_u;
      std::vector<Tensor<1, dim>>        face_phi;
      std::vector<Tensor<2, dim>>        face_grad_phi;
      std::vector<Tensor<2, dim>>        dP;
    };

    /// One cell's contributions, handed to the (serial) copier.
    struct AssemblyCopy
    {
      explicit AssemblyCopy(const unsigned int n_dofs)
          : cell_matrix(n_dofs, n_dofs)
          , cell_rhs(n_dofs)
          , cell_load(n_dofs)
          , dof_indices(n_dofs)
          , pressure_mass(n_dofs)
      {}

      FullMatrix<double>                   cell_matrix;
      Vector<double>                       cell_rhs;
      Vector<double>                       cell_load;
      std::vector<types::global_dof_index> dof_indices;
      Vector<double>     pressure_mass; ///< diagonal of int psi_i psi_j dV
      FullMatrix<double> preconditioner_matrix; ///< [A 0; 0 M_p/G], cell
      double             min_J = 0;
    };
  } // namespace

  /**
   * The residual of the mixed problem (doc/intro.md, eq. 3.1)
   *   R_u = int P(F, q) : Grad v dV - int h . v dA,
   *   R_q = int w (J - 1) dV,
   * and its derivative. The follower load on boundaries with condition
   * 'pressure' is h dA = -lambda f(Theta) cof(F) N dA (eq. 4.1); since
   * cof F is linear in F in 2D, its derivative is
   *   d(h dA)[du] = -lambda f(Theta) cof(Grad du) N dA,
   * which is exact and not symmetric. Theta is the reference angle of the
   * quadrature point. In linear theory the load is -lambda f N on the
   * undeformed surface and does not depend on u.
   *
   * The cell integrals run on all threads deal.II was given (WorkStream);
   * adding them into the Trilinos objects is serial, in the copier.
   */
  double
  RollProblem::assemble(const double load_fraction, const bool with_matrix)
  {
    TimerOutput::Scope t(timer,
                         with_matrix ? "assembly" : "assembly (residual)");
    ++n_assemblies;

    const unsigned int degree = parameters.discretization.displacement_degree();
    const FEValuesExtractors::Vector displacement(0);
    const FEValuesExtractors::Scalar pressure_unknown(dim);
    const bool                       linear = material.is_linear();
    const Tensor<2, dim>             I      = unit_symmetric_tensor<dim>();
    const bool with_preconditioner          = use_iterative_solver();

    auto cell_worker = [&](const typename DoFHandler<dim>::active_cell_iterator
                                           &cell,
                           AssemblyScratch &scratch,
                           AssemblyCopy    &copy) {
      FEValues<dim>     &fe_values      = scratch.fe_values;
      FEFaceValues<dim> &fe_face_values = *scratch.fe_face_values;
      const unsigned int n_dofs         = copy.dof_indices.size();
      const unsigned int n_q            = fe_values.n_quadrature_points;
      auto              &grad_phi       = scratch.grad_phi;
      auto              &psi            = scratch.psi;
      auto              &dP             = scratch.dP;

      fe_values.reinit(cell);
      copy.cell_matrix   = 0;
      copy.cell_rhs      = 0;
      copy.cell_load     = 0;
      copy.pressure_mass = 0;

      copy.min_J = std::numeric_limits<double>::max();
      fe_values[displacement].get_function_gradients(locally_relevant_solution,
                                                     scratch.grad_u);
      fe_values[pressure_unknown].get_function_values(locally_relevant_solution,
                                                      scratch.q_values);

      for (unsigned int q = 0; q < n_q; ++q)
        {
          const Tensor<2, dim> F     = I + scratch.grad_u[q];
          copy.min_J                 = std::min(copy.min_J, determinant(F));
          const double         p     = scratch.q_values[q];
          const Tensor<2, dim> P     = material.piola(F, p);
          const Tensor<2, dim> dP_dq = material.pressure_direction(F);
          const double         g     = material.constraint(F);
          const double         JxW   = fe_values.JxW(q);
          for (unsigned int k = 0; k < n_dofs; ++k)
            {
              grad_phi[k] = fe_values[displacement].gradient(k, q);
              psi[k]      = fe_values[pressure_unknown].value(k, q);
            }
          if (with_matrix)
            for (unsigned int j = 0; j < n_dofs; ++j)
              dP[j] = material.piola_derivative(F, p, grad_phi[j]);

          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              copy.cell_rhs(i) +=
                (scalar_product(P, grad_phi[i]) + psi[i] * g) * JxW;
              if (with_matrix && with_preconditioner)
                copy.pressure_mass(i) += psi[i] * psi[i] * JxW;
              if (!with_matrix)
                continue;
              const double gi = scalar_product(dP_dq, grad_phi[i]);
              for (unsigned int j = 0; j < n_dofs; ++j)
                copy.cell_matrix(i, j) +=
                  (scalar_product(dP[j], grad_phi[i]) + gi * psi[j] +
                   psi[i] * scalar_product(dP_dq, grad_phi[j])) *
                  JxW;
            }
        }

      for (const auto f : cell->face_indices())
        {
          if (!is_pressure_face(cell, f))
            continue;
          fe_face_values.reinit(cell, f);
          fe_face_values[displacement].get_function_gradients(
            locally_relevant_solution, scratch.face_grad_u);
          for (unsigned int q = 0; q < fe_face_values.n_quadrature_points; ++q)
            {
              const Point<dim>     &X     = fe_face_values.quadrature_point(q);
              const double          theta = std::atan2(X[1], X[0]);
              const double          f     = pressure(theta, load_fraction);
              const Tensor<1, dim> &N     = fe_face_values.normal_vector(q);
              const double          JxW   = fe_face_values.JxW(q);
              // Traction per reference area, pointing into the body.
              const Tensor<1, dim> h =
                -f * current_area_normal(scratch.face_grad_u[q], N);
              for (unsigned int k = 0; k < n_dofs; ++k)
                {
                  scratch.face_phi[k] =
                    fe_face_values[displacement].value(k, q);
                  scratch.face_grad_phi[k] =
                    fe_face_values[displacement].gradient(k, q);
                }
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const double load_i = h * scratch.face_phi[i] * JxW;
                  copy.cell_rhs(i) -= load_i;
                  copy.cell_load(i) += load_i;
                  if (!with_matrix || linear)
                    continue;
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    copy.cell_matrix(i, j) +=
                      f * (cofactor(scratch.face_grad_phi[j]) * N) *
                      scratch.face_phi[i] * JxW;
                }
            }
        }
      cell->get_dof_indices(copy.dof_indices);

      if (with_matrix && with_preconditioner)
        {
          const double G = material.shear_modulus();
          copy.preconditioner_matrix.reinit(n_dofs, n_dofs);
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const bool p_i = fe->system_to_component_index(i).first == dim;
              if (p_i)
                copy.preconditioner_matrix(i, i) = copy.pressure_mass(i) / G;
              else
                for (unsigned int j = 0; j < n_dofs; ++j)
                  if (fe->system_to_component_index(j).first != dim)
                    copy.preconditioner_matrix(i, j) = copy.cell_matrix(i, j);
            }
        }
    };

    double min_J  = std::numeric_limits<double>::max();
    auto   copier = [&](const AssemblyCopy &copy) {
      min_J = std::min(min_J, copy.min_J);
      if (with_matrix)
        constraints.distribute_local_to_global(copy.cell_matrix,
                                               copy.cell_rhs,
                                               copy.dof_indices,
                                               system_matrix,
                                               system_rhs);
      else
        constraints.distribute_local_to_global(copy.cell_rhs,
                                               copy.dof_indices,
                                               system_rhs);
      constraints.distribute_local_to_global(copy.cell_load,
                                             copy.dof_indices,
                                             external_force);
      if (with_matrix && with_preconditioner)
        constraints.distribute_local_to_global(copy.preconditioner_matrix,
                                               copy.dof_indices,
                                               preconditioner_matrix);
    };

    if (with_matrix)
      system_matrix = 0;
    if (with_matrix && with_preconditioner)
      preconditioner_matrix = 0;
    system_rhs     = 0;
    external_force = 0;

    using CellFilter =
      FilteredIterator<typename DoFHandler<dim>::active_cell_iterator>;
    WorkStream::run(CellFilter(IteratorFilters::LocallyOwnedCell(),
                               dof_handler.begin_active()),
                    CellFilter(IteratorFilters::LocallyOwnedCell(),
                               dof_handler.end()),
                    cell_worker,
                    copier,
                    AssemblyScratch(*mapping,
                                    *fe,
                                    QGauss<dim>(degree + 1),
                                    make_pressure_face_values()),
                    AssemblyCopy(fe->n_dofs_per_cell()));

    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    if (with_matrix && with_preconditioner)
      preconditioner_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    external_force.compress(VectorOperation::add);
    return Utilities::MPI::min(min_J, mpi_communicator);
  }
} // namespace rollnip

namespace rollnip
{
  /**
   * d R_u / d s for the extra follower pressure s g(Theta) at the current
   * state: from (4.1), int g (cof F N) . v dA (N dA in linear theory). The
   * contact iteration uses these as right-hand sides for the sensitivities
   * of the surface position to the parameters of the pressure.
   */
  TrilinosWrappers::MPI::Vector
  RollProblem::pressure_load_derivative(
    const std::function<double(double)> &g) const
  {
    const unsigned int degree = parameters.discretization.displacement_degree();
    const QGauss<dim - 1>            face_quadrature(degree + 1);
    const auto                       face_values = make_pressure_face_values();
    FEFaceValues<dim>               &fe_face_values = *face_values;
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n_dofs = fe->n_dofs_per_cell();
    Vector<double>                   cell_vector(n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);
    std::vector<Tensor<2, dim>>          grad_u(face_quadrature.size());
    TrilinosWrappers::MPI::Vector result(locally_owned_dofs, mpi_communicator);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_vector  = 0;
          bool touched = false;
          for (const auto f : cell->face_indices())
            if (is_pressure_face(cell, f))
              {
                fe_face_values.reinit(cell, f);
                fe_face_values[displacement].get_function_gradients(
                  locally_relevant_solution, grad_u);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    const Point<dim> &X  = fe_face_values.quadrature_point(q);
                    const double      gq = g(std::atan2(X[1], X[0]));
                    if (gq == 0)
                      continue;
                    touched                 = true;
                    const Tensor<1, dim> &N = fe_face_values.normal_vector(q);
                    const Tensor<1, dim>  nda =
                      current_area_normal(grad_u[q], N);
                    for (unsigned int i = 0; i < n_dofs; ++i)
                      cell_vector(i) +=
                        gq * nda * fe_face_values[displacement].value(i, q) *
                        fe_face_values.JxW(q);
                  }
              }
          if (!touched)
            continue;
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(cell_vector,
                                                 dof_indices,
                                                 result);
        }
    result.compress(VectorOperation::add);
    return result;
  }

  bool
  RollProblem::is_pressure_face(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    f) const
  {
    if (!cell->face(f)->at_boundary())
      return false;
    const types::boundary_id b = cell->face(f)->boundary_id();
    return b < BoundaryIds::n_boundaries &&
           parameters.boundary_conditions.condition[b] ==
             Parameters::BoundaryCondition::pressure;
  }

  Tensor<1, dim>
  RollProblem::current_area_normal(const Tensor<2, dim> &grad_u,
                                   const Tensor<1, dim> &N) const
  {
    if (material.is_linear())
      return N;
    return cofactor(unit_symmetric_tensor<dim>() + grad_u) * N;
  }

  std::unique_ptr<FEFaceValues<dim>>
  RollProblem::make_pressure_face_values() const
  {
    const unsigned int degree = parameters.discretization.displacement_degree();
    return std::make_unique<FEFaceValues<dim>>(*mapping,
                                               *fe,
                                               QGauss<dim - 1>(degree + 1),
                                               update_values |
                                                 update_gradients |
                                                 update_normal_vectors |
                                                 update_quadrature_points |
                                                 update_JxW_values);
  }
} // namespace rollnip
