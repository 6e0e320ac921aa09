#ifndef rollnip_material_material_table_h
#define rollnip_material_material_table_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/tria_accessor.h>

#include <rollnip/global.h>
#include <rollnip/material/material_law.h>
#include <rollnip/material/scaled_law.h>
#include <rollnip/parameters.h>

#include <functional>
#include <memory>
#include <vector>

namespace rollnip
{
  /**
   * The law of every layer of the cover (make_layer_law()), looked up by a
   * cell's material id (layer 0 is the one on the core). A one-layer cover
   * gives every cell the same law, whatever its id (gmsh meshes may carry
   * any physical surface tag). A modulus factor, if set, scales the law
   * of each cell (a cover softened by its temperature, doc/rolling.md):
   * law() is the one the assembly and the output use.
   */
  class MaterialTable
  {
  public:
    explicit MaterialTable(const Parameters::Material &material);

    const MaterialLaw<dim> &
    operator[](const types::material_id id) const
    {
      return layers.size() == 1 ? *layers[0] : *layers.at(id);
    }

    /// The factor s(X, layer) on the moduli of the cell whose reference
    /// centre is X; an empty function: none (every factor 1).
    using ModulusFactor =
      std::function<double(const Point<dim> &, const types::material_id)>;

    /// The law of @p cell: its layer's, its moduli times the modulus
    /// factor at the cell's centre.
    ScaledLaw<dim>
    law(const CellAccessor<dim, dim> &cell) const
    {
      const types::material_id id = cell.material_id();
      return ScaledLaw<dim>((*this)[id],
                            modulus_factor ? modulus_factor(cell.center(), id)
                                           : 1.);
    }

    /// Sets the modulus factor (empty: none) for the next solves.
    void
    set_modulus_factor(const ModulusFactor &factor)
    {
      modulus_factor = factor;
    }

    unsigned int
    n_layers() const
    {
      return layers.size();
    }

    /// The layer on the outer surface, whose modulus the contact estimates
    /// (the Hertz start of the pressure) use.
    const MaterialLaw<dim> &
    surface_layer() const
    {
      return *layers.back();
    }

    /// Whether the laws are those of the linear theory: the body then
    /// also takes the load on the reference surface and does not check J.
    bool
    is_linear() const
    {
      return linear;
    }

    /// MaterialLaw::commit() of every layer: a converged load step.
    void
    commit();

    /// MaterialLaw::rollback() of every layer: a discarded solve.
    void
    rollback();

  private:
    bool                                           linear;
    std::vector<std::unique_ptr<MaterialLaw<dim>>> layers;
    ModulusFactor                                  modulus_factor;
  };
} // namespace rollnip

#endif
