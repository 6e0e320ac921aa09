#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <rollnip/fe_fields.h>
#include <rollnip/rolling/steady_rolling.h>

namespace rollnip
{
  namespace
  {
    /// The derivative of S_iso at @p grad_u along each unit dF_ab: linear
    /// theory's exact one, finite strain's by central differences.
    std::array<Tensor<2, dim>, dim * dim>
    isochoric_derivatives(const Tensor<2, dim> &grad_u,
                          const double          C1,
                          const double          C2,
                          const bool            linear)
    {
      std::array<Tensor<2, dim>, dim * dim> d;
      constexpr double                      h = 1e-6;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          {
            Tensor<2, dim> e;
            e[a][b] = 1;
            d[a * dim + b] =
              linear ? isochoric_stress(e, C1, C2, true)
                     : (isochoric_stress(grad_u + h * e, C1, C2, false) -
                        isochoric_stress(grad_u - h * e, C1, C2, false)) /
                         (2 * h);
          }
      return d;
    }

    Tensor<2, dim>
    along(const std::array<Tensor<2, dim>, dim * dim> &d,
          const Tensor<2, dim>                        &dF)
    {
      Tensor<2, dim> r;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          r += dF[a][b] * d[a * dim + b];
      return r;
    }
  } // namespace

  /// The mixed residual of the long-term law plus the frozen overstress,
  /// P = P_e(F, q) + F S_v (linear theory: + S_v), S_v = c S_iso(F) + H,
  /// and its tangent.
  void
  SteadyRolling::add_cell(const DoFHandler<dim>::active_cell_iterator &cell,
                          FEValues<dim>          &fe_values,
                          FullMatrix<double>     &K,
                          dealii::Vector<double> &R) const
  {
    const unsigned int n   = fe.n_dofs_per_cell();
    const unsigned int nq  = fe_values.n_quadrature_points;
    const unsigned int l   = cell->material_id();
    const auto        &law = *laws[l];
    const bool   linear = scene.material.theory == Parameters::Theory::linear;
    const double C1     = scene.material.layer_C1[l],
                 C2     = scene.material.layer_C2[l];
    std::vector<Tensor<2, dim>> grad_u(nq), grad_phi(n), dP(n);
    std::vector<double>         q_values(nq), psi(n);
    fe_values.reinit(cell);
    fe_values[FEFields::displacement].get_function_gradients(solution, grad_u);
    fe_values[FEFields::pressure].get_function_values(solution, q_values);
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    for (unsigned int q = 0; q < nq; ++q)
      {
        const PointState    &point = points[cell->active_cell_index() * nq + q];
        const Tensor<2, dim> F     = I + grad_u[q];
        const Tensor<2, dim> Sv =
          point.c * isochoric_stress(grad_u[q], C1, C2, linear) + point.H;
        const Tensor<2, dim> P =
          law.piola(F, q_values[q]) + (linear ? Sv : F * Sv);
        const auto           dS    = point.c != 0
                                       ? isochoric_derivatives(grad_u[q], C1, C2, linear)
                                       : std::array<Tensor<2, dim>, dim * dim>();
        const Tensor<2, dim> dP_dq = law.pressure_direction(F);
        const double         JxW   = fe_values.JxW(q);
        for (unsigned int k = 0; k < n; ++k)
          {
            grad_phi[k] = fe_values[FEFields::displacement].gradient(k, q);
            psi[k]      = fe_values[FEFields::pressure].value(k, q);
            dP[k]       = law.piola_derivative(F, q_values[q], grad_phi[k]);
            const Tensor<2, dim> dSv = point.c * along(dS, grad_phi[k]);
            dP[k] += linear ? dSv : grad_phi[k] * Sv + F * dSv;
          }
        const double g = law.constraint(F);
        for (unsigned int i = 0; i < n; ++i)
          {
            R(i) += (scalar_product(P, grad_phi[i]) + psi[i] * g) * JxW;
            const double gi = scalar_product(dP_dq, grad_phi[i]);
            for (unsigned int j = 0; j < n; ++j)
              K(i, j) += (scalar_product(dP[j], grad_phi[i]) + gi * psi[j] +
                          psi[i] * scalar_product(dP_dq, grad_phi[j])) *
                         JxW;
          }
      }
  }

  /// The system K du = -R with the constraints (bond, active contact
  /// nodes) and the unconstrained R, whose entries at the surface are the
  /// contact forces.
  void
  SteadyRolling::assemble()
  {
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            FEFields::cell_quadrature(fe),
                            update_values | update_gradients |
                              update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   K(n, n);
    dealii::Vector<double>               R(n);
    std::vector<types::global_dof_index> dofs(n);
    matrix    = 0;
    rhs       = 0;
    reactions = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        K = 0;
        R = 0;
        add_cell(cell, fe_values, K, R);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          reactions(dofs[i]) += R(i);
        R *= -1.;
        constraints.distribute_local_to_global(K, R, dofs, matrix, rhs);
      }
  }
} // namespace rollnip
