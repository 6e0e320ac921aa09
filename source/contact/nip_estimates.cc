#include <deal.II/base/numbers.h>

#include <rollnip/contact/nip_estimates.h>
#include <rollnip/material/material_table.h>

#include <cmath>

namespace rollnip
{
  namespace NipEstimates
  {
    double
    effective_radius(const Parameters::AllParameters &p)
    {
      const double R0 = p.geometry.outer_radius;
      const double Rb = p.contact.indenter_radius;
      return std::isfinite(Rb) ? 1. / (1. / R0 + 1. / Rb) : R0;
    }

    double
    contact_modulus(const Parameters::AllParameters &p)
    {
      double compliance = 1. / (4 * surface_shear_modulus(p.material));
      if (p.mating_roll.covered)
        compliance += 1. / (4 * surface_shear_modulus(p.mating_roll.material));
      return 1. / compliance;
    }

    double
    thin_layer_compliance(const Parameters::AllParameters &p)
    {
      const auto cover = [](const Parameters::Geometry &g,
                            const Parameters::Material &m) {
        const double h = g.outer_radius - g.inner_radius;
        return h * h * h / surface_shear_modulus(m);
      };
      return cover(p.geometry, p.material) +
             (p.mating_roll.covered
                ? cover(p.mating_roll.geometry, p.mating_roll.material)
                : 0.);
    }

    double
    hertz_load(const Parameters::AllParameters &p, const double b)
    {
      return numbers::PI * b * b * contact_modulus(p) /
             (4 * effective_radius(p));
    }

    double
    thin_layer_load(const Parameters::AllParameters &p, const double b)
    {
      return 2 * std::pow(b, 5) /
             (15 * effective_radius(p) * thin_layer_compliance(p));
    }
  } // namespace NipEstimates
} // namespace rollnip
