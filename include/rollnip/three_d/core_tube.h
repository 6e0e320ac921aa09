#ifndef rollnip_three_d_core_tube_h
#define rollnip_three_d_core_tube_h

#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <rollnip/material/material_law.h>
#include <rollnip/parameters.h>
#include <rollnip/three_d/slice_mesh.h>
#include <rollnip/three_d/three_d_parameters.h>

#include <memory>
#include <utility>
#include <vector>

/**
 * The elastic steel core (Three d/Core = elastic): a tube from Core inner
 * radius to R1 meshed with the cover (shared nodes at R1: the bond is
 * continuity), running beyond the cover end at z = Slice thickness to the
 * journal at z = Bearing distance, where its end section has u_x = u_y = 0
 * (a simple support: the section may rotate, u_z is free). A half cross-
 * section (180 deg sector, symmetry on both edges) bends as the full tube.
 */
namespace rollnip
{
  namespace three_d
  {
    class SliceBody;

    /// Boundary ids of the tube's surfaces beside SliceIds (which keep
    /// their meaning; inner_arc does not occur).
    namespace CoreIds
    {
      constexpr types::boundary_id bore = 6; ///< r = Core inner radius
      /// The tube's end section at z = Bearing distance.
      constexpr types::boundary_id journal = 7;
      /// The tube's outer surface r = R1 beyond the cover end.
      constexpr types::boundary_id bare_core = 8;
    } // namespace CoreIds

    /// Throws a one-line message naming the entry if the elastic core does
    /// not fit the scene (a mesh drawn in 3D, radii, bearing, sector,
    /// boundary conditions).
    void
    check_elastic_core(const Parameters::AllParameters &parameters,
                       const Parameters::ThreeD        &three_d);

    /**
     * The cover of make_slice_mesh() on the tube: the tube's radial cells
     * (two coarse cells, halved @p level times) inside R1, the cover's
     * axial layers over the face and cells of the mean layer thickness on
     * to the bearing, the cover's cells beyond the face removed. The
     * cover's cross-section is the builtin one or, with Mesh/Source =
     * gmsh, the quadrilaterals of Mesh/Mesh file refined in their polar
     * chart; the tube's rings then run through the bond's own nodes, so
     * tube and cover share them. Material ids: the cover layers 0, 1, ...
     * and the core n_layers; boundary ids from where each face lies.
     */
    void
    make_core_tube_mesh(const Parameters::AllParameters           &parameters,
                        const Parameters::ThreeD                  &three_d,
                        const unsigned int                         level,
                        parallel::distributed::Triangulation<dim> &tria);

    /// The steel's law: compressible neo-Hooke with G = E / (2 (1 + nu)),
    /// Hooke's law at small strain.
    std::unique_ptr<MaterialLaw<dim>>
    make_core_law(const Parameters::ThreeD &three_d);

    /// The core's deflection v(z) [mm], positive away from the nip (as
    /// Core deflection): minus the bore's u_x averaged over the half circle
    /// (trapezoidal in theta, so the ovalisation cancels) at every plane of
    /// nodes from z = 0 to the bearing.
    std::vector<std::pair<double, double>>
    core_deflection_profile(const SliceBody &body);
  } // namespace three_d
} // namespace rollnip

#endif
