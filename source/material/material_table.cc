#include <rollnip/material/material_table.h>

namespace rollnip
{
  MaterialTable::MaterialTable(const Parameters::Material &material)
  {
    layers.emplace_back(material);
  }
} // namespace rollnip
