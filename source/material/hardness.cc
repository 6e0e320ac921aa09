#include <deal.II/base/exceptions.h>

#include <rollnip/material/hardness.h>

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
      if (name == "Shore A")
        return Scale::shore_a;
      if (name == "IRHD")
        return Scale::irhd;
      if (name == "P&J")
        return Scale::pusey_jones;
      AssertThrow(false,
                  dealii::ExcMessage(
                    "Material/Hardness scale: unknown scale '" + name +
                    "' (Shore A, IRHD or P&J)"));
      return Scale::shore_a;
    }

    std::string
    to_string(const Scale scale)
    {
      switch (scale)
        {
          case Scale::shore_a:
            return "Shore A";
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
          // Gent's analysis holds down to about 40 (with reduced accuracy
          // to 30); above 90 ASTM D2240 asks for the type D durometer.
          case Scale::shore_a:
            return {30., 90.};
          // The ISO 48 methods L, N and H span 10 to 100 IRHD; near 100 the
          // modulus is undetermined (infinite at 100).
          case Scale::irhd:
            return {10., 95.};
          // The published P&J to Shore A chart: 12 P&J is about 95 Shore A,
          // where the A scale ends; 250 P&J is about 30 Shore A.
          default:
            return {12., 250.};
        }
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
