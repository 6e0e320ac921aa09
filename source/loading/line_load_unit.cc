#include <deal.II/base/exceptions.h>

#include <rollnip/loading/line_load_unit.h>

namespace rollnip
{
  LineLoadUnit
  LineLoadUnit::from_string(const std::string &name)
  {
    if (name == "N/mm")
      return {name, 1.};
    if (name == "kN/m") // 1000 N per 1000 mm
      return {name, 1.};
    if (name == "pli")
      return {name, pli_in_n_per_mm};
    AssertThrow(false,
                dealii::ExcMessage("Contact/Load unit: unknown unit '" + name +
                                   "' (N/mm, kN/m or pli)"));
    return {};
  }

  std::string
  LineLoadUnit::column_suffix() const
  {
    if (name == "kN/m")
      return "kN_per_m";
    if (name == "pli")
      return "pli";
    return "N_per_mm";
  }
} // namespace rollnip
