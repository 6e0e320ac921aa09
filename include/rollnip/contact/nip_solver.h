#ifndef rollnip_contact_nip_solver_h
#define rollnip_contact_nip_solver_h

#include <deal.II/base/mpi.h>

#include <rollnip/contact/contact_result.h>
#include <rollnip/scene/scene_description.h>

#include <optional>
#include <string>

namespace rollnip
{
  /**
   * What load and indentation control and the nip study need of a contact
   * solver: the nip of one reference half nip angle theta0 of the roll.
   * InverseContact solves it against a rigid counter surface,
   * TwoRollContact against a second covered roll.
   */
  class NipSolver
  {
  public:
    virtual ~NipSolver() = default;

    /// The target of load or indentation control while it iterates on
    /// theta0: a solver may then end a solve early, marked provisional,
    /// once the theta0 misses the target by far more than its conformity
    /// residual (the control leaves that theta0 anyway).
    struct ControlGoal
    {
      bool   by_load;   ///< P, else u0
      double target;    ///< [N/mm] or [mm]
      double tolerance; ///< Contact/Control tolerance (relative)
    };

    /// Sets (or with nullopt clears) the goal; ignored by solvers that
    /// always converge fully.
    virtual void
    set_control_goal(const std::optional<ControlGoal> &goal)
    {
      (void)goal;
    }

    /// The nip at the reference half nip angle @p theta0 [rad]. A nip that
    /// does not converge leaves the state of the last converged one.
    virtual ContactResult
    solve(const double theta0) = 0;

    /// The largest theta0 [rad] the roll's mesh takes.
    virtual double
    max_nip_angle() = 0;

    /// The processes that solve the nip (the roll's).
    virtual MPI_Comm
    communicator() const = 0;

    /// The scene whose nip this solver solves (its estimates start the
    /// control's iteration).
    virtual const SceneDescription &
    scene() const = 0;

    /// Writes what this solver adds to the roll's results of nip @p step in
    /// @p directory (collective); nothing for a rigid counter surface.
    virtual void
    write_results(const ContactResult &result,
                  const std::string   &directory,
                  const unsigned int   step,
                  const bool           with_vtu)
    {
      (void)result;
      (void)directory;
      (void)step;
      (void)with_vtu;
    }
  };
} // namespace rollnip

#endif
