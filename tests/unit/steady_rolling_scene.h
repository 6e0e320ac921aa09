#ifndef rollnip_tests_steady_rolling_scene_h
#define rollnip_tests_steady_rolling_scene_h

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/problem.h>
#include <rollnip/rolling/steady_rolling.h>

#include <string>

#include "test_tools.h"

/**
 * The whole-circle scene the full steady-rolling tests share: the run-30
 * cover, one Prony term, the mesh whose energy balance closes to 1 %;
 * and the symmetric (half-model) nip they start from.
 */
namespace rollnip
{
  namespace testing
  {
    constexpr double rolling_R0 = 60.7, rolling_R1 = 47.2; // cover radii [mm]
    constexpr double rolling_Rbar = 76.2; // rigid indenter radius [mm]
    constexpr double rolling_g = 1., rolling_tau = 1e-4; // one-term SLS

    /// The cover of @p material between R1 and R0 against the rigid
    /// indenter, the Prony term (g, tau [s]), 100 fine cells over 2.5 times
    /// the nip half-angle @p theta0 [rad] each side of the nip, 16 radial
    /// cells graded 0.3.
    inline SteadyRollingScene
    steady_rolling_scene(const Parameters::Material &material,
                         const double                theta0)
    {
      SteadyRollingScene s;
      s.material               = material;
      s.viscous                = {{{rolling_g}, {rolling_tau}}};
      s.indenter_radius        = rolling_Rbar;
      s.layout.layer_radii     = {rolling_R1, rolling_R0};
      s.layout.fine_half_angle = 2.5 * theta0;
      s.layout.fine_cells      = 100;
      s.layout.radial_cells    = 16;
      s.layout.radial_grading  = 0.3;
      return s;
    }

    /// The run-30 cover at mesh level @p level, with the cover material
    /// of @p material (.prm lines; default: run 30's), against the rigid
    /// indenter at the half nip angle 3 deg: the nip the rolling tests
    /// start from.
    inline Parameters::AllParameters
    rolling_nip_parameters(const unsigned int level,
                           const std::string &material = "")
    {
      return parameters_from_string(
        "subsection Geometry\n set Inner radius = 47.2\n set Outer radius = "
        "60.7\nend\nsubsection Mesh\n set Global refinements = " +
        std::to_string(level) + "\nend\n" + material +
        "subsection Contact\n set Mode = nip angle\n set Values = 3\n set "
        "Indenter radius = 76.2\nend\n");
    }

    /// The symmetric (half-model) solver's nip of @p parameters at
    /// @p theta0 [rad].
    inline ContactResult
    symmetric_nip(const Parameters::AllParameters &parameters,
                  const double                     theta0)
    {
      RollProblem problem(parameters, MPI_COMM_WORLD);
      problem.setup();
      InverseContact contact(problem, parameters);
      return contact.solve(theta0);
    }
  } // namespace testing
} // namespace rollnip

#endif
