#include <deal.II/base/exceptions.h>

#include <rollnip/loading/line_load_unit.h>
#include <rollnip/output/units.h>

#include <cctype>
#include <cmath>

namespace rollnip
{
  namespace
  {
    /// The canonical spelling of a unit name given in any case, or "".
    std::string
    canonical_name(const std::string &given)
    {
      std::string lower = given;
      for (char &c : lower)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      for (const char *name : {"N/mm", "kN/m", "pli", "N", "kN", "lbf"})
        {
          std::string candidate = name;
          for (char &c : candidate)
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
          if (candidate == lower)
            return name;
        }
      return lower == "lbf/in" ? "pli" : "";
    }
  } // namespace

  LineLoadUnit
  LineLoadUnit::from_string(const std::string &given, const double face_length)
  {
    const std::string name = canonical_name(given);
    AssertThrow(!name.empty(),
                dealii::ExcMessage("Contact/Load unit: unknown unit '" + given +
                                   "' (N/mm, kN/m, pli, N, kN or lbf, any "
                                   "case)"));
    const bool total = name == "N" || name == "kN" || name == "lbf";
    AssertThrow(total || std::isnan(face_length),
                dealii::ExcMessage(
                  "Contact/Face length is given, but Contact/Load unit = " +
                  name +
                  " is a line load: use N, kN or lbf for a total force"));
    if (total)
      {
        AssertThrow(!std::isnan(face_length),
                    dealii::ExcMessage("Contact/Load unit = " + name +
                                       " is a total force: give the loaded "
                                       "Contact/Face length [mm]"));
        // The line load is the force over the face length.
        const double newton = name == "kN"    ? 1000.
                              : name == "lbf" ? Units::newton_per_lbf
                                              : 1.;
        return {name, newton / face_length, face_length};
      }
    // kN/m is 1000 N per 1000 mm: the same number as N/mm.
    return {name, name == "pli" ? pli_in_n_per_mm : 1., 0};
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
