#ifndef rollnip_contact_contact_body_h
#define rollnip_contact_contact_body_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/contact/surface_nodes.h>
#include <rollnip/loading/follower_load.h>
#include <rollnip/solvers/load_stepper.h>

#include <functional>
#include <vector>

namespace rollnip
{
  /**
   * What the contact iterations (InverseContact, TwoRollContact) need of a
   * deformable roll, and nothing more: its state, its outer surface, the
   * follower pressure and the solve that carries it, the load resultant,
   * the linearisation at the current state, and the nip-fitted mesh.
   * RollProblem implements it.
   */
  class ContactBody
  {
  public:
    virtual ~ContactBody() = default;

    /// The state (displacement and pressure unknowns): readable at every
    /// locally relevant dof, its locally owned part, and a new one.
    virtual const TrilinosWrappers::MPI::Vector &
    current_solution() const = 0;
    virtual const TrilinosWrappers::MPI::Vector &
    owned_solution() const = 0;
    virtual void
    set_solution(const TrilinosWrappers::MPI::Vector &owned) = 0;
    virtual const IndexSet &
    locally_owned() const = 0;

    /// The vertices of the outer arc, ordered by angle, on all ranks.
    virtual std::vector<SurfaceNode>
    surface_nodes() const = 0;

    /// The follower pressure f(Theta, lambda) [MPa], and the solve that
    /// ramps lambda to 1 (from the current state if asked; it never throws
    /// for a load it cannot carry but says so in the status).
    virtual void
    set_pressure(FollowerLoad::Pressure pressure) = 0;
    virtual RunStatus
    run(const bool   from_current_state = false,
        const double first_increment    = 0) = 0;
    /// The resultant of the applied load at @p load_fraction [N/mm].
    virtual Tensor<1, dim>
    load_resultant(const double load_fraction) const = 0;

    /// The linearisation at the current state: assemble, factorise the
    /// tangent, d R / d s for an extra pressure s g(Theta), K x = rhs
    /// for several right-hand sides at once.
    virtual double
    assemble(const double load_fraction, const bool with_matrix) = 0;
    virtual void
    factorize_tangent() = 0;
    virtual TrilinosWrappers::MPI::Vector
    pressure_load_derivative(const std::function<double(double)> &g) const = 0;
    virtual void
    solve_with_tangent(const std::vector<TrilinosWrappers::MPI::Vector> &rhs,
                       std::vector<TrilinosWrappers::MPI::Vector>       &x) = 0;

    /// The nip-fitted mesh, if the body has one.
    virtual bool
    has_nip_fitted_mesh() const = 0;
    virtual void
    fit_mesh_to_nip(const double theta0) = 0;
    virtual double
    max_nip_angle() const = 0;
    virtual MeshQuality
    cell_quality() const = 0;

    /// Whether each solve logs its load steps (off inside iterations).
    virtual void
    set_step_log(const bool on) = 0;

    /// The processes that hold the body: every collective call of the
    /// contact iteration runs on them.
    virtual MPI_Comm
    communicator() const = 0;
  };
} // namespace rollnip

#endif
