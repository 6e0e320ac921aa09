#ifndef rollnip_loading_line_load_unit_h
#define rollnip_loading_line_load_unit_h

#include <limits>
#include <string>

/**
 * Units of a line load (force per unit roll length) as engineers give it,
 * or of a total force on a given face length (doc/engineering_inputs.md,
 * section 3); the program computes in N/mm.
 */
namespace rollnip
{
  struct LineLoadUnit
  {
    /// As in the parameter file: N/mm, kN/m, pli, or N or kN (a total
    /// force over the face length).
    std::string name;
    double      to_n_per_mm;     ///< one of this unit in N/mm of line load
    double      face_length = 0; ///< [mm] of a total force, else 0

    /// The unit named @p name; a total force (N, kN) needs the loaded
    /// @p face_length [mm] (NaN: not given), which the line loads must not
    /// have. Throws ExcMessage naming Contact/Load unit or Contact/Face
    /// length for an unknown unit or a missing or needless length.
    static LineLoadUnit
    from_string(const std::string &name,
                double face_length = std::numeric_limits<double>::quiet_NaN());

    /// Whether the unit is a total force rather than a line load.
    bool
    is_total_force() const
    {
      return face_length > 0;
    }

    /// The CSV column of a load in this unit: line_load_N_per_mm,
    /// line_load_kN_per_m, line_load_pli, total_force_N or total_force_kN.
    std::string
    column_name() const;
  };

  /// One pound-force per linear inch in N/mm (4.4482216152605 N / 25.4 mm).
  constexpr double pli_in_n_per_mm = 4.4482216152605 / 25.4;
} // namespace rollnip

#endif
