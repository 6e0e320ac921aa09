#include <rollnip/three_d/load_control.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// The next trial approach: the power law P ~ u0^n through @p a and
      /// @p b (n = 1.5 without two loaded points), inside (@p low, @p high)
      /// when both are loaded bounds (P > 0).
      double
      next_approach(const SliceNip &a,
                    const SliceNip &b,
                    const SliceNip &low,
                    const SliceNip &high,
                    const double    target)
      {
        if (b.P <= 0)
          return 2. * b.u0; // not yet in contact
        double n = 1.5;
        if (a.P > 0 && a.u0 > 0 && a.u0 != b.u0 && a.P != b.P)
          n = std::clamp(std::log(b.P / a.P) / std::log(b.u0 / a.u0), 1., 3.);
        const double u         = b.u0 * std::pow(target / b.P, 1. / n);
        const bool   bracketed = low.u0 > 0 && high.u0 > 0;
        if (bracketed && (u <= low.u0 || u >= high.u0))
          return 0.5 * (low.u0 + high.u0);
        return u;
      }
    } // namespace

    SliceNip
    solve_for_load(SliceBody         &body,
                   const double       target,
                   const SliceNip    &previous,
                   const double       first_approach,
                   const double       tolerance,
                   const unsigned int max_iterations)
    {
      AssertThrow(target > 0,
                  ExcMessage("Contact/Values: a line load of Mode = load "
                             "must be positive in 3D"));
      SliceNip     a = previous;
      SliceNip     b = previous.P > 0 ? previous : body.solve(first_approach);
      SliceNip     low, high; // loaded bounds: P below and above target
      unsigned int newton = b.newton_steps, gmres = b.linear_iterations;
      if (previous.P > 0)
        newton = gmres = 0;
      for (unsigned int k = 0; k < max_iterations; ++k)
        {
          if (std::abs(b.P - target) <= tolerance * target)
            {
              b.newton_steps      = newton;
              b.linear_iterations = gmres;
              return b;
            }
          if (b.P > 0 && b.P < target)
            low = b;
          else if (b.P > target)
            high = b;
          const double u = next_approach(a, b, low, high, target);
          a              = b;
          b              = body.solve(u);
          newton += b.newton_steps;
          gmres += b.linear_iterations;
        }
      std::ostringstream what;
      what << "Three d: Contact/Mode = load did not reach P = " << target
           << " N/mm within Contact/Maximum iterations = " << max_iterations
           << " solves (last u0 = " << b.u0 << " mm, P = " << b.P << " N/mm)";
      AssertThrow(false, ExcMessage(what.str()));
      return b;
    }
  } // namespace three_d
} // namespace rollnip
