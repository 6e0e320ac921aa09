#include <rollnip/material/compressibility.h>
#include <rollnip/material/law_factory.h>
#include <rollnip/material/linear_elastic_law.h>
#include <rollnip/material/mooney_rivlin_law.h>

namespace rollnip
{
  template <int d>
  std::unique_ptr<MaterialLaw<d>>
  make_layer_law(const Parameters::Material &material, const unsigned int layer)
  {
    AssertIndexRange(layer, material.n_layers());
    const double             K = Compressibility::bulk_modulus(material, layer);
    const MooneyRivlinLaw<d> elastic(material.layer_C1[layer],
                                     material.layer_C2[layer],
                                     K);
    if (material.theory == Parameters::Theory::linear)
      return std::make_unique<LinearElasticLaw<d>>(elastic.shear_modulus(), K);
    return std::make_unique<MooneyRivlinLaw<d>>(elastic);
  }

  template std::unique_ptr<MaterialLaw<2>>
  make_layer_law<2>(const Parameters::Material &, const unsigned int);
  template std::unique_ptr<MaterialLaw<3>>
  make_layer_law<3>(const Parameters::Material &, const unsigned int);
} // namespace rollnip
