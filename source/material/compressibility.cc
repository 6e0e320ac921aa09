#include <deal.II/base/exceptions.h>

#include <rollnip/material/compressibility.h>
#include <rollnip/parameter_entries.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace rollnip
{
  namespace Compressibility
  {
    namespace
    {
      /// The value of a per-layer list: one value for all, else its own.
      double
      of_layer(const std::vector<double> &values, const unsigned int layer)
      {
        return values.size() == 1 ? values[0] : values.at(layer);
      }

      double
      shear_modulus(const Parameters::Material &material,
                    const unsigned int          layer)
      {
        return 2. * (material.layer_C1.at(layer) + material.layer_C2.at(layer));
      }

      /// Whether Material/Poisson ratio was changed from its default 0.5.
      bool
      poisson_ratio_given(const Parameters::Material &material)
      {
        for (const double nu : material.layer_poisson_ratio)
          if (nu != 0.5)
            return true;
        return false;
      }

      void
      check_count(const std::vector<double> &values,
                  const unsigned int         n_layers,
                  const std::string         &name)
      {
        AssertThrow(values.size() == 1 || values.size() == n_layers,
                    dealii::ExcMessage(
                      name + " has " + std::to_string(values.size()) +
                      " values for " + std::to_string(n_layers) +
                      " layer(s): give one value or one per layer"));
      }
    } // namespace

    double
    bulk_modulus(const Parameters::Material &material, const unsigned int layer)
    {
      if (!material.layer_bulk_modulus.empty())
        return of_layer(material.layer_bulk_modulus, layer);
      if (material.layer_poisson_ratio.empty())
        return std::numeric_limits<double>::infinity();
      const double nu = of_layer(material.layer_poisson_ratio, layer);
      if (nu >= 0.5)
        return std::numeric_limits<double>::infinity();
      return 2. * shear_modulus(material, layer) * (1. + nu) /
             (3. * (1. - 2. * nu));
    }

    double
    poisson_ratio(const Parameters::Material &material,
                  const unsigned int          layer)
    {
      const double K = bulk_modulus(material, layer);
      if (std::isinf(K))
        return 0.5;
      const double G = shear_modulus(material, layer);
      return (3. * K - 2. * G) / (2. * (3. * K + G));
    }

    namespace
    {
      void
      validate_bulk_modulus(const Parameters::Material &material,
                            const std::string          &prefix)
      {
        const unsigned int n  = material.n_layers();
        const std::string  nu = prefix + "Poisson ratio";
        const std::string  K  = prefix + "Bulk modulus";
        AssertThrow(!poisson_ratio_given(material),
                    dealii::ExcMessage(K + " and " + nu +
                                       " are both given: give one of them"));
        check_count(material.layer_bulk_modulus, n, K);
        for (unsigned int j = 0; j < n; ++j)
          {
            const double       k   = of_layer(material.layer_bulk_modulus, j);
            const double       min = 2. / 3. * shear_modulus(material, j);
            std::ostringstream message;
            message << K << " = " << k << " MPa of layer " << j + 1
                    << " must be at least 2 G/3 = " << min
                    << " MPa (Poisson ratio >= 0)";
            AssertThrow(k > 0 && k >= min, dealii::ExcMessage(message.str()));
          }
      }

      void
      validate_penalty(const Parameters::Material &material,
                       const std::string          &prefix)
      {
        for (unsigned int j = 0; j < material.n_layers(); ++j)
          {
            const double K = bulk_modulus(material, j);
            if (std::isinf(K))
              continue;
            // The multiplier's penalty (the laws' pressure_compliance()).
            const double lambda = K - 2. / 3. * shear_modulus(material, j);
            const bool   linear = material.theory == Parameters::Theory::linear;
            const double kappa =
              linear ? lambda : lambda + 2. * material.layer_C1[j];
            AssertThrow(kappa > 0,
                        dealii::ExcMessage(
                          prefix + "Poisson ratio of layer " +
                          std::to_string(j + 1) + " is too small for " +
                          (linear ? "Theory = linear (needs nu > 0)"
                                  : "this C1 (needs K - 2 G/3 + 2 C1 > 0)")));
          }
      }
    } // namespace

    void
    validate(const Parameters::Material &material, const std::string &prefix)
    {
      const unsigned int n  = material.n_layers();
      const std::string  nu = prefix + "Poisson ratio";
      check_count(material.layer_poisson_ratio, n, nu);
      for (const double v : material.layer_poisson_ratio)
        AssertThrow(v >= 0 && v <= 0.5,
                    dealii::ExcMessage(nu + " = " + Parameters::number(v) +
                                       " is outside [0, 0.5] (0.5: "
                                       "incompressible)"));
      if (!material.layer_bulk_modulus.empty())
        validate_bulk_modulus(material, prefix);
      validate_penalty(material, prefix);
    }

  } // namespace Compressibility
} // namespace rollnip
