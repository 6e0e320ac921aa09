#ifndef rollnip_material_material_table_h
#define rollnip_material_material_table_h

#include <deal.II/base/types.h>

#include <rollnip/material/mooney_rivlin.h>
#include <rollnip/parameters.h>

#include <vector>

namespace rollnip
{
  /**
   * The Mooney-Rivlin law of every layer of the cover, looked up by a
   * cell's material id (layer 0 is the one on the core). A one-layer cover
   * gives every cell the same law, whatever its id (gmsh meshes may carry
   * any physical surface tag).
   */
  class MaterialTable
  {
  public:
    explicit MaterialTable(const Parameters::Material &material);

    const MooneyRivlin &
    operator[](const types::material_id id) const
    {
      return layers.size() == 1 ? layers[0] : layers.at(id);
    }

    unsigned int
    n_layers() const
    {
      return layers.size();
    }

    /// The layer on the outer surface, whose modulus the contact estimates
    /// (the Hertz start of the pressure) use.
    const MooneyRivlin &
    surface_layer() const
    {
      return layers.back();
    }

    bool
    is_linear() const
    {
      return layers[0].is_linear();
    }

  private:
    std::vector<MooneyRivlin> layers;
  };

  /// G = 2 (C1 + C2) [MPa] of the layer on the outer surface: the modulus
  /// of the contact estimates and the reference solutions (Hertz, thin
  /// layer).
  inline double
  surface_shear_modulus(const Parameters::Material &material)
  {
    return MooneyRivlin(material).shear_modulus();
  }
} // namespace rollnip

#endif
