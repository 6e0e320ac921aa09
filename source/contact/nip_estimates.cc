#include <deal.II/base/numbers.h>

#include <rollnip/contact/nip_estimates.h>
#include <rollnip/solvers/iteration_controls.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  namespace NipEstimates
  {
    double
    effective_radius(const SceneDescription &scene)
    {
      const double R0 = scene.roll.outer_radius();
      const double Rb = scene.counter_radius();
      return std::isfinite(Rb) ? 1. / (1. / R0 + 1. / Rb) : R0;
    }

    double
    mate_nip_angle(const double R0, const double Rm, const double theta0)
    {
      return std::asin(
        std::min(IterationControls::max_mate_sine, R0 * std::sin(theta0) / Rm));
    }

    double
    contact_modulus(const SceneDescription &scene)
    {
      double compliance = 1. / (4 * scene.roll.surface_layer().shear_modulus());
      if (const RollDescription *mate = scene.covered_mate())
        compliance += 1. / (4 * mate->surface_layer().shear_modulus());
      return 1. / compliance;
    }

    double
    layered_compliance(const RollDescription &roll)
    {
      // Shear flow in a thin bonded layer under a frictionless nip: the
      // shear stress grows linearly from the free top to the core, so the
      // flux per pressure gradient is int_0^h (h - s)^2 / G(s) ds, layer by
      // layer from the core (s = 0) out; h^3/(3 G) for one layer.
      const double h = roll.cover_thickness();
      double       s = 0, compliance = 0;
      for (const LayerDescription &layer : roll.layers)
        {
          const double top = std::min(h, s + layer.thickness);
          compliance +=
            (std::pow(h - s, 3) - std::pow(h - top, 3)) / layer.shear_modulus();
          s = top;
        }
      return compliance;
    }

    double
    thin_layer_compliance(const SceneDescription &scene)
    {
      const RollDescription *mate = scene.covered_mate();
      return layered_compliance(scene.roll) +
             (mate ? layered_compliance(*mate) : 0.);
    }

    double
    hertz_load(const SceneDescription &scene, const double b)
    {
      return numbers::PI * b * b * contact_modulus(scene) /
             (4 * effective_radius(scene));
    }

    double
    thin_layer_load(const SceneDescription &scene, const double b)
    {
      return 2 * std::pow(b, 5) /
             (15 * effective_radius(scene) * thin_layer_compliance(scene));
    }

    double
    hertz_half_width(const SceneDescription &scene, const double P)
    {
      return std::sqrt(4 * P * effective_radius(scene) /
                       (numbers::PI * contact_modulus(scene)));
    }

    double
    thin_layer_half_width(const SceneDescription &scene, const double P)
    {
      return std::pow(7.5 * P * effective_radius(scene) *
                        thin_layer_compliance(scene),
                      0.2);
    }

    double
    hertz_peak_pressure(const double P, const double b)
    {
      return 2 * P / (numbers::PI * b);
    }

    double
    thin_layer_peak_pressure(const double P, const double b)
    {
      return 15 * P / (16 * b);
    }
  } // namespace NipEstimates
} // namespace rollnip
