#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/problem.h>

#include <cmath>

namespace rollnip
{
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
   */
  double
  RollProblem::assemble(const double load_fraction, const bool with_matrix)
  {
    TimerOutput::Scope t(timer,
                         with_matrix ? "assembly" : "assembly (residual)");
    ++n_assemblies;

    const unsigned int degree = parameters.discretization.displacement_degree();
    const QGauss<dim>  quadrature(degree + 1);
    const QGauss<dim - 1> face_quadrature(degree + 1);
    FEValues<dim>         fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
    const auto            face_values    = make_pressure_face_values();
    FEFaceValues<dim>    &fe_face_values = *face_values;

    const unsigned int                   n_dofs = fe->n_dofs_per_cell();
    const unsigned int                   n_q    = quadrature.size();
    FullMatrix<double>                   cell_matrix(n_dofs, n_dofs);
    Vector<double>                       cell_rhs(n_dofs);
    Vector<double>                       cell_load(n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);

    const FEValuesExtractors::Vector displacement(0);
    const FEValuesExtractors::Scalar pressure_unknown(dim);
    std::vector<Tensor<2, dim>>      grad_u(n_q);
    std::vector<double>              q_values(n_q);
    std::vector<Tensor<2, dim>>      grad_phi(n_dofs);
    std::vector<double>              psi(n_dofs);
    std::vector<Tensor<2, dim>>      face_grad_u(face_quadrature.size());
    std::vector<Tensor<1, dim>>      face_phi(n_dofs);
    std::vector<Tensor<2, dim>>      face_grad_phi(n_dofs);
    std::vector<Tensor<2, dim>>      dP(n_dofs);

    const bool           linear = material.is_linear();
    const Tensor<2, dim> I      = unit_symmetric_tensor<dim>();

    if (with_matrix)
      system_matrix = 0;
    system_rhs     = 0;
    external_force = 0;
    double min_J   = std::numeric_limits<double>::max();

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_matrix = 0;
          cell_rhs    = 0;
          cell_load   = 0;
          fe_values[displacement].get_function_gradients(
            locally_relevant_solution, grad_u);
          fe_values[pressure_unknown].get_function_values(
            locally_relevant_solution, q_values);

          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Tensor<2, dim> F     = I + grad_u[q];
              min_J                      = std::min(min_J, determinant(F));
              const Tensor<2, dim> P     = material.piola(F, q_values[q]);
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
                  dP[j] =
                    material.piola_derivative(F, q_values[q], grad_phi[j]);

              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  cell_rhs(i) +=
                    (scalar_product(P, grad_phi[i]) + psi[i] * g) * JxW;
                  if (!with_matrix)
                    continue;
                  const double gi = scalar_product(dP_dq, grad_phi[i]);
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    cell_matrix(i, j) +=
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
                locally_relevant_solution, face_grad_u);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                {
                  const Point<dim>     &X = fe_face_values.quadrature_point(q);
                  const double          theta = std::atan2(X[1], X[0]);
                  const double          f     = pressure(theta, load_fraction);
                  const Tensor<1, dim> &N     = fe_face_values.normal_vector(q);
                  const double          JxW   = fe_face_values.JxW(q);
                  // Traction per reference area, pointing into the body.
                  const Tensor<1, dim> h =
                    -f * current_area_normal(face_grad_u[q], N);
                  for (unsigned int k = 0; k < n_dofs; ++k)
                    {
                      face_phi[k] = fe_face_values[displacement].value(k, q);
                      face_grad_phi[k] =
                        fe_face_values[displacement].gradient(k, q);
                    }
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    {
                      const double load_i = h * face_phi[i] * JxW;
                      cell_rhs(i) -= load_i;
                      cell_load(i) += load_i;
                      if (!with_matrix || linear)
                        continue;
                      for (unsigned int j = 0; j < n_dofs; ++j)
                        cell_matrix(i, j) += f *
                                             (cofactor(face_grad_phi[j]) * N) *
                                             face_phi[i] * JxW;
                    }
                }
            }

          cell->get_dof_indices(dof_indices);
          if (with_matrix)
            constraints.distribute_local_to_global(
              cell_matrix, cell_rhs, dof_indices, system_matrix, system_rhs);
          else
            constraints.distribute_local_to_global(cell_rhs,
                                                   dof_indices,
                                                   system_rhs);
          constraints.distribute_local_to_global(cell_load,
                                                 dof_indices,
                                                 external_force);
        }

    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
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
