#include <deal.II/base/exceptions.h>

#include <rollnip/material/hardness.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rollnip
{
  namespace Hardness
  {
    namespace
    {
      /// The standard normal distribution function.
      double
      normal_cdf(const double z)
      {
        return 0.5 * std::erfc(-z / std::sqrt(2.));
      }

      /// Its inverse by bisection: monotone, and called once per run.
      double
      normal_quantile(const double p)
      {
        double lo = -10, hi = 10;
        for (unsigned int i = 0; i < 200; ++i)
          {
            const double mid                = 0.5 * (lo + hi);
            (normal_cdf(mid) < p ? lo : hi) = mid;
          }
        return 0.5 * (lo + hi);
      }
    } // namespace

    Scale
    scale_from_string(const std::string &name)
    {
      // Compared without case and spaces: "shore a", "ShoreA", "p&j".
      auto key = [](const std::string &text) {
        std::string k;
        for (const char c : text)
          if (c != ' ')
            k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return k;
      };
      for (const Scale scale :
           {Scale::shore_a, Scale::shore_d, Scale::irhd, Scale::pusey_jones})
        if (key(name) == key(to_string(scale)))
          return scale;
      AssertThrow(false,
                  dealii::ExcMessage(
                    "Material/Hardness scale: unknown scale '" + name +
                    "' (Shore A, Shore D, IRHD or P&J)"));
      return Scale::shore_a;
    }

    std::string
    to_string(const Scale scale)
    {
      switch (scale)
        {
          case Scale::shore_a:
            return "Shore A";
          case Scale::shore_d:
            return "Shore D";
          case Scale::irhd:
            return "IRHD";
          default:
            return "P&J";
        }
    }

    Range
    validity_range(const Scale scale)
    {
      switch (scale)
        {
          // Gent's relation is finite below 100; rollnip stops at 95,
          // where one point is 17 % in E (validated_range() warns).
          case Scale::shore_a:
            return {20., 95.};
          // The Shore D correlation is stated for 30 to 85; rollnip stops
          // at 80 (E = 198 MPa), the stiffest cover it calls rubber.
          case Scale::shore_d:
            return {30., 80.};
          // The ISO 48 methods L, N and H span 10 to 100 IRHD; near 100 the
          // modulus is undetermined (infinite at 100).
          case Scale::irhd:
            return {10., 95.};
          // Hard covers down to 5 P&J (E about 220 MPa), soft ones to 300.
          default:
            return {5., 300.};
        }
    }

    Range
    validated_range(const Scale scale)
    {
      switch (scale)
        {
          // Gent (1958) found his theory good above about 40; ASTM D2240
          // sends readings above 90 to the type D durometer.
          case Scale::shore_a:
            return {40., 90.};
          case Scale::shore_d:
            return {30., 80.};
          case Scale::irhd:
            return {10., 95.};
          // The published P&J to Shore A chart: 12 P&J is about 95 Shore A,
          // where the A scale ends; 200 P&J is about 39 Shore A.
          default:
            return {12., 200.};
        }
    }

    double
    youngs_modulus_log_linear(const double S)
    {
      return std::pow(10., 0.0235 * S - 0.6403);
    }

    double
    youngs_modulus_from_shore_d(const double S)
    {
      return youngs_modulus_log_linear(S + 50.);
    }

    double
    shore_a_from_modulus(const double E)
    {
      double lo = 0, hi = 100;
      for (unsigned int i = 0; i < 200; ++i)
        {
          const double mid                                 = 0.5 * (lo + hi);
          (youngs_modulus_from_shore_a(mid) < E ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    }

    Band
    modulus_band(const double value, const Scale scale)
    {
      const double E = youngs_modulus(value, scale);
      Band         band{E, E};
      auto         add = [&band](const double e) {
        band.low  = std::min(band.low, e);
        band.high = std::max(band.high, e);
      };
      const double S = scale == Scale::shore_d       ? value + 50.
                       : scale == Scale::pusey_jones ? shore_a_from_modulus(E)
                                                     : value;
      // Each correlation where its reading lies in its accepted range.
      if (S >= 20 && S <= 95)
        add(youngs_modulus_from_shore_a(S));
      if (S >= 10 && S <= 95)
        add(youngs_modulus_from_irhd(S));
      if (S >= 20 && S <= 135)
        add(youngs_modulus_log_linear(S));
      return band;
    }

    double
    youngs_modulus_from_shore_a(const double S)
    {
      return 0.0981 * (56. + 7.62336 * S) / (0.137505 * (254. - 2.54 * S));
    }

    double
    youngs_modulus_from_irhd(const double H)
    {
      // H = 100 Phi(k (log10 E - 0.364)) with 100 k phi(0) = 57.
      const double k = 0.57 * std::sqrt(2. * M_PI);
      return std::pow(10., 0.364 + normal_quantile(H / 100.) / k);
    }

    double
    youngs_modulus_from_pusey_jones(const double D)
    {
      const double force  = 9.80665;    // 1 kgf [N]
      const double radius = 3.175 / 2.; // 1/8 inch ball [mm]
      return force / (0.0038 * std::pow(radius, 0.65) * std::pow(D, 1.35));
    }

    double
    youngs_modulus(const double value, const Scale scale)
    {
      switch (scale)
        {
          case Scale::shore_a:
            return youngs_modulus_from_shore_a(value);
          case Scale::shore_d:
            return youngs_modulus_from_shore_d(value);
          case Scale::irhd:
            return youngs_modulus_from_irhd(value);
          default:
            return youngs_modulus_from_pusey_jones(value);
        }
    }

    std::string
    source(const Scale scale)
    {
      switch (scale)
        {
          case Scale::shore_a:
            return "Gent (1958)";
          case Scale::shore_d:
            return "log-linear correlation at S_A = S_D + 50";
          case Scale::irhd:
            return "ISO 48 IRHD-modulus relation";
          default:
            return "ISO 48 ball-indentation relation at the P&J load";
        }
    }

    MooneyRivlin
    mooney_rivlin_from_modulus(const double E, const double c2_over_c1)
    {
      const double sum = E / 6.;
      const double C1  = sum / (1. + c2_over_c1);
      return {C1, sum - C1};
    }
  } // namespace Hardness
} // namespace rollnip
