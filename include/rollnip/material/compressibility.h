#ifndef rollnip_material_compressibility_h
#define rollnip_material_compressibility_h

#include <rollnip/parameters.h>

namespace rollnip
{
  /**
   * The volumetric stiffness of the layers of a cover from the entries
   * Material/Poisson ratio or Material/Bulk modulus (one value for all
   * layers or one per layer), with the layer's small-strain shear modulus
   * G = 2 (C1 + C2):
   *   K = 2 G (1 + nu) / (3 (1 - 2 nu)),   nu = (3 K - 2 G) / (2 (3 K + G)).
   * nu = 0.5, the default, is exact incompressibility (K infinite).
   */
  namespace Compressibility
  {
    /// The bulk modulus of layer @p layer [MPa]; infinity: incompressible.
    double
    bulk_modulus(const Parameters::Material &material,
                 const unsigned int          layer);

    /// Poisson's ratio of layer @p layer; 0.5: incompressible.
    double
    poisson_ratio(const Parameters::Material &material,
                  const unsigned int          layer);

    /// Checks the entries' counts and ranges (nu in [0, 0.5], K >= 2 G/3,
    /// not both entries); throws a one-line message naming the entry,
    /// prefixed by @p prefix ("Material/" or "Mating roll/Material/").
    void
    validate(const Parameters::Material &material, const std::string &prefix);
  } // namespace Compressibility
} // namespace rollnip

#endif
