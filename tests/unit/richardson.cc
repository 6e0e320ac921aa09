// Richardson extrapolation of the study mode (study/refinement_study.h):
// exact for a sequence 1 + c 2^(-p k) (the limit 1 and the order p come
// back to round-off), and an observed order above the element's degree
// + 1 is flagged and not used: the value is extrapolated with the cap.

#include <rollnip/app/refinement_study.h>

#include "test_tools.h"

using namespace rollnip;

int
main()
{
  testing::Checker checker;
  for (const double p : {1., 2.})
    {
      std::vector<double> v;
      for (unsigned int k = 0; k < 4; ++k)
        v.push_back(1 + 0.3 * std::pow(2., -p * k));
      const Extrapolation e = extrapolate(v, 3.);
      checker.check(e.valid && !e.capped && std::abs(e.value - 1) < 1e-12 &&
                      std::abs(e.order - p) < 1e-9,
                    "order " + testing::num(p) + ": limit " +
                      testing::num(e.value) + ", order " +
                      testing::num(e.order));
    }
  // Order 4.7 from a pre-asymptotic sequence, capped at 3 (Q2-P1).
  const std::vector<double> v = {1.1,
                                 1.1 - 0.01,
                                 1.09 - 0.01 * std::pow(2., -4.7)};
  const Extrapolation       e = extrapolate(v, 3.);
  const double expected       = v[2] + (v[2] - v[1]) * 0.125 / (1 - 0.125);
  checker.check(e.valid && e.capped && std::abs(e.order - 4.7) < 1e-9 &&
                  std::abs(e.value - expected) < 1e-14,
                "order 4.7 is flagged and the limit taken at order 3: " +
                  testing::num(e.value));
  return checker.result();
}
