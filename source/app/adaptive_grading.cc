#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <rollnip/app/adaptive_grading.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/contact/nip_solver.h>
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
    /// Solves the scene of @p quiet, grading pass @p pass (the pressure,
    /// or the first contact value on the scene's own nip solver, against
    /// a covered mating roll too), and returns its adapted coarse widths.
    std::vector<double>
    graded_pass(const Parameters::AllParameters &quiet,
                const unsigned int               pass,
                const MPI_Comm                   communicator)
    {
      // Destroyed inside the handler when something throws, so that its
      // timer does not report on an exception in flight.
      auto scene = std::make_unique<Scene>(quiet, communicator);
      try
        {
          RollProblem &problem = scene->roll();
          problem.set_step_log(false);
          std::string failure;
          if (scene->has_nip_solver())
            {
              const ContactResult r =
                solve_controlled_nip(scene->nip_solver(),
                                     quiet,
                                     quiet.contact.values[0]);
              failure = r.converged ? "" : r.message;
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
          const std::vector<double> steps =
            adapted_circumferential_steps(problem,
                                          quiet.mesh.circumferential_steps,
                                          quiet.geometry.sector_angle);
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
  } // namespace

  Parameters::AllParameters
  adapt_grading(const Parameters::AllParameters &parameters,
                const MPI_Comm                   communicator)
  {
    Parameters::AllParameters p = parameters;
    if (parameters.mesh.adaptive_passes == 0 ||
        parameters.mesh.source != Parameters::MeshSource::builtin)
      return p;
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(communicator) ==
                               0);
    p.mesh.circumferential_steps    = coarse_circumferential_steps(p);
    Parameters::AllParameters quiet = p;
    quiet.output.write_vtu          = false;
    quiet.output.write_csv          = false;
    quiet.output.print_timing       = false;
    quiet.contact.compare_linear    = false;
    for (unsigned int pass = 1; pass <= parameters.mesh.adaptive_passes; ++pass)
      {
        quiet.mesh.circumferential_steps = p.mesh.circumferential_steps;
        p.mesh.circumferential_steps = graded_pass(quiet, pass, communicator);
        const auto &w                = p.mesh.circumferential_steps;
        pcout << "Adaptive grading, pass " << pass << ": coarse cells from "
              << std::setprecision(3) << w.front() * 180 / numbers::PI
              << " deg at the line of centres to "
              << *std::max_element(w.begin(), w.end()) * 180 / numbers::PI
              << " deg (widest)" << std::endl;
      }
    return p;
  }
} // namespace rollnip
