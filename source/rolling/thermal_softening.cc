#include <rollnip/parameter_entries.h>
#include <rollnip/rolling/thermal_softening.h>

#include <cmath>
#include <string>

namespace rollnip
{
  namespace Parameters
  {
    void
    ThermalSoftening::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Temperature dependence");
      declare_documented(prm,
                         "Reference temperature",
                         "20",
                         Patterns::Double(-273.15),
                         "The temperature at which Material's moduli and "
                         "the loss data of Rolling hold [degC]");
      declare_documented(prm,
                         "Modulus temperature coefficient",
                         "0",
                         Patterns::Anything(),
                         "c [1/K]: the moduli are exp(-c (T - T_ref)) "
                         "times Material's, so c is their relative fall "
                         "per kelvin (0.005 to 0.02 for filled rubber); one "
                         "value or one per layer; 0: no softening");
      declare_documented(prm,
                         "WLF C1",
                         "0",
                         Patterns::Anything(),
                         "The WLF shift of the relaxation times, log10 a_T "
                         "= -C1 (T - T_ref) / (C2 + T - T_ref), taken "
                         "about Reference temperature; one value or one "
                         "per layer; 0: the times do not shift");
      declare_documented(prm,
                         "WLF C2",
                         "100",
                         Patterns::Anything(),
                         "C2 [K] of the WLF shift, positive; one value or "
                         "one per layer");
      declare_documented(prm,
                         "Maximum iterations",
                         "20",
                         Patterns::Integer(1),
                         "Nip solves of the fixed point of nip, loss, "
                         "temperature and modulus after the first");
      declare_documented(prm,
                         "Temperature tolerance",
                         "0.01",
                         Patterns::Double(0.),
                         "The fixed point has converged when the "
                         "temperature of a pass differs from the one its "
                         "modulus was taken at by no more than this [K]");
      prm.leave_subsection();
    }

    namespace
    {
      /// One value, or one per layer, of Rolling/Temperature
      /// dependence/@p entry, each at least @p low (strictly if
      /// @p strict).
      std::vector<double>
      layer_values(const std::string &text,
                   const std::string &entry,
                   const unsigned int n_layers,
                   const double       low,
                   const bool         strict)
      {
        const std::string   name = "Rolling/Temperature dependence/" + entry;
        std::vector<double> v;
        for (const auto &word : Utilities::split_string_list(text, ','))
          {
            std::size_t end = 0;
            double      x   = std::nan("");
            try
              {
                x = std::stod(word, &end);
              }
            catch (...)
              {
                end = 0;
              }
            AssertThrow(end == word.size() && std::isfinite(x),
                        ExcMessage(name + ": '" + word + "' is not a number"));
            AssertThrow(strict ? x > low : x >= low,
                        ExcMessage(name + " must be " +
                                   (strict ? "greater than " : "at least ") +
                                   number(low) + ", not " + number(x)));
            v.push_back(x);
          }
        AssertThrow(v.size() == 1 || v.size() == n_layers,
                    ExcMessage(name + " has " + std::to_string(v.size()) +
                               " values: give one, or one per layer (" +
                               std::to_string(n_layers) + ")"));
        return v;
      }
    } // namespace

    void
    ThermalSoftening::parse(ParameterHandler &prm, const unsigned int n_layers)
    {
      prm.enter_subsection("Temperature dependence");
      reference_temperature = prm.get_double("Reference temperature");
      modulus_coefficient =
        layer_values(prm.get("Modulus temperature coefficient"),
                     "Modulus temperature coefficient",
                     n_layers,
                     -1.,
                     true);
      wlf_c1 = layer_values(prm.get("WLF C1"), "WLF C1", n_layers, 0., false);
      wlf_c2 = layer_values(prm.get("WLF C2"), "WLF C2", n_layers, 0., true);
      max_iterations = prm.get_integer("Maximum iterations");
      tolerance      = prm.get_double("Temperature tolerance");
      prm.leave_subsection();
    }

    bool
    ThermalSoftening::active() const
    {
      for (const double c : modulus_coefficient)
        if (c != 0)
          return true;
      for (const double c : wlf_c1)
        if (c != 0)
          return true;
      return false;
    }

    double
    ThermalSoftening::modulus_factor(const unsigned int layer,
                                     const double       T) const
    {
      const double c = of_layer(modulus_coefficient, layer);
      return c == 0 ? 1. : std::exp(-c * (T - reference_temperature));
    }

    double
    ThermalSoftening::time_shift(const unsigned int layer, const double T) const
    {
      const double C1 = of_layer(wlf_c1, layer);
      if (C1 == 0)
        return 1.;
      const double C2 = of_layer(wlf_c2, layer);
      const double dT = T - reference_temperature;
      AssertThrow(C2 + dT > 0,
                  ExcMessage("Rolling/Temperature dependence/WLF C2: the "
                             "cover reaches " +
                             number(T) +
                             " degC, at or below Reference temperature - "
                             "C2, where the WLF shift has no meaning"));
      return std::pow(10., -C1 * dT / (C2 + dT));
    }
  } // namespace Parameters
} // namespace rollnip
