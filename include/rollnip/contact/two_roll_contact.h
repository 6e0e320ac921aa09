#ifndef rollnip_contact_two_roll_contact_h
#define rollnip_contact_two_roll_contact_h

#include <rollnip/contact/counter_surface.h>
#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_solver.h>
#include <rollnip/problem.h>

#include <functional>
#include <memory>
#include <vector>

namespace rollnip
{
  /**
   * The nip of two covered rolls (Mating roll/Type = covered roll,
   * doc/two_rolls.md). Batra's inverse idea is kept for the first roll:
   * its reference half nip angle theta0 is the control and its contact
   * pressure the unknown. The two are coupled by an outer fixed-point
   * iteration on the mating roll's deformed surface:
   *  1. the first roll's contact iteration (InverseContact) makes its
   *     surface conform, over [0, theta0], to the mating roll's deformed
   *     surface (a DeformedRoll; at the start the current state);
   *  2. the mating roll is loaded by the same pressure at the same
   *     deformed points: the first roll's f at the point whose deformed
   *     x2 (along the common tangent) is the mating node's;
   *  3. its new deformed surface, relaxed with Aitken's factor (the first
   *     one G_mate / (G + G_mate), exact for two half-spaces), is the
   *     counter surface of the next pass,
   * until the surface moves less than Contact/Conformity tolerance times
   * the first roll's indentation. The indentation of the result is the
   * approach of the centres, the sum of both rolls' indentations.
   */
  class TwoRollContact : public NipSolver
  {
  public:
    /// The nip of @p roll, of the scene @p description, and the mating
    /// roll of @p mate_parameters (made by the scene builder, kept here
    /// for the mating roll's problem).
    TwoRollContact(ContactBody                     &roll,
                   const Parameters::AllParameters &parameters,
                   const SceneDescription          &description,
                   Parameters::AllParameters        mate_parameters);

    ContactResult
    solve(const double theta0) override;

    double
    max_nip_angle() override
    {
      return contact.max_nip_angle();
    }

    MPI_Comm
    communicator() const override
    {
      return contact.communicator();
    }

    const SceneDescription &
    scene() const override
    {
      return contact.scene();
    }

    /// The mating roll's files in @p directory/mating_roll.
    void
    write_results(const ContactResult &result,
                  const std::string   &directory,
                  const unsigned int   step,
                  const bool           with_vtu) override;

    const RollProblem &
    mating_roll() const
    {
      return mate;
    }

  private:
    /// The mating roll's description.
    const RollDescription &
    mate_description() const
    {
      return *contact.scene().covered_mate();
    }

    /// Deformed surface nodes of a roll in its own frame (reference
    /// position plus the displacement @p u the gap sees; none if empty).
    static std::vector<Point<dim>>
    deformed(const std::vector<SurfaceNode>    &nodes,
             const std::vector<Tensor<1, dim>> &u);

    /// The mating roll's deformed surface nodes.
    std::vector<Point<dim>>
    mate_shape() const;

    /// Loads the mating roll with the first roll's pressure of @p result,
    /// mapped by the deformed coordinate x2; "" on success, else why not.
    std::string
    load_mate(const ContactResult &result);

    /// Equilibrium of the mating roll, its indentation and the penetration
    /// of its surface into the first roll's, in @p result.
    void
    measure_mate(ContactResult &result) const;

    /// Fits the mating roll's mesh (if nip-fitted) to the estimate of its
    /// contact edge at the first roll's @p theta0 and collects its surface
    /// nodes; returns the unscaled estimate [rad].
    double
    fit_mate_to_estimate(const double theta0);

    /// Keeps the converged pair of @p result as the state to go back to,
    /// and how far the estimate was off.
    void
    keep_converged(ContactResult &result, const double estimate);

    /// Fits the mating roll's nip-fitted mesh to its reference angle
    /// @p angle [rad] (bounded by what the mesh takes) and collects its
    /// surface nodes again.
    void
    fit_mate_mesh(const double angle);

    /// Refits the mating roll's mesh so that a node lies on its contact
    /// edge (the mating point at the deformed x2 of the first roll's edge,
    /// found by load_mate) when the edge has moved off the fitted node;
    /// true if it did.
    bool
    refit_mate_mesh();

    /// Back to the last converged pair of states, @p roll_nip the roll's.
    void
    restore(const InverseContact::Converged &roll_nip);

    const Parameters::AllParameters     mate_parameters;
    ContactBody                        &roll;
    RollProblem                         mate;
    const std::shared_ptr<DeformedRoll> mate_surface;
    InverseContact                      contact;
    std::vector<SurfaceNode>            mate_nodes;
    /// The reference angle of the mating roll's contact edge, as loaded
    /// last, and the angle its mesh is fitted to [rad]; their ratio to the
    /// first estimate at the last converged nip starts the next one.
    double       mate_edge_angle = 0, mate_fit_angle = 0, mate_angle_factor = 1;
    double       mate_converged_fit_angle = 0;
    unsigned int mate_refits              = 0;
    /// The mating roll's pressure f(Theta_mate) of its current state.
    std::function<double(double)> mate_pressure;
    /// The mating roll's state and pressure of the last converged nip.
    TrilinosWrappers::MPI::Vector mate_converged;
    std::function<double(double)> mate_converged_pressure;
    ConditionalOStream            pcout;
  };
} // namespace rollnip

#endif
