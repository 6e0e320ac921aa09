#include <deal.II/base/exceptions.h>

#include <rollnip/output/units.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace rollnip
{
  namespace Units
  {
    Unit
    unit(const Quantity quantity, const Parameters::UnitSystem system)
    {
      const bool us = system == Parameters::UnitSystem::us;
      switch (quantity)
        {
          case Quantity::length:
            return us ? Unit{"in", "in", 1. / mm_per_inch}
                      : Unit{"mm", "mm", 1.};
          case Quantity::pressure:
            return us ? Unit{"psi", "psi", 1. / mpa_per_psi}
                      : Unit{"MPa", "MPa", 1.};
          case Quantity::line_load:
            return us ? Unit{"pli", "pli", 1. / pli_in_n_per_mm}
                      : Unit{"N/mm", "N_per_mm", 1.};
          case Quantity::force:
            return us ? Unit{"lbf", "lbf", 1. / newton_per_lbf}
                      : Unit{"N", "N", 1.};
          case Quantity::speed:
            return us ? Unit{"fpm", "fpm", 1. / m_per_min_per_fpm}
                      : Unit{"m/min", "m_per_min", 1.};
          default:
            return Unit{"ms", "ms", 1.};
        }
    }

    std::string
    lower_case(const std::string &text)
    {
      std::string s = text;
      std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) {
        return std::tolower(c);
      });
      return s;
    }

    Parameters::UnitSystem
    system_from_string(const std::string &text)
    {
      const std::string s = lower_case(text);
      if (s == "si")
        return Parameters::UnitSystem::si;
      AssertThrow(s == "us",
                  dealii::ExcMessage("Output/Units: unknown system '" + text +
                                     "' (SI or US)"));
      return Parameters::UnitSystem::us;
    }

    double
    speed_in_m_per_min(const std::string &text)
    {
      std::istringstream in(text);
      double             value = std::nan("");
      if (!(in >> value))
        value = std::nan("");
      std::string name, rest;
      in.clear();
      in >> name >> rest;
      const std::string u      = lower_case(name);
      double            factor = std::nan("");
      if (u.empty() || u == "m/min")
        factor = 1.;
      else if (u == "m/s")
        factor = m_per_min_per_m_per_s;
      else if (u == "fpm" || u == "ft/min")
        factor = m_per_min_per_fpm;
      AssertThrow(rest.empty() && std::isfinite(value) && value >= 0 &&
                    !std::isnan(factor),
                  dealii::ExcMessage(
                    "Contact/Surface speed = '" + text +
                    "': give a number >= 0 and a unit m/min (the default), "
                    "m/s or fpm"));
      return value * factor;
    }
  } // namespace Units
} // namespace rollnip
