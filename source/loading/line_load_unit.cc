#include <deal.II/base/exceptions.h>

#include <rollnip/loading/line_load_unit.h>

#include <cmath>

namespace rollnip
{
  LineLoadUnit
  LineLoadUnit::from_string(const std::string &name, const double face_length)
  {
    const bool total = name == "N" || name == "kN";
    AssertThrow(total || std::isnan(face_length),
                dealii::ExcMessage(
                  "Contact/Face length is given, but Contact/Load unit = " +
                  name + " is a line load: use N or kN for a total force"));
    if (total)
      {
        AssertThrow(!std::isnan(face_length),
                    dealii::ExcMessage("Contact/Load unit = " + name +
                                       " is a total force: give the loaded "
                                       "Contact/Face length [mm]"));
        // The line load is the force over the face length.
        return {name, (name == "kN" ? 1000. : 1.) / face_length, face_length};
      }
    if (name == "N/mm")
      return {name, 1., 0};
    if (name == "kN/m") // 1000 N per 1000 mm
      return {name, 1., 0};
    if (name == "pli")
      return {name, pli_in_n_per_mm, 0};
    AssertThrow(false,
                dealii::ExcMessage("Contact/Load unit: unknown unit '" + name +
                                   "' (N/mm, kN/m, pli, N or kN)"));
    return {};
  }

  std::string
  LineLoadUnit::column_name() const
  {
    if (is_total_force())
      return "total_force_" + name;
    if (name == "kN/m")
      return "line_load_kN_per_m";
    if (name == "pli")
      return "line_load_pli";
    return "line_load_N_per_mm";
  }
} // namespace rollnip
