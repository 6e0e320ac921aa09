#ifndef rollnip_material_layer_order_h
#define rollnip_material_layer_order_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/global.h>

namespace rollnip
{
  namespace Parameters
  {
    struct AllParameters;
    struct Material;
  } // namespace Parameters

  /**
   * Material/Layer order: in which order the per-layer lists of a layered
   * cover (C1, C2, Hardness, Layer thicknesses) are written. The program
   * reads them from the core out; a roll maker's data sheet often lists
   * the top stock first, and a table entered that way is a valid, wrong
   * cover. So the order is stated: `core first`, or `top first` (the
   * lists are then reversed when read); a layered cover without it gets
   * one warning saying how it was read (doc/layers.md).
   */
  namespace LayerOrder
  {
    /// Declares Material/Layer order in the current subsection.
    void
    declare(ParameterHandler &prm);

    /// Applies the Layer order of the Material subsection in the current
    /// subsection of @p prm to @p material, which was parsed from it:
    /// reverses a top-first table, warns once (on MPI rank 0, prefixed
    /// with @p prefix in the entry's name) when a layered cover's order is
    /// not stated.
    void
    apply(ParameterHandler     &prm,
          Parameters::Material &material,
          const std::string    &prefix);

    /// apply() to the cover of @p parameters and, if it is a covered
    /// roll, to the mating roll's cover.
    void
    apply(ParameterHandler &prm, Parameters::AllParameters &parameters);
  } // namespace LayerOrder
} // namespace rollnip

#endif
