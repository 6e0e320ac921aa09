#ifndef rollnip_face_face_parameters_h
#define rollnip_face_face_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/global.h>

#include <string>

/**
 * The parameters of the face model (subsection Face, doc/face.md): the
 * rolls' cores as beams along the face, their crowns, the loading and the
 * foundation that couples them, the cross-section's own nip law.
 */
namespace rollnip
{
  namespace Parameters
  {
    /// One roll's core along the face: a tube (or a solid shaft).
    struct FaceCore
    {
      double outer_diameter; ///< [mm]
      double inner_diameter; ///< [mm]; 0: solid
      double youngs_modulus; ///< [MPa]
      double poisson_ratio;
      double density; ///< [kg/m^3], for the own weight

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    enum class CrownShape
    {
      none,
      parabolic,
      sine,
      circular,
      ideal, ///< the deflection under the design load (computed)
      table  ///< (y, change) read from a CSV file
    };

    /// One roll's crown: the change of its radius along the face, zero at
    /// the face ends.
    struct FaceCrown
    {
      CrownShape  shape;
      double      amount; ///< at the centre [mm], on the diameter or radius
      bool        on_diameter; ///< amounts and table values are diameters
      std::string table_file;
      /// Mean line load the ideal crown is designed for [N/mm]; 0: the
      /// face's own load.
      double design_line_load;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    enum class FaceLoading
    {
      mean_line_load,
      bearing_forces
    };

    enum class FaceFoundation
    {
      cross_section, ///< the scene's own nip law P_2D(u0)
      linear         ///< q = k delta
    };

    struct Face
    {
      bool           enabled;
      double         face_length;      ///< [mm]
      double         bearing_distance; ///< between the journals [mm]
      FaceLoading    loading;
      double         mean_line_load; ///< [N/mm]
      double         bearing_force;  ///< per bearing [N]
      bool           own_weight;
      bool           shear_deformation; ///< Timoshenko (true) or Euler
      unsigned int   elements;          ///< beam elements along the face
      FaceFoundation foundation;
      double         foundation_stiffness; ///< k [N/mm^2]
      unsigned int   law_samples;
      double         law_maximum_approach; ///< [mm]; 0: estimated
      double         law_range;            ///< largest over smallest u0
      std::string    law_cache_directory;  ///< empty: Output/Directory
      bool           nonlocal;             ///< q - l^2 q'' = P_2D
      double         nonlocal_factor;      ///< l over the nip half-width
      double         surface_speed;        ///< [m/min]; 0: no dwell
      bool           mate_is_beam;         ///< else rigid and straight
      FaceCore       roll_core, mate_core;
      FaceCrown      roll_crown, mate_crown;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
      /// Relations the patterns cannot check; throws naming the entry.
      void
      validate() const;
    };
  } // namespace Parameters
} // namespace rollnip

#endif
