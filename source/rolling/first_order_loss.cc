#include <deal.II/base/numbers.h>

#include <rollnip/rolling/first_order_loss.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  namespace
  {
    /// The whole turn of @p circle: its samples mirrored about theta = 0
    /// (E_rtheta and S_rtheta change sign) and the given ones; a closing
    /// sample at 2 pi - theta_last for a half-roll sector.
    std::vector<CircleSample>
    whole_turn(const MaterialCircle &circle, const bool closed)
    {
      std::vector<CircleSample> turn;
      const auto               &s      = circle.samples;
      auto                      mirror = [](CircleSample m) {
        m.theta = -m.theta;
        m.E[1]  = -m.E[1];
        m.S[1]  = -m.S[1];
        return m;
      };
      for (auto it = s.rbegin(); it != s.rend(); ++it)
        turn.push_back(mirror(*it));
      turn.insert(turn.end(), s.begin(), s.end());
      if (closed && !s.empty())
        {
          CircleSample last = mirror(s.back());
          last.theta += 2. * numbers::PI;
          turn.push_back(last);
        }
      return turn;
    }

    /// S' : E' dtheta over the segment from @p a to @p b (both linear in
    /// theta): (Delta S : Delta E) / Delta theta [MPa rad^-1].
    double
    segment_product(const CircleSample &a, const CircleSample &b)
    {
      const double dS[3] = {b.S[0] - a.S[0], b.S[1] - a.S[1], b.S[2] - a.S[2]};
      const double dE[3] = {b.E[0] - a.E[0], b.E[1] - a.E[1], b.E[2] - a.E[2]};
      return (dS[0] * dE[0] + 2. * dS[1] * dE[1] + dS[2] * dE[2]) /
             (b.theta - a.theta);
    }
  } // namespace

  RollingLoss
  first_order_loss(
    const std::vector<MaterialCircle>                 &circles,
    const Parameters::Rolling                         &rolling,
    const double                                       R0,
    const double                                       sector_angle,
    const double                                       speed,
    const std::function<double(double, unsigned int)> &circle_factor)
  {
    RollingLoss loss;
    loss.speed          = speed;
    const double Omega  = 1e3 * speed / R0; // [1/s]
    const bool   closed = sector_angle > numbers::PI * (1 - 1e-9);
    // MPa/s = 1e6 W/m^3; MPa/s mm^2 = N mm/s per mm = W/m.
    constexpr double W_per_m3 = 1e6;
    for (const auto &circle : circles)
      {
        const double tau =
          rolling.layer(circle.layer).viscous_time(); // sum g_i tau_i
        const auto turn  = whole_turn(circle, closed);
        double     total = 0, peak = 0;
        for (unsigned int k = 1; k < turn.size(); ++k)
          {
            const double p = segment_product(turn[k - 1], turn[k]);
            total += p;
            peak = std::max(peak, p / (turn[k].theta - turn[k - 1].theta));
          }
        const double factor =
          Omega * Omega * tau *
          (circle_factor ? circle_factor(circle.radius, circle.layer) : 1.);
        loss.power += circle.weight * factor * total;
        loss.circles.push_back({circle.radius,
                                circle.weight,
                                circle.layer,
                                W_per_m3 * factor * total / (2. * numbers::PI),
                                W_per_m3 * factor * peak});
      }
    loss.rolling_resistance = speed > 0 ? loss.power / (1e3 * speed) : 0.;
    return loss;
  }
} // namespace rollnip
