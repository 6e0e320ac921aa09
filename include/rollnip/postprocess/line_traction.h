#ifndef rollnip_postprocess_line_traction_h
#define rollnip_postprocess_line_traction_h

#include <rollnip/body/roll_body.h>

#include <vector>

namespace rollnip
{
  /// The traction t = sigma n on one node of the bond or of an interface,
  /// n the unit normal of the DEFORMED line pointing away from the roll
  /// axis and s = (-n2, n1) its tangent (counter-clockwise) [MPa].
  struct LineTraction
  {
    double theta;    ///< reference angle of the node [rad]
    double sigma_nn; ///< n . sigma n
    double sigma_nt; ///< s . sigma n
  };

  /**
   * The traction on the bond r = R1 (boundary id 0) at its mesh vertices,
   * recovered from the consistent nodal forces of the cover's cells there
   * (the reactions of the constrained core nodes) through the mass matrix
   * of the bond: int t phi_a da = f_a. Gathered on rank 0 (other ranks get
   * an empty vector), sorted by angle. Collective.
   */
  std::vector<LineTraction>
  bond_traction(const RollBody &body);

  /// The same on interface @p j (between layers j and j + 1, from the
  /// core), from the nodal forces of layer j's cells, or of layer j + 1's
  /// if @p from_outer_layer: t is continuous across the bonded interface,
  /// so either side gives it (up to the discretisation error).
  std::vector<LineTraction>
  interface_traction(const RollBody    &body,
                     const unsigned int j,
                     const bool         from_outer_layer = false);
} // namespace rollnip

#endif
