#include <rollnip/material/material_table.h>

namespace rollnip
{
  MaterialTable::MaterialTable(const Parameters::Material &material)
  {
    const bool linear = material.theory == Parameters::Theory::linear;
    for (unsigned int j = 0; j < material.n_layers(); ++j)
      layers.emplace_back(material.layer_C1[j], material.layer_C2[j], linear);
  }
} // namespace rollnip
