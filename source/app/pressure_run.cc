#include <deal.II/base/mpi.h>

#include <rollnip/app/pressure_run.h>
#include <rollnip/contact/inverse_contact.h>
#include <rollnip/problem.h>
#include <rollnip/scene/scene_builder.h>

#include <iostream>
#include <memory>

namespace rollnip
{
  int
  validate_mesh(const Parameters::AllParameters &parameters,
                const std::string               &file,
                const MPI_Comm                   communicator)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    // Destroyed inside the handler when something throws, so that its
    // timer does not report on an exception still in flight.
    auto problem = std::make_unique<RollProblem>(parameters, communicator);
    try
      {
        problem->setup();
        // Prescribed nip angles on a mesh that does not move its nodes to
        // them: each must hold a contact zone, as the solve would check.
        const auto &c = parameters.contact;
        if (c.mode == Parameters::ContactMode::nip_angle &&
            !parameters.mating_roll.covered && !problem->has_nip_fitted_mesh())
          {
            const std::vector<SurfaceNode> nodes = problem->surface_nodes();
            for (const double theta0 : c.values)
              nodes_in_zone(nodes, theta0);
          }
      }
    catch (...)
      {
        problem->silence_timer();
        problem.reset();
        throw;
      }
    if (root)
      std::cout << "rollnip: '" << file << "' is valid" << std::endl;
    problem->silence_timer();
    return 0;
  }

  int
  run_pressure(const Parameters::AllParameters &parameters,
               const MPI_Comm                   communicator)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    // Destroyed inside the handler when something throws (see validate_mesh).
    auto scene = std::make_unique<Scene>(parameters, communicator);
    try
      {
        RollProblem &problem = scene->roll();
        RunStatus    status  = problem.run();
        problem.write_results(status);
        if (!status.converged)
          {
            if (root)
              std::cerr << "rollnip: error: " << status.message
                        << "; results of that state are in '"
                        << parameters.output.directory << "'" << std::endl;
            return 1;
          }
        return 0;
      }
    catch (...)
      {
        scene->silence_timers();
        scene.reset();
        throw;
      }
  }
} // namespace rollnip
