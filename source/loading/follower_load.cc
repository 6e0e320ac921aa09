#include <rollnip/boundary_ids.h>
#include <rollnip/fe_fields.h>
#include <rollnip/loading/follower_load.h>
#include <rollnip/loading/pressure_load.h>

namespace rollnip
{
  FollowerLoad::FollowerLoad(const Parameters::AllParameters &parameters,
                             const bool                       linear_theory)
      : parameters(parameters)
      , linear(linear_theory)
  {
    auto load =
      std::make_shared<PressureLoad>(parameters.load, parameters.geometry);
    pressure = [load](const double theta, const double lambda) {
      return lambda * load->value(theta);
    };
  }

  bool
  FollowerLoad::acts_on(
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

  std::unique_ptr<FEFaceValues<dim>>
  FollowerLoad::make_face_values(const Mapping<dim>       &mapping,
                                 const FiniteElement<dim> &fe) const
  {
    return std::make_unique<FEFaceValues<dim>>(mapping,
                                               fe,
                                               FEFields::face_quadrature(fe),
                                               update_values |
                                                 update_gradients |
                                                 update_normal_vectors |
                                                 update_quadrature_points |
                                                 update_JxW_values);
  }

  Tensor<1, dim>
  FollowerLoad::current_area_normal(const Tensor<2, dim> &grad_u,
                                    const Tensor<1, dim> &N) const
  {
    if (linear)
      return N;
    return cofactor(unit_symmetric_tensor<dim>() + grad_u) * N;
  }
} // namespace rollnip
