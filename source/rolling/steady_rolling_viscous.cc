#include <deal.II/fe/fe_values.h>

#include <rollnip/fe_fields.h>
#include <rollnip/rolling/periodic_relaxation.h>
#include <rollnip/rolling/steady_rolling.h>

#include <cmath>

namespace rollnip
{
  namespace
  {
    /// Polar components of @p T at angle @p phi.
    PolarTensor
    to_polar(const Tensor<2, dim> &T, const double phi)
    {
      const double c = std::cos(phi), s = std::sin(phi);
      const double xy = 0.5 * (T[0][1] + T[1][0]);
      return {{c * c * T[0][0] + 2 * c * s * xy + s * s * T[1][1],
               -c * s * T[0][0] + (c * c - s * s) * xy + c * s * T[1][1],
               s * s * T[0][0] - 2 * c * s * xy + c * c * T[1][1]}};
    }

    /// The Cartesian tensor of polar components @p P at angle @p phi.
    Tensor<2, dim>
    to_cartesian(const PolarTensor &P, const double phi)
    {
      const double   c = std::cos(phi), s = std::sin(phi);
      Tensor<2, dim> T;
      T[0][0] = c * c * P[0] - 2 * c * s * P[1] + s * s * P[2];
      T[0][1] = c * s * P[0] + (c * c - s * s) * P[1] - c * s * P[2];
      T[1][0] = T[0][1];
      T[1][1] = s * s * P[0] + 2 * c * s * P[1] + c * c * P[2];
      return T;
    }

  } // namespace

  void
  SteadyRolling::point_fields(std::vector<PolarTensor> &S,
                              std::vector<PolarTensor> &E) const
  {
    FEValues<dim> fe_values(mapping,
                            fe,
                            circle_quadrature(1).points[1],
                            update_gradients);
    const bool    linear = scene.material.theory == Parameters::Theory::linear;
    std::vector<Tensor<2, dim>> grad_u(2);
    S.resize(samples.size());
    E.resize(samples.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[FEFields::displacement].get_function_gradients(solution,
                                                                 grad_u);
        const unsigned int l = cell->material_id();
        for (unsigned int a = 0; a < 2; ++a)
          {
            const unsigned int    s  = 2 * cell->active_cell_index() + a;
            const Tensor<2, dim> &gu = grad_u[a];
            const Tensor<2, dim>  strain =
              linear ? Tensor<2, dim>(0.5 * (gu + transpose(gu)))
                      : Tensor<2, dim>(
                         0.5 * (gu + transpose(gu) + transpose(gu) * gu));
            E[s] = to_polar(strain, samples[s].theta);
            S[s] = to_polar(isochoric_stress(gu,
                                             scene.material.layer_C1[l],
                                             scene.material.layer_C2[l],
                                             linear),
                            samples[s].theta);
          }
      }
  }

  /// Every branch of every circle integrated over its periodic history
  /// (the samples' c and H), and the power dissipated: the circles'
  /// Omega times the closed integral of Q : dE (branch_work()).
  double
  SteadyRolling::circle_histories()
  {
    std::vector<PolarTensor> S, E;
    point_fields(S, E);
    const double Omega = 1e3 * speed / layout.radii().back(); // [1/s]
    double       power = 0;
    for (unsigned int k = 0; k < circle_samples.size(); ++k)
      {
        const auto              &ids = circle_samples[k];
        const unsigned int       n   = ids.size();
        std::vector<double>      theta(n);
        std::vector<PolarTensor> Sk(n), Ek(n);
        for (unsigned int m = 0; m < n; ++m)
          {
            theta[m]          = samples[ids[m]].theta;
            Sk[m]             = S[ids[m]];
            Ek[m]             = E[ids[m]];
            samples[ids[m]].c = 0;
            samples[ids[m]].H = {{0, 0, 0}};
          }
        circle_dissipation[k] = 0;
        const unsigned int l  = samples[ids[0]].layer;
        const auto        &branches =
          scene.viscous.size() == 1 ? scene.viscous[0] : scene.viscous.at(l);
        for (unsigned int b = 0; b < branches.g.size(); ++b)
          {
            const double        g = branches.g[b], tau = branches.tau[b];
            const BranchHistory h = periodic_branch(theta, Sk, g, tau, Omega);
            for (unsigned int m = 0; m < n; ++m)
              {
                samples[ids[m]].c += h.c[m];
                for (unsigned int i = 0; i < 3; ++i)
                  samples[ids[m]].H[i] += h.H[m][i];
              }
            // MPa/s = 1e6 W/m^3 over the turn's 2 pi; times the circle's
            // area per radian, MPa/s mm^2 = W/m.
            const double mean = Omega *
                                branch_work(theta, Sk, Ek, h, g, tau, Omega) /
                                (2 * numbers::PI);
            circle_dissipation[k] += 1e6 * mean;
            power += circle_weight[k] * 2 * numbers::PI * mean;
          }
      }
    return power;
  }

  /// The samples' H turned to Cartesian components.
  double
  SteadyRolling::update_history()
  {
    dissipated    = circle_histories();
    double change = 0;
    for (auto &s : samples)
      {
        const Tensor<2, dim> H = to_cartesian(s.H, s.theta);
        change                 = std::max(change, (H - s.H_cartesian).norm());
        s.H_cartesian          = H;
      }
    return change;
  }
} // namespace rollnip
