#ifndef rollnip_material_law_factory_h
#define rollnip_material_law_factory_h

#include <rollnip/global.h>
#include <rollnip/material/material_law.h>
#include <rollnip/parameters.h>

#include <memory>

namespace rollnip
{
  /**
   * The law of layer @p layer (0: on the core) of @p material: the
   * Mooney-Rivlin law in finite strain, or, for Theory = linear, the
   * small-strain law of the same shear modulus, each with the layer's bulk
   * modulus (material/compressibility.h). The only place that turns the
   * theory and the constants of a layer into a law; a new law is a new
   * class and a new case here. @p d: 2 for the plane-strain body, 3 for
   * the 3D one.
   */
  template <int d = dim>
  std::unique_ptr<MaterialLaw<d>>
  make_layer_law(const Parameters::Material &material,
                 const unsigned int          layer);
} // namespace rollnip

#endif
