#include <rollnip/geometry/gmsh_scan.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace rollnip
{
  namespace
  {
    /// The dimension of gmsh element type @p type (the numbering of the
    /// gmsh manual, first and second order); 0 for points and unknown types.
    unsigned int
    element_dimension(const int type)
    {
      switch (type)
        {
          case 1: // 2-node line
          case 8: // 3-node line
            return 1;
          case 2:  // triangle
          case 3:  // quadrilateral
          case 9:  // 6-node triangle
          case 10: // 9-node quadrilateral
          case 16: // 8-node quadrilateral
            return 2;
          case 4:  // tetrahedron
          case 5:  // hexahedron
          case 6:  // prism
          case 7:  // pyramid
          case 11: // 10-node tetrahedron
          case 12: // 27-node hexahedron
          case 13: // 18-node prism
          case 14: // 14-node pyramid
          case 17: // 20-node hexahedron
          case 18: // 15-node prism
          case 19: // 13-node pyramid
            return 3;
          default:
            return 0;
        }
    }

    /// Format 2: one element a line, "number type ...".
    void
    element_types_v2(std::istream &in, std::set<int> &types)
    {
      long n = 0;
      in >> n;
      std::string line;
      std::getline(in, line);
      for (long k = 0; k < n && std::getline(in, line); ++k)
        {
          std::istringstream fields(line);
          long               number = 0;
          int                type   = 0;
          if (fields >> number >> type)
            types.insert(type);
        }
    }

    /// Format 4: blocks headed "entityDim entityTag type count".
    void
    element_types_v4(std::istream &in, std::set<int> &types)
    {
      long blocks = 0, n = 0, min_tag = 0, max_tag = 0;
      in >> blocks >> n >> min_tag >> max_tag;
      std::string line;
      std::getline(in, line);
      for (long b = 0; b < blocks && std::getline(in, line); ++b)
        {
          std::istringstream header(line);
          unsigned int       entity_dimension = 0;
          long               tag = 0, count = 0;
          int                type = 0;
          if (!(header >> entity_dimension >> tag >> type >> count))
            return;
          types.insert(type);
          for (long k = 0; k < count && std::getline(in, line); ++k)
            ;
        }
    }
  } // namespace

  std::set<int>
  gmsh_element_types(const std::string &file)
  {
    std::ifstream in(file);
    std::string   line;
    double        version = 0;
    int           binary  = 1;
    std::set<int> types;
    while (std::getline(in, line))
      {
        if (line.rfind("$MeshFormat", 0) == 0)
          {
            in >> version >> binary;
            if (binary != 0)
              break;
          }
        else if (line.rfind("$Elements", 0) == 0)
          {
            if (version >= 4)
              element_types_v4(in, types);
            else if (version >= 2)
              element_types_v2(in, types);
            break;
          }
      }
    return types;
  }

  unsigned int
  gmsh_mesh_dimension(const std::string &file)
  {
    unsigned int dimension = 0;
    for (const int type : gmsh_element_types(file))
      dimension = std::max(dimension, element_dimension(type));
    return dimension;
  }

  bool
  gmsh_volume_cells_are_hexahedra(const std::string &file)
  {
    for (const int type : gmsh_element_types(file))
      if (element_dimension(type) == 3 && type != 5 && type != 12 && type != 17)
        return false;
    return true;
  }
} // namespace rollnip
