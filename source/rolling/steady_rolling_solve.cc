#include <rollnip/rolling/steady_rolling.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  bool
  SteadyRolling::solve_elastic(const double target, const unsigned int steps)
  {
    speed = 0;
    for (auto &p : points)
      {
        p.c = 0;
        p.H = 0;
      }
    dissipated         = 0;
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
  /// the history from the current state, then Newton with it frozen,
  /// until the state changes by less than 1e-8 u0. The history is
  /// under-relaxed (halving the step, down to 1/16) while the change
  /// grows.
  bool
  SteadyRolling::solve_speed(const double V)
  {
    speed             = V;
    converged         = false;
    fixed_point_count = 0;
    double omega = 1, last_change = std::numeric_limits<double>::max();
    std::vector<Tensor<2, dim>> H_old(points.size());
    for (unsigned int it = 0; it < 200; ++it)
      {
        for (unsigned int p = 0; p < points.size(); ++p)
          H_old[p] = points[p].H;
        update_history();
        if (omega < 1)
          for (unsigned int p = 0; p < points.size(); ++p)
            points[p].H = omega * points[p].H + (1 - omega) * H_old[p];
        const dealii::Vector<double> previous = solution;
        if (!newton(50))
          return false;
        ++fixed_point_count;
        dealii::Vector<double> difference = solution;
        difference -= previous;
        const double change = difference.linfty_norm();
        if (change < 1e-8 * u0)
          {
            update_history(); // the dissipation of the converged state
            converged = true;
            return true;
          }
        if (change > last_change && omega > 1. / 16)
          omega *= 0.5;
        last_change = change;
      }
    return false;
  }

  SteadyRollingResult
  SteadyRolling::result() const
  {
    SteadyRollingResult r;
    const double        R0   = layout.radii().back();
    r.converged              = converged;
    r.speed                  = speed;
    r.approach               = u0;
    r.power                  = dissipated;
    r.resistance_energy      = speed > 0 ? dissipated / (1e3 * speed) : 0.;
    r.fixed_point_iterations = fixed_point_count;
    r.newton_steps           = newton_count;
    // The surface nodes by angle.
    std::vector<const SurfaceNode *> nodes;
    for (const auto &entry : surface)
      nodes.push_back(&entry.second);
    const auto angle = [](const SurfaceNode *n) {
      return std::atan2(n->X[1], n->X[0]);
    };
    std::sort(nodes.begin(), nodes.end(), [&](auto a, auto b) {
      return angle(a) < angle(b);
    });
    const unsigned int n      = nodes.size();
    double             torque = 0, first = 0, last = 0, total = 0, moment = 0;
    bool               any = false;
    for (unsigned int i = 0; i < n; ++i)
      {
        const SurfaceNode &node = *nodes[i];
        if (!active.count(node.dofs[0]))
          continue;
        const Tensor<1, dim> nrm = gap_normal(node);
        const double         lambda =
          nrm[0] * reactions(node.dofs[0]) + nrm[1] * reactions(node.dofs[1]);
        const Point<dim> x = deformed(node);
        r.load -= lambda * nrm[0];
        total += lambda;
        moment += lambda * angle(&node);
        torque += lambda * (x[0] * nrm[1] - x[1] * nrm[0]);
        const Point<dim> before = deformed(*nodes[(i + n - 1) % n]);
        const Point<dim> after  = deformed(*nodes[(i + 1) % n]);
        const double     p =
          lambda / (0.5 * (x.distance(before) + x.distance(after)));
        r.pressure.emplace_back(angle(&node), p);
        if (p > r.peak_pressure)
          {
            r.peak_pressure = p;
            r.peak_position = angle(&node);
          }
        // The edge: halfway to the neighbouring free node.
        const double half = 0.5 * (angle(nodes[(i + 1) % n]) - angle(&node));
        const double back =
          0.5 * (angle(&node) - angle(nodes[(i + n - 1) % n]));
        if (!any)
          first = angle(&node) - back;
        last = angle(&node) + half;
        any  = true;
      }
    r.pressure_centre   = total > 0 ? moment / total : 0.;
    r.theta_in          = first;
    r.theta_out         = last;
    r.half_width        = 0.5 * R0 * (last - first);
    r.resistance_moment = -torque / R0;
    return r;
  }
} // namespace rollnip
