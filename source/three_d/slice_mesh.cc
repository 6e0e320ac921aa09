#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <rollnip/geometry/cover_layers.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/drawn_mesh.h>
#include <rollnip/three_d/slice_mesh.h>

#include <cmath>
#include <iostream>

namespace rollnip
{
  namespace three_d
  {
    std::vector<double>
    halved_steps(const std::vector<double> &steps, const unsigned int level)
    {
      std::vector<double> result;
      const unsigned int  n = 1u << level;
      for (const double s : steps)
        result.insert(result.end(), n, s / n);
      return result;
    }

    void
    refined_gmsh_cross_section(const Parameters::AllParameters &parameters,
                               const unsigned int               level,
                               Triangulation<2>                &flat)
    {
      Triangulation<2> section;
      read_gmsh_cross_section(parameters, section);
      section.set_all_manifold_ids(0);
      section.set_manifold(0, PolarManifold<2>(Point<2>()));
      section.refine_global(level);
      GridGenerator::flatten_triangulation(section, flat);
    }

    void
    bend_into_cylinder(Triangulation<dim> &body)
    {
      GridTools::transform(
        [](const Point<dim> &p) {
          return Point<dim>(p[0] * std::cos(p[1]), p[0] * std::sin(p[1]), p[2]);
        },
        body);
    }

    namespace
    {
      /// A drawn mesh brings its own layers: says so (on the root process)
      /// when Three d/Layers or Axial grading were set.
      void
      warn_ignored_layers(const unsigned int layers,
                          const double       axial_grading,
                          const std::string &file,
                          const MPI_Comm     communicator)
      {
        if ((layers != 1 || axial_grading != 1.) &&
            Utilities::MPI::this_mpi_process(communicator) == 0)
          std::cerr << "rollnip: warning: Three d/Layers and Three d/Axial "
                       "grading are ignored: the cells along the axis are "
                       "those of the 3D mesh in Mesh/Mesh file '"
                    << file << "'" << std::endl;
      }

      /// @p planes with the middle of every gap inserted.
      std::vector<double>
      halved_planes(const std::vector<double> &planes)
      {
        std::vector<double> result = {planes.front()};
        for (unsigned int j = 1; j < planes.size(); ++j)
          {
            result.push_back((planes[j - 1] + planes[j]) / 2.);
            result.push_back(planes[j]);
          }
        return result;
      }

      /// Every cell's material id: the cover layer (0 on the core) its
      /// mean vertex radius lies in. radial_steps() puts every
      /// interface on a cell boundary, so no cell straddles two layers.
      void
      set_slice_layer_ids(const Parameters::AllParameters &parameters,
                          Triangulation<dim>              &triangulation)
      {
        const std::vector<double> radii = layer_radii(parameters);
        for (const auto &cell : triangulation.active_cell_iterators())
          cell->set_material_id(
            layer_at_radius(radii, mean_vertex_radius(cell)));
      }

      /// The builtin sector annulus as an (r, theta, z) box bent into
      /// Cartesian coordinates; colorize gives ids 0..5 in the order of
      /// SliceIds.
      void
      make_builtin_slice(const Parameters::AllParameters &parameters,
                         const unsigned int               level,
                         const double                     thickness,
                         const std::vector<double>       &axial,
                         Triangulation<dim>              &coarse)
      {
        const auto                            &g     = parameters.geometry;
        const std::vector<std::vector<double>> steps = {
          halved_steps(radial_steps(parameters, parameters.mesh.radial_grading),
                       level),
          halved_steps(coarse_circumferential_steps(parameters), level),
          axial};
        GridGenerator::subdivided_hyper_rectangle(
          coarse,
          steps,
          Point<dim>(g.inner_radius, 0., 0.),
          Point<dim>(g.outer_radius, g.sector_angle, thickness),
          /*colorize=*/true);
        bend_into_cylinder(coarse);
      }

      /**
       * refined_gmsh_cross_section() extruded through the z of @p planes.
       * The side faces keep the 2D ids; z = 0 and z = L get SliceIds.
       */
      void
      make_gmsh_slice(const Parameters::AllParameters &parameters,
                      const unsigned int               level,
                      const std::vector<double>       &planes,
                      Triangulation<dim>              &coarse)
      {
        Triangulation<2> flat;
        refined_gmsh_cross_section(parameters, level, flat);
        GridGenerator::extrude_triangulation(flat, planes, coarse);
        const double tol = 1e-9 * planes.back();
        for (const auto &face : coarse.active_face_iterators())
          if (face->at_boundary())
            {
              const double z = face->center()[2];
              if (std::abs(z) < tol)
                face->set_boundary_id(SliceIds::near_face);
              else if (std::abs(z - planes.back()) < tol)
                face->set_boundary_id(SliceIds::far_face);
            }
      }
    } // namespace

    AxialPlanes
    make_slice_mesh(const Parameters::AllParameters           &parameters,
                    const unsigned int                         level,
                    const double                               thickness,
                    const unsigned int                         layers,
                    parallel::distributed::Triangulation<dim> &triangulation,
                    const double                               axial_grading)
    {
      Triangulation<dim> coarse;
      AxialPlanes planes = {axial_planes(thickness, layers, axial_grading),
                            true};
      const bool  gmsh = parameters.mesh.source == Parameters::MeshSource::gmsh;
      const bool  drawn = is_drawn_slice(parameters);
      if (drawn)
        {
          planes = read_drawn_slice(parameters, thickness, coarse);
          warn_ignored_layers(layers,
                              axial_grading,
                              parameters.mesh.mesh_file,
                              triangulation.get_communicator());
        }
      else if (gmsh)
        make_gmsh_slice(parameters, level, planes.z, coarse);
      else
        make_builtin_slice(parameters,
                           level,
                           thickness,
                           axial_steps(thickness, layers, axial_grading),
                           coarse);
      coarse.set_all_manifold_ids(0);
      set_slice_layer_ids(parameters, coarse);
      triangulation.copy_triangulation(coarse);
      Tensor<1, dim> axis;
      axis[2] = 1.;
      triangulation.set_manifold(0,
                                 CylindricalManifold<dim>(axis, Point<dim>()));
      if (drawn)
        {
          // A drawn body is refined as drawn: every cell halves in r, theta
          // and z, so the layers along the axis halve too.
          triangulation.refine_global(level);
          for (unsigned int k = 0; k < level; ++k)
            planes.z = halved_planes(planes.z);
        }
      return planes;
    }
  } // namespace three_d
} // namespace rollnip
