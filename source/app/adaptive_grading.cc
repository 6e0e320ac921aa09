#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <rollnip/app/adaptive_grading.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/contact/nip_solver.h>
#include <rollnip/contact/two_roll_contact.h>
#include <rollnip/geometry/adaptive_grading.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/problem.h>
#include <rollnip/scene/scene_builder.h>

#include <algorithm>
#include <iomanip>
#include <memory>

namespace rollnip
{
  namespace
  {
    /// The coarse widths [rad] of both rolls after a grading pass; empty
    /// for a roll that this pass does not re-cut.
    struct GradedSteps
    {
      std::vector<double> roll, mate;
    };

    /// Whether pass @p pass re-cuts the cells of the roll of @p roll
    /// (the first roll's scene or the mating roll's): within its own
    /// Adaptive grading passes, on a builtin mesh that is not nip-fitted.
    bool
    grades(const Parameters::AllParameters &roll, const unsigned int pass)
    {
      return pass <= roll.mesh.adaptive_passes &&
             roll.mesh.source == Parameters::MeshSource::builtin &&
             !roll.nip_fitted_mesh();
    }

    /// Solves the scene of @p quiet (the pressure, or the first contact
    /// value on the scene's own nip solver, against a covered mating roll
    /// too), grading pass @p pass.
    void
    solve_pass(Scene                           &scene,
               const Parameters::AllParameters &quiet,
               const unsigned int               pass)
    {
      RollProblem &problem = scene.roll();
      problem.set_step_log(false);
      std::string failure;
      if (scene.has_nip_solver())
        {
          const ContactResult r = solve_controlled_nip(scene.nip_solver(),
                                                       quiet,
                                                       quiet.contact.values[0]);
          failure               = r.converged ? "" : r.message;
        }
      else
        {
          const RunStatus status = problem.run();
          failure                = status.converged ? "" : status.message;
        }
      AssertThrow(failure.empty(),
                  ExcMessage("Mesh/Adaptive grading passes: the solve of "
                             "pass " +
                             std::to_string(pass) + " failed: " + failure));
    }

    /// Solves the scene of @p quiet, grading pass @p pass, and returns the
    /// adapted coarse widths of each roll it re-cuts: the mating roll's
    /// from its own solved state in the two-roll nip.
    GradedSteps
    graded_pass(const Parameters::AllParameters &quiet,
                const unsigned int               pass,
                const MPI_Comm                   communicator)
    {
      // Destroyed inside the handler when something throws, so that its
      // timer does not report on an exception in flight.
      auto scene = std::make_unique<Scene>(quiet, communicator);
      try
        {
          solve_pass(*scene, quiet, pass);
          GradedSteps steps;
          if (grades(quiet, pass))
            steps.roll =
              adapted_circumferential_steps(scene->roll(),
                                            quiet.mesh.circumferential_steps,
                                            quiet.geometry.sector_angle);
          const Parameters::AllParameters mate = quiet.mating_roll_parameters();
          if (quiet.mating_roll.covered && grades(mate, pass))
            steps.mate = adapted_circumferential_steps(
              dynamic_cast<TwoRollContact &>(scene->nip_solver()).mating_roll(),
              mate.mesh.circumferential_steps,
              mate.geometry.sector_angle);
          scene->silence_timers();
          return steps;
        }
      catch (...)
        {
          scene->silence_timers();
          scene.reset();
          throw;
        }
    }

    /// The screen line of a pass that re-cut the cells @p w of @p which.
    void
    report(ConditionalOStream        &pcout,
           const unsigned int         pass,
           const std::string         &which,
           const std::vector<double> &w)
    {
      pcout << "Adaptive grading, pass " << pass << which
            << ": coarse cells from " << std::setprecision(3)
            << w.front() * 180 / numbers::PI
            << " deg at the line of centres to "
            << *std::max_element(w.begin(), w.end()) * 180 / numbers::PI
            << " deg (widest)" << std::endl;
    }
  } // namespace

  Parameters::AllParameters
  adapt_grading(const Parameters::AllParameters &parameters,
                const MPI_Comm                   communicator)
  {
    Parameters::AllParameters p = parameters;
    // Each roll's own entry counts its passes; every pass solves the
    // whole scene, both rolls.
    const unsigned int n_passes =
      std::max(p.mesh.adaptive_passes,
               p.mating_roll.covered ? p.mating_roll.mesh.adaptive_passes : 0u);
    if (n_passes == 0)
      return p;
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(communicator) ==
                               0);
    if (grades(p, 1))
      p.mesh.circumferential_steps = coarse_circumferential_steps(p);
    if (p.mating_roll.covered && grades(p.mating_roll_parameters(), 1))
      p.mating_roll.mesh.circumferential_steps =
        coarse_circumferential_steps(p.mating_roll_parameters());
    Parameters::AllParameters quiet = p;
    quiet.output.write_vtu          = false;
    quiet.output.write_csv          = false;
    quiet.output.print_timing       = false;
    quiet.contact.compare_linear    = false;
    for (unsigned int pass = 1; pass <= n_passes; ++pass)
      {
        quiet.mesh.circumferential_steps = p.mesh.circumferential_steps;
        quiet.mating_roll.mesh.circumferential_steps =
          p.mating_roll.mesh.circumferential_steps;
        const GradedSteps steps = graded_pass(quiet, pass, communicator);
        if (!steps.roll.empty())
          report(pcout, pass, "", p.mesh.circumferential_steps = steps.roll);
        if (!steps.mate.empty())
          report(pcout,
                 pass,
                 " (mating roll)",
                 p.mating_roll.mesh.circumferential_steps = steps.mate);
      }
    return p;
  }
} // namespace rollnip
