#ifndef rollnip_rolling_rolling_parameters_h
#define rollnip_rolling_rolling_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/global.h>
#include <rollnip/rolling/thermal_softening.h>

#include <memory>
#include <string>
#include <vector>

/**
 * The parameters of the rolling loss and the cover's temperature
 * (subsection Rolling, doc/rolling.md): the surface speed, the cover's
 * viscoelastic description per layer and its thermal data.
 */
namespace rollnip
{
  namespace Parameters
  {
    struct AllParameters;

    /// How the cover's hysteresis is given (the same for every layer).
    enum class ViscoelasticModel
    {
      kelvin_voigt, ///< one retardation time: sigma_v = 2 G tau dev(eps_dot)
      prony,        ///< relative moduli g_i and relaxation times tau_i
      loss_tangent  ///< tan(delta) at a frequency, fitted by one dashpot
    };

    /// The hysteresis of one layer of the cover.
    struct ViscousLayer
    {
      /// Relative moduli g_i (over the long-term modulus) and times
      /// tau_i [s] of the Maxwell branches on the isochoric part; one
      /// branch of g = 1 for a Kelvin-Voigt or loss-tangent layer, whose
      /// tau is the retardation time.
      std::vector<double> g, tau;

      /// sum_i g_i tau_i [s]: the only number the first-order loss needs
      /// (the viscosity over the long-term shear modulus).
      double
      viscous_time() const;
      /// The longest time of the layer [s], for the validity check.
      double
      longest_time() const;
    };

    enum class CoreThermalCondition
    {
      fixed_temperature,
      insulated
    };

    struct Rolling
    {
      bool enabled = false;
      /// Surface speed of the roll [m/s]; the first of speeds.
      double speed = 0;
      /// Every speed of the speed table [m/s] (speed first).
      std::vector<double> speeds;
      /// Whether the speeds were given in m/min (for the reports).
      bool                      in_m_per_min = true;
      ViscoelasticModel         model        = ViscoelasticModel::kelvin_voigt;
      std::vector<ViscousLayer> layers; ///< one per layer of the cover
      /// Thermal conductivity per layer [W/(m K)].
      std::vector<double>  conductivity;
      double               heat_transfer = 0;  ///< to the air [W/(m^2 K)]
      double               ambient       = 20; ///< [degC]
      double               core          = 20; ///< [degC]
      CoreThermalCondition core_condition =
        CoreThermalCondition::fixed_temperature;
      /// The cover's modulus and times against its temperature.
      ThermalSoftening softening;
      /// The covered mating roll's cover (subsection Rolling/Mating roll),
      /// at the same surface speed; none for a rigid mate.
      std::shared_ptr<Rolling> mate;

      /// The full steady rolling of each nip (doc/rolling.md, section 7):
      /// on, its speeds [m/s] (ascending; empty: speeds) and its mesh.
      bool                full_steady = false;
      std::vector<double> full_speeds;
      unsigned int        full_nip_cells = 100, full_radial_cells = 16;

      static void
      declare(ParameterHandler &prm);
      /// Reads the subsection; @p n_layers is the cover's number of layers
      /// (one value of a per-layer entry applies to all of them),
      /// @p contact_speed Contact/Surface speed [m/min], taken when
      /// Rolling/Surface speed is 0; @p mate_layers the covered mating
      /// roll's layers (0: a rigid mate, Rolling/Mating roll not read).
      void
      parse(ParameterHandler  &prm,
            const unsigned int n_layers,
            const double       contact_speed,
            const unsigned int mate_layers = 0);
      /// The cover's hysteresis and thermal entries of the current
      /// subsection.
      void
      parse_cover(ParameterHandler &prm, const unsigned int n_layers);
      /// Rolling/Mating roll (from within Rolling) into mate.
      void
      parse_mate(ParameterHandler &prm, const unsigned int n_layers);
      /// Relations to the rest of the scene @p scene; throws naming the
      /// entry.
      void
      validate(const AllParameters &scene) const;

      /// The layer of the cover @p layer's hysteresis (one layer: all).
      const ViscousLayer &
      layer(const unsigned int layer) const
      {
        return layers.size() == 1 ? layers[0] : layers.at(layer);
      }
      /// The conductivity of @p layer [W/(m K)].
      double
      layer_conductivity(const unsigned int layer) const
      {
        return conductivity.size() == 1 ? conductivity[0]
                                        : conductivity.at(layer);
      }
    };

    /// The Kelvin-Voigt retardation time [s] of a loss tangent
    /// @p tan_delta measured at @p frequency [Hz]: the one dashpot in
    /// parallel with the spring whose tan(delta) = omega tau is the
    /// measured one at omega = 2 pi @p frequency.
    double
    retardation_time_from_loss_tangent(const double tan_delta,
                                       const double frequency);
  } // namespace Parameters
} // namespace rollnip

#endif
