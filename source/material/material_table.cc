#include <rollnip/material/law_factory.h>
#include <rollnip/material/material_table.h>

namespace rollnip
{
  MaterialTable::MaterialTable(const Parameters::Material &material)
      : linear(material.theory == Parameters::Theory::linear)
  {
    for (unsigned int j = 0; j < material.n_layers(); ++j)
      layers.push_back(make_layer_law(material, j));
  }

  void
  MaterialTable::commit()
  {
    for (const auto &law : layers)
      law->commit();
  }

  void
  MaterialTable::rollback()
  {
    for (const auto &law : layers)
      law->rollback();
  }
} // namespace rollnip
