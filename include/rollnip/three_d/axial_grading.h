#ifndef rollnip_three_d_axial_grading_h
#define rollnip_three_d_axial_grading_h

#include <utility>
#include <vector>

namespace rollnip
{
  namespace three_d
  {
    /**
     * The layer thicknesses along the roll axis [mm]: @p layers cells over
     * @p length, thinning geometrically so that the first (z = 0) is
     * @p grading times the last (z = length), which resolves the fall of
     * the line load at a free cover end with few layers.
     */
    std::vector<double>
    axial_steps(const double       length,
                const unsigned int layers,
                const double       grading);

    /// The z of the planes of nodes of axial_steps() [mm], 0 to length.
    std::vector<double>
    axial_planes(const double       length,
                 const unsigned int layers,
                 const double       grading);

    /// The index of the plane of @p planes nearest to @p z.
    unsigned int
    nearest_plane(const std::vector<double> &planes, const double z);

    /// The hat functions of @p planes at @p z: (j, t) with z between
    /// planes j and j + 1, plane j's hat 1 - t there and plane j + 1's t
    /// (t = 0 at or beyond the last plane, and before the first).
    std::pair<unsigned int, double>
    hat_share(const std::vector<double> &planes, const double z);
  } // namespace three_d
} // namespace rollnip

#endif
