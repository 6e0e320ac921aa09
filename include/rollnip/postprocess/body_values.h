#ifndef rollnip_postprocess_body_values_h
#define rollnip_postprocess_body_values_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/postprocess/surface_data.h>

namespace rollnip
{
  /**
   * What users and drivers read off the state of a body (all collective:
   * every rank calls, the sums are global). Implemented in
   * source/postprocess/body_values.cc.
   */

  /// Radial displacement [mm] of the mesh vertex at @p X (NaN if none).
  double
  radial_displacement_at(const RollBody &body, const Point<dim> &X);

  /// Radial displacement [mm] of the surface point (R0, 0).
  double
  radial_displacement_on_line_of_centres(const RollBody &body);

  /// Resultant of the follower load on the model [N/mm] at
  /// @p load_fraction.
  Tensor<1, dim>
  load_resultant(const RollBody &body, const double load_fraction);

  /// Outer and bond surface values (gathered on rank 0) and the extremes
  /// of the fields over the cover.
  SurfaceData
  surface_data(const RollBody &body, const double load_fraction);

  /// Extremes over the Gauss points of the whole cover (on all ranks).
  FieldExtremes
  field_extremes(const RollBody &body);
} // namespace rollnip

#endif
