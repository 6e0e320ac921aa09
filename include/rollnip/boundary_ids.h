#ifndef rollnip_boundary_ids_h
#define rollnip_boundary_ids_h

#include <deal.II/base/types.h>

/**
 * The one place where the boundary and manifold ids of the roll scene are
 * defined (doc/intro.md, section 1). Gmsh files in meshes/ use the same
 * numbers as their physical curve tags.
 */
namespace rollnip
{
  namespace BoundaryIds
  {
    /// Inner arc r = R1: the bond surface with the rigid core.
    constexpr dealii::types::boundary_id inner_arc = 0;
    /// Outer arc r = R0: the cover surface, loaded or free.
    constexpr dealii::types::boundary_id outer_arc = 1;
    /// The edge X2 = 0 on the line of centres.
    constexpr dealii::types::boundary_id symmetry_edge = 2;
    /// The edge theta = sector angle.
    constexpr dealii::types::boundary_id far_edge = 3;

    constexpr unsigned int n_boundaries = 4;
  } // namespace BoundaryIds

  namespace ManifoldIds
  {
    /// Polar manifold centred on the roll axis.
    constexpr dealii::types::manifold_id polar = 0;
  } // namespace ManifoldIds
} // namespace rollnip

#endif
