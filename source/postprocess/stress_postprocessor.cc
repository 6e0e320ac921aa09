#include <rollnip/postprocess/stress_postprocessor.h>
#include <rollnip/postprocess/stress_state.h>

namespace rollnip
{
  StressPostprocessor::StressPostprocessor(const MaterialTable &materials)
      : materials(materials)
  {}

  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    return {"sigma_xx",
            "sigma_yy",
            "sigma_xy",
            "sigma_zz",
            "sigma_rr",
            "sigma_thetatheta",
            "sigma_rtheta",
            "von_mises",
            "hydrostatic_pressure",
            "J",
            "max_principal_stretch",
            "min_principal_stretch",
            "max_principal_strain",
            // Tensors (dim x dim, row by row), for ParaView's tensor
            // filters: the in-plane Cauchy stress and the Green-Lagrange
            // strain E = (F^T F - I) / 2.
            "cauchy_stress",
            "cauchy_stress",
            "cauchy_stress",
            "cauchy_stress",
            "green_lagrange_strain",
            "green_lagrange_strain",
            "green_lagrange_strain",
            "green_lagrange_strain"};
  }

  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(13, DataComponentInterpretation::component_is_scalar);
    interpretation.insert(
      interpretation.end(),
      2 * dim * dim,
      DataComponentInterpretation::component_is_part_of_tensor);
    return interpretation;
  }

  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return update_values | update_gradients | update_quadrature_points;
  }

  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed) const
  {
    const auto cell = inputs.template get_cell<dim>();
    for (unsigned int p = 0; p < inputs.solution_values.size(); ++p)
      {
        Tensor<2, dim> grad_u;
        Tensor<1, dim> u;
        for (unsigned int i = 0; i < dim; ++i)
          {
            u[i]      = inputs.solution_values[p][i];
            grad_u[i] = inputs.solution_gradients[p][i];
          }
        const StressState s =
          evaluate_stress_state(materials,
                                *cell,
                                grad_u,
                                inputs.solution_values[p][dim],
                                inputs.evaluation_points[p],
                                u);
        const double           out[]     = {s.sigma[0][0],
                                            s.sigma[1][1],
                                            s.sigma[0][1],
                                            s.sigma_zz,
                                            s.sigma_rr,
                                            s.sigma_tt,
                                            s.sigma_rt,
                                            s.von_mises,
                                            s.hydrostatic_pressure,
                                            s.J,
                                            s.max_stretch,
                                            s.min_stretch,
                                            std::max(s.max_stretch - 1., 1. - s.min_stretch)};
        constexpr unsigned int n_scalars = sizeof(out) / sizeof(out[0]);
        for (unsigned int k = 0; k < n_scalars; ++k)
          computed[p][k] = out[k];
        const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + grad_u;
        const Tensor<2, dim> E =
          0.5 * (transpose(F) * F - unit_symmetric_tensor<dim>());
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              computed[p][n_scalars + dim * i + j]             = s.sigma[i][j];
              computed[p][n_scalars + dim * dim + dim * i + j] = E[i][j];
            }
      }
  }
} // namespace rollnip
