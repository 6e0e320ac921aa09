#include <deal.II/base/numbers.h>

#include <rollnip/contact/nip_estimates.h>
#include <rollnip/material/material_table.h>

#include <algorithm>
#include <cmath>
#include <vector>

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
    layered_compliance(const Parameters::Geometry &geometry,
                       const Parameters::Material &material)
    {
      // Shear flow in a thin bonded layer under a frictionless nip: the
      // shear stress grows linearly from the free top to the core, so the
      // flux per pressure gradient is int_0^h (h - s)^2 / G(s) ds, layer by
      // layer from the core (s = 0) out; h^3/(3 G) for one layer.
      const double        h = geometry.outer_radius - geometry.inner_radius;
      const MaterialTable layers(material);
      std::vector<double> thickness = material.layer_thicknesses;
      if (thickness.empty())
        thickness = {h};
      double s = 0, compliance = 0;
      for (unsigned int j = 0; j < thickness.size(); ++j)
        {
          const double top = std::min(h, s + thickness[j]);
          compliance += (std::pow(h - s, 3) - std::pow(h - top, 3)) /
                        layers[j].shear_modulus();
          s = top;
        }
      return compliance;
    }

    double
    thin_layer_compliance(const Parameters::AllParameters &p)
    {
      return layered_compliance(p.geometry, p.material) +
             (p.mating_roll.covered ? layered_compliance(p.mating_roll.geometry,
                                                         p.mating_roll.material)
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
