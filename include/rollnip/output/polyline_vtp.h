#ifndef rollnip_output_polyline_vtp_h
#define rollnip_output_polyline_vtp_h

#include <deal.II/base/point.h>

#include <rollnip/global.h>

#include <string>
#include <utility>
#include <vector>

namespace rollnip
{
  /// Values at the points of a polyline: (array name, one value per point).
  using PointArrays = std::vector<std::pair<std::string, std::vector<double>>>;

  /**
   * A polyline as a VTK PolyData file (.vtp, ASCII), whole or not at all:
   * the indenter's outline and the contact pressure along the deformed
   * surface, the pieces of a nip that are not cells of the mesh.
   */
  void
  write_polyline_vtp(const std::string             &file,
                     const std::vector<Point<dim>> &points,
                     const PointArrays             &arrays);
} // namespace rollnip

#endif
