#ifndef rollnip_scene_scene_builder_h
#define rollnip_scene_scene_builder_h

#include <deal.II/base/mpi.h>

#include <rollnip/parameters.h>
#include <rollnip/scene/scene_description.h>

#include <memory>

namespace rollnip
{
  class CounterSurface;
  class NipSolver;
  class RollProblem;

  /**
   * The objects of one run, built here and nowhere else from the scene
   * description of one parameter set: the roll (set up) and, for a contact
   * scene, its counter surface and nip solver: InverseContact against the
   * rigid circle or plane, TwoRollContact against the covered mating roll,
   * whose parameters are made here. Every kind of run builds its scenes
   * with it: the pressure run, the nip sweep with its linear and
   * error-estimate companions, the refinement study, the adaptive grading.
   */
  class Scene
  {
  public:
    /// The scene of @p parameters, which must outlive it, on the processes
    /// of @p communicator.
    Scene(const Parameters::AllParameters &parameters, MPI_Comm communicator);

    ~Scene();

    /// What the scene is, as built.
    const SceneDescription description;

    RollProblem &
    roll()
    {
      return *roll_problem;
    }

    const RollProblem &
    roll() const
    {
      return *roll_problem;
    }

    /// Whether this is a contact scene (Contact/Mode), with a nip solver.
    bool
    has_nip_solver() const
    {
      return static_cast<bool>(solver);
    }

    /// The nip solver of a contact scene.
    NipSolver &
    nip_solver();

    /// The rigid counter surface (circle or plane) of a contact scene;
    /// nullptr against a covered mating roll or without contact.
    const CounterSurface *
    rigid_counter_surface() const
    {
      return counter_surface.get();
    }

    /// Turns the timers of the scene's problems off, so that they do not
    /// report on an exception in flight.
    void
    silence_timers();

  private:
    std::unique_ptr<RollProblem>          roll_problem;
    std::shared_ptr<const CounterSurface> counter_surface;
    std::unique_ptr<NipSolver>            solver;
  };
} // namespace rollnip

#endif
