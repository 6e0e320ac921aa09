#ifndef rollnip_contact_inverse_contact_h
#define rollnip_contact_inverse_contact_h

#include <rollnip/contact/contact_body.h>
#include <rollnip/contact/counter_surface.h>
#include <rollnip/contact/nip_solver.h>
#include <rollnip/contact/surface_nodes.h>
#include <rollnip/parameters.h>

#include <Eigen/Dense>

#include <functional>
#include <memory>
#include <vector>

namespace rollnip
{
  /**
   * Batra's inverse contact iteration (doc/intro.md, section 7): for a
   * prescribed reference half nip angle theta0, find the follower pressure
   * f(Theta) on [0, theta0], f(theta0) = 0, such that the deformed surface
   * lies on the indenter on the whole zone. f is piecewise linear between
   * the outer-surface nodes in [0, theta0) and theta0; its nodal values are
   * the unknowns. The equations are zero gaps at those nodes (but the one
   * on the line of centres, which defines u0) and at theta0 itself. Newton
   * on the values: the gap sensitivities come from linearised solves with
   * the tangent that Newton factorised last on the way to the converged
   * state (one or two Newton updates from it); the small dense system is solved
   * with Eigen.
   */
  class InverseContact : public NipSolver
  {
  public:
    /// Against the rigid circle or plane of Contact/Indenter radius; a
    /// scene with a covered mating roll is refused (its solver is
    /// TwoRollContact, built by the scene builder).
    InverseContact(ContactBody                     &body,
                   const Parameters::AllParameters &parameters);

    /// Against @p counter_surface of the scene @p description, which its
    /// owner may reshape between solves (the deformed surface of a mating
    /// roll).
    InverseContact(ContactBody                          &body,
                   const Parameters::AllParameters      &parameters,
                   const SceneDescription               &description,
                   std::shared_ptr<const CounterSurface> counter_surface);

    ContactResult
    solve(const double theta0) override;

    void
    set_control_goal(const std::optional<ControlGoal> &goal) override
    {
      control_goal = goal;
    }

    /// Half the sector on the nip-fitted mesh, else the angle of the third
    /// surface node from the end.
    double
    max_nip_angle() override;

    MPI_Comm
    communicator() const override
    {
      return body.communicator();
    }

    const SceneDescription &
    scene() const override
    {
      return description;
    }

    /// The state, pressure and theta0 of a converged nip.
    struct Converged
    {
      TrilinosWrappers::MPI::Vector state;
      std::function<double(double)> pressure; ///< empty: none yet
      double                        theta0 = 0;
    };

    /// The last converged nip.
    const Converged &
    last_converged() const
    {
      return converged;
    }

    /// Back to @p nip, which becomes the last converged one (an outer
    /// iteration that failed after this one converged).
    void
    restore_converged(const Converged &nip);

    /// The last converged nip of @p other, the same scene on a nested mesh
    /// of another level or element, as this one's last converged nip: its
    /// displacement carried over (transfer_nested_displacement()), its
    /// pressure and theta0. The next solve then starts from it instead of
    /// from the unloaded cover. Returns false, and changes nothing, where
    /// @p other has no converged nip or the meshes do not nest.
    bool
    start_from(const InverseContact &other);

    /// The conformity tolerance of its iteration, a fraction of u0.
    double
    tolerance() const
    {
      return conformity_tolerance;
    }

    /// The pressure f(Theta) [MPa] of the current state (empty before the
    /// first solve).
    const std::function<double(double)> &
    pressure() const
    {
      return applied_pressure;
    }

    /// The outer-surface nodes of the last solve.
    const std::vector<SurfaceNode> &
    surface_nodes() const
    {
      return nodes;
    }

    /// The displacements of the current state at surface_nodes(), as the
    /// gap sees them (the normal part only in linear theory).
    std::vector<Tensor<1, dim>>
    surface_displacements() const
    {
      return nodal_values(body.current_solution());
    }

  private:
    /// The contact zone of one theta0 on the surface nodes: the knots of
    /// the pressure, the nodes around the edge and the weights of the
    /// edge row of the equations.
    struct Zone
    {
      double              theta0;
      std::vector<double> knots;          ///< nodes below theta0, then theta0
      unsigned int        m;              ///< pressure parameters (= equations)
      unsigned int        left, above, B; ///< nodes about the edge
      double              weight;         ///< theta0 between left and above
      double              c_A, c_B;       ///< edge-row weights
    };

    /// The pressure parameters of the iteration and its damping memory.
    struct Iterate
    {
      std::vector<double>           a;      ///< f at the knots [MPa]
      std::vector<double>           f_from; ///< f of the current state
      TrilinosWrappers::MPI::Vector accepted_state;
      std::function<double(double)> accepted_pressure;
      std::vector<double>           accepted_a;
      double                        accepted_residual;
      unsigned int                  halvings = 0;
    };

    /// The gaps of one solved pressure, scaled by u0 (eq. 7.2).
    struct Gaps
    {
      std::vector<double>     g;
      std::vector<Point<dim>> x; ///< deformed surface nodes
      double                  u0, residual, conformity;
    };

    /// The outer-surface nodes, ordered by angle, identical on all ranks.
    void
    collect_surface_nodes();

    /// u at all surface nodes of a distributed vector (on all ranks); in
    /// linear theory only its normal part, which alone enters the gap.
    std::vector<Tensor<1, dim>>
    nodal_values(const TrilinosWrappers::MPI::Vector &v) const;

    /// Fits the mesh, collects the nodes and lays out the zone of theta0.
    Zone
    make_zone(const double theta0);

    /// The first pressure: the last one stretched to the new zone and
    /// scaled by pressure_growth(), or a Hertz-like parabola.
    void
    initial_pressure(const Zone &zone, Iterate &iterate) const;

    /// Solves the cover under the pressure iterate.a, ramping from the
    /// current one and retrying closer to it if that fails; "" on success,
    /// else why not.
    std::string
    carry_pressure(const Zone &zone, Iterate &iterate, const unsigned int it);

    /// The gaps of the current state and the results they give.
    Gaps
    measure_gaps(const Zone &zone, ContactResult &result) const;

    /// Takes back and halves an update whose residual grew; "" if the
    /// iteration goes on, else why it stops.
    std::string
    damp(const Zone &zone, const Gaps &gaps, Iterate &iterate, bool &retry);

    /// d(gaps)/d(a): one linearised solve per knot with the last Newton
    /// factorisation.
    Eigen::MatrixXd
    sensitivities(const Zone &zone, const Gaps &gaps);

    /// Whether the iterate of @p result (conformity residual @p residual)
    /// misses the control goal by so much more than that residual that
    /// converging it further would not move the control's next theta0.
    bool
    far_from_goal(const ContactResult &result, const double residual) const;

    /// The first lines of the iteration's screen log.
    void
    print_header(const Zone &zone) const;

    /// The checks of a converged nip (pressure sign, penetration) and the
    /// restore of a failed one.
    void
    finish(const Zone &zone, ContactResult &result);

    /// d log(peak pressure) / d log theta0 along the nips solved so far,
    /// or 1 (Hertz) before two of them.
    double
    pressure_growth() const;

    ContactBody                                &body;
    const Parameters::AllParameters            &parameters;
    const SceneDescription                      description;
    const std::shared_ptr<const CounterSurface> counter_surface;
    std::vector<SurfaceNode>                    nodes;
    ConditionalOStream                          pcout;
    /// Contact/Conformity tolerance, and under load or indentation control
    /// at most a fraction of Contact/Control tolerance: the nip's P and u0
    /// carry the conformity error, and the control must see past it.
    const double conformity_tolerance;
    /// The pressure of the body's current state (empty before the
    /// first solve) and its theta0: the next solve starts from them.
    std::function<double(double)> applied_pressure;
    double                        applied_theta0 = 0;
    /// The last converged nip.
    Converged converged;
    /// theta0 and peak pressure of a converged nip.
    struct NipSize
    {
      double theta0 = 0, peak = 0;
    };
    /// The last converged nip and the last one before it at another
    /// theta0: how the pressure grows with theta0 between them.
    NipSize last_nip, nip_before;
    /// Set by load or indentation control while it iterates.
    std::optional<ControlGoal> control_goal;
  };

  /// The outer-surface nodes @p nodes (by angle) below @p theta0 [rad],
  /// the zone's pressure parameters; throws where theta0 leaves fewer than
  /// two, or reaches the end of the arc (what a solve at theta0 refuses).
  unsigned int
  nodes_in_zone(const std::vector<SurfaceNode> &nodes, const double theta0);

  /// contact.txt (scalars and checks, then the lines @p more) and
  /// contact_pressure.csv (f at the knots) in @p directory, written by
  /// rank 0.
  void
  write_contact_results(const ContactResult &result,
                        const std::string   &directory,
                        const std::string   &more = "");
} // namespace rollnip

#endif
