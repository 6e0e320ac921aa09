#include <rollnip/output/atomic_file.h>
#include <rollnip/output/polyline_vtp.h>

#include <iomanip>

namespace rollnip
{
  void
  write_polyline_vtp(const std::string             &file,
                     const std::vector<Point<dim>> &points,
                     const PointArrays             &arrays)
  {
    write_atomically(file, [&](std::ostream &out) {
      const std::size_t n = points.size();
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"PolyData\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n"
          << "  <PolyData>\n"
          << "    <Piece NumberOfPoints=\"" << n
          << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << (n > 1 ? 1 : 0)
          << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
          << "      <PointData>\n"
          << std::setprecision(10);
      for (const auto &[name, values] : arrays)
        {
          out << "        <DataArray type=\"Float64\" Name=\"" << name
              << "\" format=\"ascii\">\n         ";
          for (const double v : values)
            out << ' ' << v;
          out << "\n        </DataArray>\n";
        }
      out << "      </PointData>\n"
          << "      <Points>\n"
          << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n         ";
      for (const auto &p : points)
        out << ' ' << p[0] << ' ' << p[1] << " 0";
      out << "\n        </DataArray>\n"
          << "      </Points>\n"
          << "      <Lines>\n"
          << "        <DataArray type=\"Int64\" Name=\"connectivity\" "
             "format=\"ascii\">\n         ";
      for (std::size_t i = 0; i < n && n > 1; ++i)
        out << ' ' << i;
      out << "\n        </DataArray>\n"
          << "        <DataArray type=\"Int64\" Name=\"offsets\" "
             "format=\"ascii\">\n         ";
      if (n > 1)
        out << ' ' << n;
      out << "\n        </DataArray>\n"
          << "      </Lines>\n"
          << "    </Piece>\n"
          << "  </PolyData>\n"
          << "</VTKFile>\n";
    });
  }
} // namespace rollnip
