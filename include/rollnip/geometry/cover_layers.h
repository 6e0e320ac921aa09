#ifndef rollnip_geometry_cover_layers_h
#define rollnip_geometry_cover_layers_h

#include <deal.II/grid/tria.h>

#include <rollnip/global.h>
#include <rollnip/parameters.h>

#include <vector>

namespace rollnip
{
  /**
   * The radial layout of a (layered) cover: where its interfaces are, how
   * many coarse radial cells each layer gets, and which layer a cell is in.
   * Both mesh generators take their radial cells from here, so that every
   * interface is a cell boundary.
   */

  /// Radii of the layer boundaries [mm], from R1 to R0 (layers + 1).
  std::vector<double>
  layer_radii(const Parameters::AllParameters &parameters);

  /// Coarse radial cells of every layer: in proportion to the thickness,
  /// at least one each, Mesh/Radial cells in all (or one per layer if
  /// there are more layers).
  std::vector<unsigned int>
  layer_cell_counts(const Parameters::AllParameters &parameters);

  /// The extra grading (outermost over innermost cell) of @p layer's own
  /// cells: (G below / G)^(1/4) for a layer stiffer than the one below it,
  /// 1 otherwise. A stiff layer on a soft one bends over a length that
  /// grows like the fourth root of its stiffness against the foundation's;
  /// its cells thicken towards the interface and thin towards its surface,
  /// where the nip loads it. Measured on a 3.5 mm top 5 times stiffer than
  /// its 10 mm base: the error of P of Q1-P0 at level 2 falls from 0.033 %
  /// to 0.028 % (against Q2-P1, doc/accuracy.md; the peak pressure's
  /// rises from 0.071 % to 0.085 %). The square root grades further, but
  /// its error then stops falling by 4 per level and the level-1 error
  /// estimate drops to a quarter of the error.
  /// Continuous in the moduli: two equal layers stay one layer.
  double
  stiff_layer_grading(const Parameters::AllParameters &parameters,
                      const unsigned int               layer);

  /// The coarse radial cell widths [mm] from R1 to R0: the geometric
  /// grading of the whole cover with last over first cell @p ratio, each
  /// layer taking its cells of it stretched to fill the layer exactly
  /// and graded once more by stiff_layer_grading().
  std::vector<double>
  radial_steps(const Parameters::AllParameters &parameters, const double ratio);

  /// The layer (0 on the core) that radius @p r [mm] lies in.
  unsigned int
  layer_at_radius(const std::vector<double> &radii, const double r);

  /// Sets every cell's material id to the layer its centre lies in.
  void
  set_layer_ids(const Parameters::AllParameters &parameters,
                Triangulation<dim>              &triangulation);

  /// Throws a one-line message naming @p origin if a cell's material id is
  /// not a layer or its centre lies outside that layer (gmsh meshes of a
  /// layered cover carry the layer as physical surface tag 0, 1, ...);
  /// the entries are named with @p prefix ("" or "Mating roll/").
  void
  check_layer_ids(const Parameters::AllParameters &parameters,
                  const Triangulation<dim>        &triangulation,
                  const std::string               &origin,
                  const std::string               &prefix);
} // namespace rollnip

#endif
