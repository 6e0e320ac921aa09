#include <rollnip/rolling/steady_rolling.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  bool
  SteadyRolling::solve_elastic(const double target, const unsigned int steps)
  {
    speed = 0;
    for (auto &s : samples)
      {
        s.c           = 0;
        s.H_cartesian = 0;
      }
    dissipated = 0;
    std::fill(circle_dissipation.begin(), circle_dissipation.end(), 0.);
    const double start = u0;
    converged          = false;
    for (unsigned int s = 1; s <= steps; ++s)
      {
        u0 = start + (target - start) * s / steps;
        if (!newton(50))
          return false;
      }
    converged = true;
    return true;
  }

  /// The fixed point of the overstress's history and the equilibrium:
  /// the history from the current state, then one Newton step with it
  /// frozen, until the active set stays and the step is below 1e-8 u0;
  /// then Newton to convergence with the history of that state. The
  /// history is under-relaxed (halving, down to 1/16) while the steps
  /// grow.
  bool
  SteadyRolling::solve_speed(const double V)
  {
    speed             = V;
    converged         = false;
    fixed_point_count = 0;
    double omega = 1, last = std::numeric_limits<double>::max();
    std::vector<Tensor<2, dim>> H_old(samples.size());
    for (unsigned int it = 0; it < 300; ++it)
      {
        for (unsigned int p = 0; p < samples.size(); ++p)
          H_old[p] = samples[p].H_cartesian;
        update_history();
        if (omega < 1)
          for (unsigned int p = 0; p < samples.size(); ++p)
            samples[p].H_cartesian =
              omega * samples[p].H_cartesian + (1 - omega) * H_old[p];
        bool         changed = false;
        const double step    = newton_step(changed);
        ++fixed_point_count;
        if (step == std::numeric_limits<double>::max())
          return false;
        if (!changed && step < 1e-8 * u0)
          {
            update_history();
            if (!newton(20))
              return false;
            update_history(); // the dissipation of the converged state
            converged = true;
            return true;
          }
        if (step > last && omega > 1. / 16)
          omega *= 0.5;
        last = step;
      }
    return false;
  }

  /// The surface nodes by angle with their contact forces: lambda the
  /// normal force [N/mm], p = lambda over the deformed tributary length.
  std::vector<SteadyRolling::NodeForce>
  SteadyRolling::contact_forces() const
  {
    std::vector<NodeForce> nodes;
    const bool linear = scene.material.theory == Parameters::Theory::linear;
    for (const auto &[x_dof, node] : surface)
      {
        NodeForce f;
        f.theta  = std::atan2(node.X[1], node.X[0]);
        f.normal = gap_normal(node);
        f.x      = deformed(node);
        // The moment balance of the discrete equilibrium holds about the
        // reference positions in linear theory, the deformed in finite
        // strain.
        f.arm    = linear ? node.X : f.x;
        f.active = active.count(x_dof) > 0;
        if (f.active)
          f.lambda = f.normal * Tensor<1, dim>({reactions(node.dofs[0]),
                                                reactions(node.dofs[1])});
        nodes.push_back(f);
      }
    std::sort(nodes.begin(), nodes.end(), [](const auto &a, const auto &b) {
      return a.theta < b.theta;
    });
    const unsigned int n = nodes.size();
    for (unsigned int i = 0; i < n; ++i)
      nodes[i].p = nodes[i].lambda /
                   (0.5 * (nodes[i].x.distance(nodes[(i + n - 1) % n].x) +
                           nodes[i].x.distance(nodes[(i + 1) % n].x)));
    return nodes;
  }

  SteadyRollingResult
  SteadyRolling::result() const
  {
    SteadyRollingResult r;
    r.converged               = converged;
    r.speed                   = speed;
    r.approach                = u0;
    r.power                   = dissipated;
    r.resistance_energy       = speed > 0 ? dissipated / (1e3 * speed) : 0.;
    r.fixed_point_iterations  = fixed_point_count;
    r.newton_steps            = newton_count;
    const auto         nodes  = contact_forces();
    const unsigned int n      = nodes.size();
    double             torque = 0, total = 0, moment = 0;
    bool               any = false;
    for (unsigned int i = 0; i < n; ++i)
      {
        const NodeForce &f = nodes[i];
        if (!f.active)
          continue;
        r.load -= f.lambda * f.normal[0];
        total += f.lambda;
        moment += f.lambda * f.theta;
        torque += f.lambda * (f.arm[0] * f.normal[1] - f.arm[1] * f.normal[0]);
        r.pressure.emplace_back(f.theta, f.p);
        if (f.p > r.peak_pressure)
          {
            r.peak_pressure = f.p;
            r.peak_position = f.theta;
          }
        // The edges: halfway to the neighbouring free node.
        if (!any)
          r.theta_in = 0.5 * (f.theta + nodes[(i + n - 1) % n].theta);
        r.theta_out = 0.5 * (f.theta + nodes[(i + 1) % n].theta);
        any         = true;
      }
    const double R0     = layout.radii().back();
    r.pressure_centre   = total > 0 ? moment / total : 0.;
    r.half_width        = 0.5 * R0 * (r.theta_out - r.theta_in);
    r.resistance_moment = -torque / R0;
    return r;
  }
} // namespace rollnip
