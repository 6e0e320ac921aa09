#include <rollnip/material/law_factory.h>
#include <rollnip/material/linear_elastic_law.h>
#include <rollnip/material/mooney_rivlin_law.h>

namespace rollnip
{
  std::unique_ptr<MaterialLaw<dim>>
  make_layer_law(const Parameters::Material &material, const unsigned int layer)
  {
    AssertIndexRange(layer, material.n_layers());
    const MooneyRivlinLaw<dim> elastic(material.layer_C1[layer],
                                       material.layer_C2[layer]);
    if (material.theory == Parameters::Theory::linear)
      return std::make_unique<LinearElasticLaw<dim>>(elastic.shear_modulus());
    return std::make_unique<MooneyRivlinLaw<dim>>(elastic);
  }
} // namespace rollnip
