
#include <rollnip/geometry/cover_layers.h>
#include <rollnip/geometry/gmsh_scan.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/drawn_mesh.h>
#include <rollnip/three_d/slice_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <set>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// What each SliceIds id stands for, in the messages.
      const std::array<std::string, 6> id_names = {
        {"inner arc r = Geometry/Inner radius",
         "outer arc r = Geometry/Outer radius",
         "symmetry plane theta = 0",
         "far edge plane theta = Geometry/Sector angle",
         "symmetry plane z = 0",
         "far face z = Three d/Slice thickness"}};

      std::string
      at(const Point<dim> &p)
      {
        return "(" + Parameters::number(p[0]) + ", " +
               Parameters::number(p[1]) + ", " + Parameters::number(p[2]) +
               ") mm";
      }

      /// GridIn<3> on the file; hexahedra of positive volume only.
      void
      read_hexahedra(const std::string  &file,
                     const std::string  &origin,
                     Triangulation<dim> &coarse)
      {
        std::ifstream in(file);
        AssertThrow(in.good(),
                    ExcMessage("Mesh/Mesh file: cannot open '" + file + "'"));
        const std::string hexahedra_only =
          "; the 3D body needs hexahedra only (in gmsh: extrude a "
          "recombined surface with Layers and Recombine)";
        AssertThrow(gmsh_volume_cells_are_hexahedra(file),
                    ExcMessage(origin +
                               " contains tetrahedra, prisms or pyramids" +
                               hexahedra_only));
        read_gmsh_mesh(in,
                       coarse,
                       origin + " is not a readable gmsh mesh of hexahedra");
        AssertThrow(coarse.n_active_cells() > 0 &&
                      coarse.all_reference_cells_are_hyper_cube(),
                    ExcMessage(origin + " contains no hexahedra" +
                               hexahedra_only));
        for (const auto &cell : coarse.active_cell_iterators())
          AssertThrow(cell->measure() > 0,
                      ExcMessage(origin + ": the cell at " +
                                 at(cell->center()) +
                                 " has a volume <= 0 (an inverted or tangled "
                                 "hexahedron)"));
      }

      /// Equidistant stations from 0 to @p length, twice as far apart as
      /// the median length in z of the outer surface's faces: a hat over
      /// about two cells, whose interpolant on the cells (which shares the
      /// nodal forces) keeps its shape.
      std::vector<double>
      axial_stations(const Triangulation<dim> &coarse, const double length)
      {
        std::vector<double> extents;
        for (const auto &face : coarse.active_face_iterators())
          if (face->at_boundary() && face->boundary_id() == SliceIds::outer_arc)
            {
              double low = face->vertex(0)[2], high = low;
              for (const unsigned int v : face->vertex_indices())
                {
                  low  = std::min(low, face->vertex(v)[2]);
                  high = std::max(high, face->vertex(v)[2]);
                }
              extents.push_back(high - low);
            }
        double spacing = length;
        if (!extents.empty())
          {
            std::nth_element(extents.begin(),
                             extents.begin() + extents.size() / 2,
                             extents.end());
            spacing = 2 * extents[extents.size() / 2];
          }
        const unsigned int n = std::max<long>(
          1, std::lround(length / std::max(spacing, 1e-6 * length)));
        std::vector<double> stations;
        for (unsigned int j = 0; j <= n; ++j)
          stations.push_back(length * j / n);
        return stations;
      }

      /// The planes z = const of the vertices, checked to run from 0 to
      /// @p length; the mesh's layers if every cell lies between two
      /// neighbouring ones, else axial_stations().
      AxialPlanes
      axial_layers(const Triangulation<dim> &coarse,
                   const double              length,
                   const std::string        &origin)
      {
        const double        tol = 1e-6 * length;
        std::vector<double> z;
        for (const auto &cell : coarse.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            z.push_back(cell->vertex(v)[2]);
        std::sort(z.begin(), z.end());
        AssertThrow(std::abs(z.front()) < tol &&
                      std::abs(z.back() - length) < tol,
                    ExcMessage(origin +
                               " spans z = " + Parameters::number(z.front()) +
                               " to " + Parameters::number(z.back()) +
                               " mm; the 3D body runs from z = 0 to Three "
                               "d/Slice thickness = " +
                               Parameters::number(length) + " mm"));
        std::vector<double> planes = {0.};
        for (const double zk : z)
          if (zk - planes.back() > tol)
            planes.push_back(zk);
        planes.back() = length;
        for (const auto &cell : coarse.active_cell_iterators())
          {
            std::set<unsigned int> on;
            for (const unsigned int v : cell->vertex_indices())
              on.insert(nearest_plane(planes, cell->vertex(v)[2]));
            if (on.size() != 2 || *on.rbegin() != *on.begin() + 1)
              return {axial_stations(coarse, length), false};
          }
        return {planes, true};
      }

      /// Distance [mm] of @p x from the half-plane through the axis at
      /// angle @p a (from the axis itself behind it).
      double
      distance_from_half_plane(const Point<dim> &x, const double a)
      {
        const double along = x[0] * std::cos(a) + x[1] * std::sin(a);
        return along >= 0 ? std::abs(x[0] * std::sin(a) - x[1] * std::cos(a))
                          : std::hypot(x[0], x[1]);
      }

      /// Distance [mm] of @p x from the surface of boundary id @p b.
      double
      distance_from_surface(const Parameters::AllParameters &parameters,
                            const double                     length,
                            const types::boundary_id         b,
                            const Point<dim>                &x)
      {
        const auto  &g = parameters.geometry;
        const double r = std::hypot(x[0], x[1]);
        switch (b)
          {
            case SliceIds::inner_arc:
              return std::abs(r - g.inner_radius);
            case SliceIds::outer_arc:
              return std::abs(r - g.outer_radius);
            case SliceIds::symmetry_edge:
              return distance_from_half_plane(x, 0.);
            case SliceIds::far_edge:
              return distance_from_half_plane(x, g.sector_angle);
            case SliceIds::near_face:
              return std::abs(x[2]);
            default:
              return std::abs(x[2] - length);
          }
      }

      /// Every boundary face carries one of the ids 0..5, each id is
      /// present, and its faces lie on the surface it names.
      void
      check_boundary_ids(const Parameters::AllParameters &parameters,
                         const Triangulation<dim>        &coarse,
                         const double                     length,
                         const std::string               &origin)
      {
        std::array<double, 6> worst = {{-1, -1, -1, -1, -1, -1}};
        for (const auto &face : coarse.active_face_iterators())
          if (face->at_boundary())
            {
              const types::boundary_id b = face->boundary_id();
              AssertThrow(b < worst.size(),
                          ExcMessage(origin + ": boundary id " +
                                     std::to_string(b) +
                                     " is not one of 0 (inner arc), 1 (outer "
                                     "arc), 2 (theta = 0), 3 (far edge), 4 "
                                     "(z = 0), 5 (far face)"));
              worst[b] = std::max(worst[b], 0.);
              for (const unsigned int v : face->vertex_indices())
                worst[b] = std::max(worst[b],
                                    distance_from_surface(
                                      parameters, length, b, face->vertex(v)));
            }
        for (unsigned int b = 0; b < worst.size(); ++b)
          AssertThrow(worst[b] >= 0,
                      ExcMessage(origin +
                                 ": the mesh has no boundary with id " +
                                 std::to_string(b) + " (" + id_names[b] + ")"));
        for (unsigned int b = 0; b < worst.size(); ++b)
          AssertThrow(worst[b] < 1e-6 * parameters.geometry.outer_radius,
                      ExcMessage(origin + ": faces with boundary id " +
                                 std::to_string(b) + " do not lie on the " +
                                 id_names[b] + " (off by " +
                                 Parameters::number(worst[b]) +
                                 " mm); faces in no physical surface get "
                                 "id 0"));
      }

      /// No cell of a layered cover straddles an interface.
      void
      check_layer_interfaces(const Parameters::AllParameters &parameters,
                             const Triangulation<dim>        &coarse,
                             const std::string               &origin)
      {
        const std::vector<double> radii = layer_radii(parameters);
        const double              tol = 1e-6 * parameters.geometry.outer_radius;
        for (const auto &cell : coarse.active_cell_iterators())
          {
            const Point<dim>   c = cell->center();
            const unsigned int j =
              layer_at_radius(radii, mean_vertex_radius(cell));
            for (const unsigned int v : cell->vertex_indices())
              {
                const double r =
                  std::hypot(cell->vertex(v)[0], cell->vertex(v)[1]);
                AssertThrow(r > radii[j] - tol && r < radii[j + 1] + tol,
                            ExcMessage(origin + ": the cell at " + at(c) +
                                       " straddles an interface of "
                                       "Material/Layer thicknesses"));
              }
          }
      }
    } // namespace

    AxialPlanes
    read_drawn_slice(const Parameters::AllParameters &parameters,
                     const double                     length,
                     Triangulation<dim>              &coarse)
    {
      const std::string &file   = parameters.mesh.mesh_file;
      const std::string  origin = "Mesh/Mesh file '" + file + "'";
      read_hexahedra(file, origin, coarse);
      const AxialPlanes planes = axial_layers(coarse, length, origin);
      check_boundary_ids(parameters, coarse, length, origin);
      check_layer_interfaces(parameters, coarse, origin);
      return planes;
    }

    bool
    is_drawn_slice(const Parameters::AllParameters &parameters)
    {
      return parameters.mesh.source == Parameters::MeshSource::gmsh &&
             gmsh_mesh_dimension(parameters.mesh.mesh_file) == 3;
    }
  } // namespace three_d
} // namespace rollnip
