#ifndef rollnip_three_d_three_d_parameters_h
#define rollnip_three_d_three_d_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/global.h>

#include <string>

/**
 * The parameters of the 3D body (subsection Three d, doc/three_d.md): the
 * builtin sector annulus of Geometry and Mesh extruded along the face into
 * a slice, pressed by the rigid indenter of Contact at the approaches of
 * Contact/Values (Mode = indentation) through an active set.
 */
namespace rollnip
{
  namespace Parameters
  {
    struct ThreeD
    {
      bool         enabled;
      double       slice_thickness; ///< [mm], along the roll axis
      unsigned int layers;          ///< cells through the thickness
      /// u_z = 0 on z = L too (plane-strain slice); false: z = L is free.
      bool         fix_far_face;
      double       approach_step; ///< largest u0 increment per load step [mm]
      unsigned int max_newton_iterations;
      /// Thickness of the first layer (z = 0) over the last (z = L), >= 1:
      /// layers thinning geometrically towards the (free) far face.
      double axial_grading = 1.;

      /// The rigid core's bending line v(z) [mm], away from the nip: a
      /// muparser expression in z [mm] (three_d/core_deflection.h).
      std::string core_deflection;

      /// Three d/Core = elastic: a steel tube meshed with the cover and
      /// supported at its journals (core_tube.h); false: the rigid core.
      bool   elastic_core        = false;
      double core_inner_radius   = 0;     ///< [mm]
      double core_youngs_modulus = 210e3; ///< [MPa]
      double core_poisson_ratio  = 0.3;
      /// The journal's distance from the middle of the face, z = 0 [mm].
      double bearing_distance = 0;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace rollnip

#endif
