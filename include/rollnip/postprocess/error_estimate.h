#ifndef rollnip_postprocess_error_estimate_h
#define rollnip_postprocess_error_estimate_h

#include <rollnip/parameters.h>

#include <array>
#include <string>

namespace rollnip
{
  /// The reported numbers of a nip that carry an error estimate, in the
  /// order of NipNumbers.
  namespace NipQuantity
  {
    enum Index : unsigned int
    {
      theta0,            ///< half nip angle [deg]
      load,              ///< P [N/mm]
      indentation,       ///< u0 [mm]
      half_chord,        ///< b, half the nip width [mm]
      peak_pressure,     ///< [MPa]
      mean_pressure,     ///< P / 2b [MPa]
      bond_sigma_rr,     ///< smallest sigma_rr on the bond [MPa]
      bond_sigma_rtheta, ///< largest |sigma_rtheta| on the bond [MPa]
      n_quantities
    };

    /// The column stem of quantity @p q in the results files (the unit
    /// follows it), e.g. "P" for "P_N_per_mm".
    std::string
    key(const Index q);

    /// The unit of @p q as a column suffix, e.g. "N_per_mm".
    std::string
    unit(const Index q);

    /// How @p q is named on the screen, e.g. "P" or "bond sigma_rtheta".
    std::string
    label(const Index q);
  } // namespace NipQuantity

  using NipNumbers = std::array<double, NipQuantity::n_quantities>;

  /**
   * The estimated error of each reported number of a nip (doc/accuracy.md,
   * "Error estimates"). The nip is solved again with the same control
   * (theta0, P or u0) on the mesh one level coarser, and each number's
   * error is Richardson's: |a - c| / (2^p - 1), with p the order at which
   * that number converges for the element (measured, error_order()). At
   * level 0 the companion is one level finer and the error of the answer
   * is |a - c| 2^p / (2^p - 1). The mean pressure P / 2b takes the sum of
   * the relative errors of P and b.
   */
  struct ErrorEstimate
  {
    bool       available = false;
    NipNumbers error{}; ///< absolute, in the numbers' units
    /// Mesh level of the companion solve and its wall time [s].
    unsigned int companion_level   = 0;
    double       companion_seconds = 0;
    /// Why there is none, when not available.
    std::string missing;

    /// The error of @p q relative to @p value, nan if not available.
    double
    relative(const NipQuantity::Index q, const double value) const;

    /// How the estimate was made, in one line.
    std::string
    method(const Parameters::Element     element,
           const Parameters::ContactMode mode,
           const unsigned int            level) const;
  };

  /// The order of convergence in the mesh size at which quantity @p q of a
  /// nip converges with @p element on the builtin meshes when the nip is
  /// controlled by @p mode (measured, doc/accuracy.md): with theta0
  /// prescribed the nip's numbers follow the contact edge and converge at
  /// first order; with P or u0 prescribed, P, u0 and the peak pressure
  /// converge at second order.
  double
  error_order(const Parameters::Element     element,
              const NipQuantity::Index      q,
              const Parameters::ContactMode mode);

  /// The estimate of the errors of @p answer, solved at mesh level
  /// @p level, from @p companion, the same nip at @p companion_level
  /// (level - 1, or 1 at level 0).
  ErrorEstimate
  estimate_errors(const NipNumbers             &answer,
                  const NipNumbers             &companion,
                  const Parameters::Element     element,
                  const Parameters::ContactMode mode,
                  const unsigned int            level,
                  const unsigned int            companion_level);

  /// A nip's numbers extrapolated from three mesh levels, and their
  /// estimated errors.
  struct ExtrapolatedNumbers
  {
    NipNumbers value{}; ///< in the numbers' units
    NipNumbers error{}; ///< absolute, in the numbers' units
  };

  /// The order at which numbers extrapolated at order 1 from three levels
  /// (extrapolate_first_order()) converge with @p element at a prescribed
  /// theta0, measured on the default scene at 4, 8, 12 deg against the
  /// other element family (doc/accuracy.md): the changes of P's
  /// extrapolation fall by 0.22 to 0.29 per level with Q2-P1 (order 2),
  /// by 0.34 to 0.39 with Q1-P0 at 12 deg (order 1.5).
  double
  extrapolated_order(const Parameters::Element element);

  /**
   * Richardson at order 1 for numbers that converge at first order (with
   * theta0 prescribed, doc/accuracy.md "An accuracy target"): from the
   * nip at mesh levels L (@p fine), L - 1 (@p middle) and L - 2
   * (@p coarse), the value 2 fine - middle, and its error as the change
   * from the same extrapolation one level down, 2 middle - coarse, over
   * 2^q - 1 with q = extrapolated_order(@p element).
   */
  ExtrapolatedNumbers
  extrapolate_first_order(const NipNumbers         &fine,
                          const NipNumbers         &middle,
                          const NipNumbers         &coarse,
                          const Parameters::Element element);
} // namespace rollnip

#endif
