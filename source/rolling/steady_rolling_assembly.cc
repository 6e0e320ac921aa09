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

  /// The mixed residual of the long-term law, P_e(F, q) : Grad v +
  /// w c(F), and its tangent on the 2 x 2 Gauss points.
  void
  SteadyRolling::add_cell(const DoFHandler<dim>::active_cell_iterator &cell,
                          FEValues<dim>          &fe_values,
                          FullMatrix<double>     &K,
                          dealii::Vector<double> &R) const
  {
    const unsigned int          n   = fe.n_dofs_per_cell();
    const unsigned int          nq  = fe_values.n_quadrature_points;
    const auto                 &law = *laws[cell->material_id()];
    std::vector<Tensor<2, dim>> grad_u(nq), grad_phi(n);
    std::vector<double>         q_values(nq), psi(n);
    fe_values.reinit(cell);
    fe_values[FEFields::displacement].get_function_gradients(solution, grad_u);
    fe_values[FEFields::pressure].get_function_values(solution, q_values);
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    for (unsigned int q = 0; q < nq; ++q)
      {
        const Tensor<2, dim> F     = I + grad_u[q];
        const Tensor<2, dim> P     = law.piola(F, q_values[q]);
        const Tensor<2, dim> dP_dq = law.pressure_direction(F);
        const double         g     = law.constraint(F);
        const double         JxW   = fe_values.JxW(q);
        for (unsigned int k = 0; k < n; ++k)
          {
            grad_phi[k] = fe_values[FEFields::displacement].gradient(k, q);
            psi[k]      = fe_values[FEFields::pressure].value(k, q);
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            R(i) += (scalar_product(P, grad_phi[i]) + psi[i] * g) * JxW;
            const double gi = scalar_product(dP_dq, grad_phi[i]);
            for (unsigned int j = 0; j < n; ++j)
              K(i, j) +=
                (scalar_product(
                   law.piola_derivative(F, q_values[q], grad_phi[j]),
                   grad_phi[i]) +
                 gi * psi[j] + psi[i] * scalar_product(dP_dq, grad_phi[j])) *
                JxW;
          }
      }
  }

  /// The frozen overstress on the cell's two samples (the points where
  /// the circles carry its history, so that the stress in equilibrium is
  /// the one whose work is the dissipation): P_v = F S_v (linear theory:
  /// S_v), S_v = c S_iso(F) + H, and its tangent.
  void
  SteadyRolling::add_overstress(
    const DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                               &at_samples,
    FullMatrix<double>                          &K,
    dealii::Vector<double>                      &R) const
  {
    const unsigned int n = fe.n_dofs_per_cell();
    const unsigned int l = cell->material_id();
    const bool   linear  = scene.material.theory == Parameters::Theory::linear;
    const double C1      = scene.material.layer_C1[l],
                 C2      = scene.material.layer_C2[l];
    std::vector<Tensor<2, dim>> grad_u(2), grad_phi(n);
    at_samples.reinit(cell);
    at_samples[FEFields::displacement].get_function_gradients(solution, grad_u);
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    for (unsigned int a = 0; a < 2; ++a)
      {
        const Sample &s = samples[2 * cell->active_cell_index() + a];
        if (s.c == 0 && s.H_cartesian.norm() == 0)
          continue;
        const Tensor<2, dim> F = I + grad_u[a];
        const Tensor<2, dim> Sv =
          s.c * isochoric_stress(grad_u[a], C1, C2, linear) + s.H_cartesian;
        const Tensor<2, dim> P = linear ? Sv : F * Sv;
        const auto dS = isochoric_derivatives(grad_u[a], C1, C2, linear);
        for (unsigned int k = 0; k < n; ++k)
          grad_phi[k] = at_samples[FEFields::displacement].gradient(k, a);
        for (unsigned int j = 0; j < n; ++j)
          {
            const Tensor<2, dim> dSv = s.c * along(dS, grad_phi[j]);
            const Tensor<2, dim> dP = linear ? dSv : grad_phi[j] * Sv + F * dSv;
            for (unsigned int i = 0; i < n; ++i)
              K(i, j) += scalar_product(dP, grad_phi[i]) * s.JxW;
          }
        for (unsigned int i = 0; i < n; ++i)
          R(i) += scalar_product(P, grad_phi[i]) * s.JxW;
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
    FEValues<dim>                        at_samples(mapping,
                             fe,
                             circle_quadrature(1).points[1],
                             update_gradients);
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
        add_overstress(cell, at_samples, K, R);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          reactions(dofs[i]) += R(i);
        R *= -1.;
        constraints.distribute_local_to_global(K, R, dofs, matrix, rhs);
      }
  }
} // namespace rollnip
