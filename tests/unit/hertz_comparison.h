#ifndef rollnip_tests_hertz_comparison_h
#define rollnip_tests_hertz_comparison_h

#include <rollnip/contact/contact_result.h>

#include "test_tools.h"

#include <vector>

namespace rollnip
{
  namespace testing
  {
    /**
     * Contact results at shrinking nips beside plane-strain Hertz for an
     * incompressible pair, P = pi b^2 E* / (4 R) and peak pressure
     * 2 P / (pi b), with b the contact half-width. The thickness and the
     * curvature of the covers change both by relative amounts of order
     * (b/h)^2 and (b/R0)^2, so the errors must shrink with the nip.
     */
    class HertzComparison
    {
    public:
      /// @p E_star [MPa] and @p R [mm] of the pair; @p h [mm], the
      /// thickness that b is compared with in the printed b/h.
      HertzComparison(const double E_star, const double R, const double h)
          : E_star(E_star)
          , R(R)
          , h(h)
      {}

      /// Records and prints the errors of the nip @p r at @p theta0_deg.
      void
      add(Checker &checker, const double theta0_deg, const ContactResult &r)
      {
        const double b          = r.half_chord;
        const double P_hertz    = numbers::PI * b * b * E_star / (4 * R);
        const double peak_hertz = 2 * r.nip_load / (numbers::PI * b);
        checker.check(r.converged,
                      "theta0 = " + num(theta0_deg) + " deg converged");
        load_error.push_back(std::abs(r.nip_load / P_hertz - 1));
        peak_error.push_back(std::abs(r.peak_pressure / peak_hertz - 1));
        std::cout << "  theta0 = " << theta0_deg << " deg, b/h = " << b / h
                  << ": P = " << r.nip_load << " N/mm, Hertz " << P_hertz
                  << " N/mm (error " << 100 * load_error.back() << " %); peak "
                  << r.peak_pressure << " MPa, 2P/(pi b) " << peak_hertz
                  << " MPa (error " << 100 * peak_error.back() << " %)"
                  << std::endl;
      }

      /// The peak-pressure error falls from nip to nip; from the third nip
      /// on (b/h < 0.08 in both tests), P lies within 1 % of Hertz and
      /// closer than at the first.
      void
      check_trends(Checker &checker) const
      {
        for (unsigned int i = 1; i < peak_error.size(); ++i)
          checker.check(peak_error[i] < peak_error[i - 1],
                        "the peak-pressure error shrinks with the nip: " +
                          num(100 * peak_error[i - 1]) + " % -> " +
                          num(100 * peak_error[i]) + " %");
        for (unsigned int i = 2; i < load_error.size(); ++i)
          checker.check(load_error[i] < 0.01 && load_error[i] < load_error[0],
                        "P within 1 % of Hertz at b/h < 0.08 (" +
                          num(100 * load_error[i]) + " %, " +
                          num(100 * load_error[0]) + " % at the first nip)");
      }

    private:
      const double        E_star, R, h;
      std::vector<double> load_error, peak_error;
    };
  } // namespace testing
} // namespace rollnip

#endif
