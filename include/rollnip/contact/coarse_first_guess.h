#ifndef rollnip_contact_coarse_first_guess_h
#define rollnip_contact_coarse_first_guess_h

#include <rollnip/parameters.h>

#include <mpi.h>

#include <memory>
#include <string>

namespace rollnip
{
  class Scene;

  /**
   * The first theta0 of a cold load or indentation target from the same
   * scene at mesh level 0 (both rolls' meshes there): its nip-angle solves cost
   * a few milliseconds, and its P(theta0) or u0(theta0) differs from the fine
   * mesh's by the discretisation error only, a few per cent at most, where
   * a closed-form law (Hertz, thin layer) misses a bonded layer of finite
   * thickness by tens of per cent.
   */
  struct CoarseFirstGuess
  {
    double theta = 0; ///< [rad], 0 if the coarse nip did not converge
    double slope = 0; ///< d log q / d log theta0 there, 0 if unknown
    /// d^2 log theta0 / d (log q)^2 of its converged nips, 0 if unknown
    double       curvature = 0;
    unsigned int n_solves  = 0; ///< contact solves on the coarse mesh
    double       seconds   = 0; ///< wall time, set-up included
    std::string  failure;       ///< why there is no guess, if there is none
    /// The largest q (P [N/mm] or u0 [mm]) of a coarse nip that converged
    /// and its theta0 [rad]; 0 if none did.
    double largest_reached = 0, largest_reached_theta = 0;
    /// The level-0 scene, its last converged nip the guess's (null where
    /// there is no guess): the fine mesh's first solve starts from its
    /// state (InverseContact::start_from()).
    std::shared_ptr<Scene> scene;
  };

  /// Whether the scene has a coarser level than its own to calibrate on
  /// (above level 0), a load or indentation control, and a rigid indenter
  /// or a single target (Contact/Values) against a covered mating roll.
  bool
  coarse_first_guess_pays(const Parameters::AllParameters &p);

  /// Solves @p target (P [N/mm] or u0 [mm]) on the scene @p p at mesh
  /// level 0, quietly, on the processes of @p comm. A coarse nip that
  /// fails or cannot be built leaves theta = 0 and says why; an error of
  /// one process only (memory, files) is thrown on.
  CoarseFirstGuess
  coarse_first_guess(const Parameters::AllParameters &p,
                     const double                     target,
                     const MPI_Comm                   comm);
} // namespace rollnip

#endif
