#include <deal.II/base/numbers.h>

#include <rollnip/face/crown.h>
#include <rollnip/global.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace rollnip
{
  namespace Face
  {
    std::vector<std::pair<double, double>>
    read_crown_table(const std::string &file, const std::string &entry)
    {
      std::ifstream in(file);
      AssertThrow(in.good(),
                  ExcMessage(entry + " '" + file + "' cannot be opened"));
      std::vector<std::pair<double, double>> rows;
      std::string                            line;
      unsigned int                           n = 0;
      while (std::getline(in, line))
        {
          ++n;
          std::replace(line.begin(), line.end(), ',', ' ');
          std::istringstream s(line);
          double             y, c;
          if (line.find_first_not_of(" \t\r") == std::string::npos ||
              line[line.find_first_not_of(" \t")] == '#')
            continue;
          if (!(s >> y >> c))
            {
              // The header: the first line that is not two numbers.
              AssertThrow(rows.empty() && n == 1,
                          ExcMessage(entry + " '" + file + "', line " +
                                     std::to_string(n) +
                                     ": not 'y, change' in mm"));
              continue;
            }
          AssertThrow(rows.empty() || y > rows.back().first,
                      ExcMessage(entry + " '" + file + "', line " +
                                 std::to_string(n) +
                                 ": y must increase from row to row"));
          rows.emplace_back(y, c);
        }
      AssertThrow(rows.size() >= 2,
                  ExcMessage(entry + " '" + file +
                             "' holds fewer than two rows"));
      if (rows.front().first >= 0)
        {
          std::vector<std::pair<double, double>> mirrored;
          for (auto it = rows.rbegin(); it != rows.rend(); ++it)
            if (it->first > 0)
              mirrored.emplace_back(-it->first, it->second);
          mirrored.insert(mirrored.end(), rows.begin(), rows.end());
          rows = mirrored;
        }
      return rows;
    }

    Crown
    make_crown(const Parameters::FaceCrown &p, const double face_length)
    {
      using Parameters::CrownShape;
      const double scale = p.on_diameter ? 0.5 : 1.;
      const double c     = scale * p.amount;
      const double half  = face_length / 2;
      switch (p.shape)
        {
          case CrownShape::parabolic:
            return
              [=](const double y) { return c * (1 - (y / half) * (y / half)); };
          case CrownShape::sine:
            return [=](const double y) {
              return c * std::cos(numbers::PI / 2 * y / half);
            };
          case CrownShape::circular:
            {
              // The arc through both face ends with height c at the centre.
              const double R = (half * half + c * c) / (2 * c);
              return [=](const double y) {
                const double s = std::sqrt(R * R - y * y);
                return c > 0 ? s - (R - c) : -s - (R - c);
              };
            }
          case CrownShape::table:
            {
              const auto rows =
                read_crown_table(p.table_file, "Face/Crown/Table file");
              return [=](const double y) {
                if (y <= rows.front().first)
                  return scale * rows.front().second;
                if (y >= rows.back().first)
                  return scale * rows.back().second;
                const auto it =
                  std::upper_bound(rows.begin(),
                                   rows.end(),
                                   y,
                                   [](const double v, const auto &r) {
                                     return v < r.first;
                                   });
                const auto  &a = *(it - 1), &b = *it;
                const double s = (y - a.first) / (b.first - a.first);
                return scale * ((1 - s) * a.second + s * b.second);
              };
            }
          default:
            return [](const double) { return 0.; };
        }
    }

    Crown
    ideal_crown(const FaceMesh        &mesh,
                const BeamSection     &section,
                const Eigen::VectorXd &w,
                const double           face_length)
    {
      const double end = (deflection_at(mesh, section, w, -face_length / 2) +
                          deflection_at(mesh, section, w, face_length / 2)) /
                         2;
      return [=](const double y) {
        return deflection_at(mesh, section, w, y) - end;
      };
    }
  } // namespace Face
} // namespace rollnip
