#ifndef rollnip_output_units_h
#define rollnip_output_units_h

#include <rollnip/parameters.h>

#include <string>

/**
 * The one table of units rollnip reports in (doc/engineering_inputs.md,
 * section 3): the program computes in mm, MPa, N/mm, N, m/min and ms; a
 * reported number is converted here, to SI (those units) or US customary
 * units (in, psi, pli, lbf, fpm; times stay in ms). Unit names in the
 * parameter file are read case-insensitively.
 */
namespace rollnip
{
  namespace Units
  {
    /// Exact definitions: the international inch and pound-force.
    constexpr double mm_per_inch    = 25.4;
    constexpr double newton_per_lbf = 4.4482216152605;
    /// One psi in MPa (lbf per square inch).
    constexpr double mpa_per_psi = newton_per_lbf / (mm_per_inch * mm_per_inch);
    /// One foot per minute in m/min, one m/s in m/min.
    constexpr double m_per_min_per_fpm     = 12 * mm_per_inch / 1000.;
    constexpr double m_per_min_per_m_per_s = 60.;

    /// What a reported number is.
    enum class Quantity
    {
      length,    ///< mm or in
      pressure,  ///< MPa or psi (stresses and moduli too)
      line_load, ///< N/mm or pli
      force,     ///< N or lbf
      speed,     ///< m/min or fpm
      time       ///< ms in both systems
    };

    /// A unit of a reported quantity: its name on the screen, its tag in
    /// CSV column names, and how many of it make one program unit.
    struct Unit
    {
      std::string name;
      std::string column;
      double      per_program_unit;

      /// @p value (in the program's unit) in this unit.
      double
      operator()(const double value) const
      {
        return value * per_program_unit;
      }
    };

    /// The unit of @p quantity in @p system.
    Unit
    unit(Quantity quantity, Parameters::UnitSystem system);

    /// @p text in lower case (unit names are case-insensitive).
    std::string
    lower_case(const std::string &text);

    /// Output/Units as written: SI or US, any case. Throws ExcMessage
    /// naming Output/Units otherwise.
    Parameters::UnitSystem
    system_from_string(const std::string &text);

    /// A speed as "V" (m/min), "V m/min", "V m/s" or "V fpm" (also
    /// ft/min), any case, in m/min (>= 0). Throws ExcMessage naming
    /// Contact/Surface speed otherwise.
    double
    speed_in_m_per_min(const std::string &text);
  } // namespace Units
} // namespace rollnip

#endif
