#include <rollnip/contact/counter_surface.h>
#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/two_roll_contact.h>
#include <rollnip/problem.h>
#include <rollnip/scene/scene_builder.h>

namespace rollnip
{
  namespace
  {
    /// The nip solver of @p description for @p roll: against
    /// @p counter_surface, or against the covered mating roll.
    std::unique_ptr<NipSolver>
    nip_solver_of(RollProblem                                 &roll,
                  const Parameters::AllParameters             &parameters,
                  const SceneDescription                      &description,
                  const std::shared_ptr<const CounterSurface> &counter_surface)
    {
      if (description.covered_mate())
        return std::make_unique<TwoRollContact>(
          roll, parameters, description, parameters.mating_roll_parameters());
      return std::make_unique<InverseContact>(roll,
                                              parameters,
                                              description,
                                              counter_surface);
    }
  } // namespace

  Scene::Scene(const Parameters::AllParameters &parameters,
               MPI_Comm                         communicator)
      : description(describe_scene(parameters))
  {
    try
      {
        roll_problem = std::make_unique<RollProblem>(parameters, communicator);
        roll_problem->setup();
        if (parameters.contact.mode == Parameters::ContactMode::none)
          return;
        if (!description.covered_mate())
          counter_surface = make_counter_surface(description);
        solver = nip_solver_of(*roll_problem,
                               parameters,
                               description,
                               counter_surface);
      }
    catch (...)
      {
        silence_timers();
        solver.reset();
        roll_problem.reset();
        throw;
      }
  }

  Scene::~Scene() = default;

  NipSolver &
  Scene::nip_solver()
  {
    Assert(solver, ExcMessage("a scene without contact has no nip solver"));
    return *solver;
  }

  void
  Scene::silence_timers()
  {
    if (roll_problem)
      roll_problem->silence_timer();
  }
} // namespace rollnip
