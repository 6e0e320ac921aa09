#ifndef rollnip_face_face_solver_h
#define rollnip_face_face_solver_h

#include <rollnip/face/beam.h>
#include <rollnip/face/foundation_law.h>

#include <Eigen/Dense>

#include <array>
#include <functional>

/**
 * The nonlinear face problem (doc/face.md): the roll's core and, if it
 * bends, the mating roll's as beams simply supported at their bearings,
 * coupled along the face by the foundation q = P(delta) with the local
 * approach delta(y) = a - w_roll(y) - w_mate(y) + crown(y); the bearing
 * approach a is an unknown held by the total nip force.
 */
namespace rollnip
{
  namespace Face
  {
    /// Everything solve_face() needs. Deflections w are positive away from
    /// the nip for both rolls.
    struct FaceModel
    {
      double       face_length;      ///< L [mm]
      double       bearing_distance; ///< B >= L [mm]
      unsigned int elements;         ///< beam elements on the face
      BeamSection  roll;
      bool         mate_is_beam = false;
      BeamSection  mate;
      /// Line loads along w on the whole beams [N/mm] (the own weight:
      /// negative for the roll on top, positive for the one below).
      double roll_beam_load = 0, mate_beam_load = 0;
      /// Both crowns' radius change at y [mm]; empty: none.
      std::function<double(double)> crown;
      double                        total_force; ///< the nip's [N]
      const FoundationLaw          *law = nullptr;
      /// l of the non-local foundation q - l^2 q'' = P(delta) [mm]; 0:
      /// the local q = P(delta).
      double nonlocal_length = 0;
    };

    /// The converged face.
    struct FaceSolution
    {
      FaceSolution(const FaceModel &model);

      const FaceModel *model;
      FaceMesh         mesh;
      Eigen::VectorXd  roll, mate; ///< nodal (w, theta) of each beam
      double           approach   = 0;
      unsigned int     iterations = 0;
      /// The beams' forces on their bearings (left, right) [N], positive
      /// away from the nip.
      std::array<double, 2> roll_bearings{{0, 0}}, mate_bearings{{0, 0}};
      /// The line load at the face nodes (the non-local one if asked)
      /// [N/mm].
      Eigen::VectorXd nodal_line_load;

      double
      roll_deflection(const double y) const;
      double
      mate_deflection(const double y) const;
      double
      crown(const double y) const;
      /// delta(y) [mm].
      double
      approach_at(const double y) const;
      /// q(y) [N/mm]: P(delta(y)), or the non-local q at the nodes
      /// interpolated linearly.
      double
      line_load(const double y) const;
    };

    /// Newton on the beams' dofs and the approach with a line search on
    /// the energy's slope; throws if it does not converge.
    FaceSolution
    solve_face(const FaceModel &model);
  } // namespace Face
} // namespace rollnip

#endif
