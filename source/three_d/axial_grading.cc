#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/three_d/axial_grading.h>

#include <algorithm>
#include <cmath>

namespace rollnip
{
  namespace three_d
  {
    std::vector<double>
    axial_steps(const double       length,
                const unsigned int layers,
                const double       grading)
    {
      return graded_steps(layers, length, 1. / grading);
    }

    std::vector<double>
    axial_planes(const double       length,
                 const unsigned int layers,
                 const double       grading)
    {
      std::vector<double> planes = {0.};
      for (const double step : axial_steps(length, layers, grading))
        planes.push_back(planes.back() + step);
      // The last plane is the far face itself, not a sum of rounded steps.
      planes.back() = length;
      return planes;
    }

    unsigned int
    nearest_plane(const std::vector<double> &planes, const double z)
    {
      const auto above = std::lower_bound(planes.begin(), planes.end(), z);
      if (above == planes.begin())
        return 0;
      if (above == planes.end() || z - *(above - 1) < *above - z)
        return above - planes.begin() - 1;
      return above - planes.begin();
    }

    std::pair<unsigned int, double>
    hat_share(const std::vector<double> &planes, const double z)
    {
      const auto above = std::upper_bound(planes.begin(), planes.end(), z);
      if (above == planes.begin())
        return {0, 0.};
      if (above == planes.end())
        return {planes.size() - 1, 0.};
      const unsigned int j = above - planes.begin() - 1;
      return {j, (z - planes[j]) / (planes[j + 1] - planes[j])};
    }
  } // namespace three_d
} // namespace rollnip
