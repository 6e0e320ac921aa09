#ifndef rollnip_loading_follower_load_h
#define rollnip_loading_follower_load_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <rollnip/fe_fields.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/global.h>
#include <rollnip/kinematics.h>
#include <rollnip/parameters.h>

#include <functional>
#include <memory>
#include <vector>

namespace rollnip
{
  /**
   * The follower pressure on the boundaries with condition 'pressure'
   * (doc/intro.md, eq. 4.1): a traction h dA = -f(Theta, lambda) cof(F) N
   * dA per reference area, with Theta the reference angle and lambda the
   * load fraction (N dA in linear theory). The residual, the load
   * derivative the contact iteration asks for and the resultant all
   * integrate over the same points, through for_each_point().
   */
  class FollowerLoad
  {
  public:
    /// f(Theta, lambda) [MPa].
    using Pressure = std::function<double(double, double)>;

    /// The load of Load/Pressure function, lambda f(Theta).
    FollowerLoad(const Parameters::AllParameters &parameters,
                 const bool                       linear_theory);

    /// Replaces f (the contact iteration sets its own).
    void
    set_pressure(Pressure new_pressure)
    {
      pressure = std::move(new_pressure);
    }

    double
    value(const double theta, const double lambda) const
    {
      return pressure(theta, lambda);
    }

    /// Whether face @p f of @p cell carries the load.
    bool
    acts_on(const typename DoFHandler<dim>::active_cell_iterator &cell,
            const unsigned int                                    f) const;

    /// Face values for the load integrals (FEFields::face_quadrature), with
    /// values, gradients, normals, points and JxW.
    std::unique_ptr<FEFaceValues<dim>>
    make_face_values(const Mapping<dim>       &mapping,
                     const FiniteElement<dim> &fe) const;

    /// n da / dA = cof(I + grad u) N, or N in linear theory.
    Tensor<1, dim>
    current_area_normal(const Tensor<2, dim> &grad_u,
                        const Tensor<1, dim> &N) const;

    /**
     * Calls visit(q, theta, grad_u, N, JxW) at every quadrature point of
     * every loaded face of @p cell, with @p face_values reinit'ed on the
     * face and grad_u the displacement gradient of @p solution there.
     */
    template <typename VectorType, typename Visit>
    void
    for_each_point(const typename DoFHandler<dim>::active_cell_iterator &cell,
                   FEFaceValues<dim>           &face_values,
                   const VectorType            &solution,
                   std::vector<Tensor<2, dim>> &grad_u,
                   const Visit                 &visit) const
    {
      for (const auto f : cell->face_indices())
        {
          if (!acts_on(cell, f))
            continue;
          face_values.reinit(cell, f);
          grad_u.resize(face_values.n_quadrature_points);
          face_values[FEFields::displacement].get_function_gradients(solution,
                                                                     grad_u);
          for (unsigned int q = 0; q < face_values.n_quadrature_points; ++q)
            visit(q,
                  reference_angle(face_values.quadrature_point(q)),
                  grad_u[q],
                  face_values.normal_vector(q),
                  face_values.JxW(q));
        }
    }

    bool
    is_linear() const
    {
      return linear;
    }

  private:
    const Parameters::AllParameters &parameters;
    const bool                       linear;
    Pressure                         pressure;
  };
} // namespace rollnip

#endif
