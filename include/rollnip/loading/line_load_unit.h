#ifndef rollnip_loading_line_load_unit_h
#define rollnip_loading_line_load_unit_h

#include <string>

/**
 * Units of a line load (force per unit roll length) as engineers give it
 * (doc/engineering_inputs.md, section 3); the program computes in N/mm.
 */
namespace rollnip
{
  struct LineLoadUnit
  {
    std::string name;        ///< as in the parameter file: N/mm, kN/m or pli
    double      to_n_per_mm; ///< one of this unit in N/mm

    /// The unit named @p name; throws ExcMessage naming Contact/Load unit
    /// for an unknown one.
    static LineLoadUnit
    from_string(const std::string &name);

    /// The name for a CSV column: N_per_mm, kN_per_m or pli.
    std::string
    column_suffix() const;
  };

  /// One pound-force per linear inch in N/mm (4.4482216152605 N / 25.4 mm).
  constexpr double pli_in_n_per_mm = 4.4482216152605 / 25.4;
} // namespace rollnip

#endif
