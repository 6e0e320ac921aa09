#ifndef rollnip_rolling_thermal_softening_h
#define rollnip_rolling_thermal_softening_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/global.h>

#include <vector>

namespace rollnip
{
  namespace Parameters
  {
    /**
     * How the cover's modulus and hysteresis depend on its temperature
     * (subsection Rolling/Temperature dependence, doc/rolling.md). Per
     * layer (one value: every layer), relative to Reference temperature,
     * at which Material's moduli and Rolling's loss data hold:
     *  - the moduli scale by exp(-c (T - T_ref)), c the modulus
     *    temperature coefficient [1/K] (its relative fall per kelvin);
     *  - the relaxation and retardation times by the WLF shift a_T,
     *    log10 a_T = -C1 (T - T_ref) / (C2 + T - T_ref) (C1 = 0: none).
     * With any c or C1 not zero, each nip is iterated with the cover's
     * temperature to a fixed point.
     */
    struct ThermalSoftening
    {
      double              reference_temperature = 20; ///< [degC]
      std::vector<double> modulus_coefficient{0.};    ///< c [1/K]
      std::vector<double> wlf_c1{0.}, wlf_c2{100.};   ///< C1 [-], C2 [K]
      unsigned int        max_iterations = 20;
      /// On the largest difference between a pass's temperature and the
      /// one its modulus was taken at [K].
      double tolerance = 0.01;

      static void
      declare(ParameterHandler &prm);
      /// Reads the subsection (from within Rolling); one-line errors
      /// name the entry; @p n_layers the cover's layers.
      void
      parse(ParameterHandler &prm, const unsigned int n_layers);

      /// Whether the temperature changes anything (some c or C1 not 0).
      bool
      active() const;

      /// G(T) / G(T_ref) of layer @p layer at @p T [degC].
      double
      modulus_factor(const unsigned int layer, const double T) const;

      /// The WLF shift a_T of layer @p layer at @p T [degC]; throws
      /// naming the entry if T is at or below T_ref - C2.
      double
      time_shift(const unsigned int layer, const double T) const;

    private:
      static double
      of_layer(const std::vector<double> &v, const unsigned int layer)
      {
        return v.size() == 1 ? v[0] : v.at(layer);
      }
    };
  } // namespace Parameters

  /// What the fixed point of nip and temperature did (doc/rolling.md),
  /// with the constant-modulus answer (its first pass) to compare.
  struct ThermalCoupling
  {
    bool         active     = false;
    bool         converged  = false;
    unsigned int iterations = 0; ///< nip solves after the first
    /// Each pass's residual [K]: the largest difference between the
    /// temperature its nip gives and the one its modulus was taken at.
    std::vector<double> temperature_changes;
    /// The ratio of the last two residuals (the contraction), nan if
    /// fewer.
    double contraction = 0;
    /// The constant-modulus nip: its width 2b [mm], F_r [N/mm] and
    /// temperatures [degC].
    double constant_width = 0, constant_rolling_resistance = 0;
    double constant_bond = 0, constant_surface = 0, constant_max = 0;
    /// The range of the modulus factor over the cover at the end.
    /// The softened nip's width 2b [mm].
    double width              = 0;
    double min_modulus_factor = 1, max_modulus_factor = 1;
    /// Wall time of the passes after the first nip [s].
    double seconds = 0;
  };
} // namespace rollnip

#endif
