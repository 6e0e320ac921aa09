#ifndef rollnip_rolling_steady_rolling_h
#define rollnip_rolling_steady_rolling_h

#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <rollnip/material/material_law.h>
#include <rollnip/parameters.h>
#include <rollnip/rolling/annulus_mesh.h>
#include <rollnip/rolling/cover_circles.h>
#include <rollnip/rolling/first_order_loss.h>
#include <rollnip/rolling/periodic_relaxation.h>
#include <rollnip/rolling/rolling_parameters.h>

#include <map>
#include <memory>
#include <set>
#include <vector>

namespace rollnip
{
  /// What the full steady rolling needs of a scene: the cover's layers
  /// (long-term Mooney-Rivlin law and theory), their Prony branches, the
  /// mesh and the rigid mating roll.
  struct SteadyRollingScene
  {
    Parameters::Material                  material;
    std::vector<Parameters::ViscousLayer> viscous; ///< one, or one per layer
    AnnulusLayout                         layout;
    double indenter_radius = 0; ///< [mm]; inf: a flat counter surface
  };

  /// The steady state of the nip at one speed, in the engineer's units.
  struct SteadyRollingResult
  {
    bool   converged         = false;
    double speed             = 0;       ///< V [m/s]
    double approach          = 0;       ///< u0 [mm]
    double load              = 0;       ///< P [N/mm]
    double resistance_moment = 0;       ///< F_r from the contact moment [N/mm]
    double resistance_energy = 0;       ///< F_r = dissipation / V [N/mm]
    double power             = 0;       ///< dissipated [W/m]
    double theta_in = 0, theta_out = 0; ///< contact edges [rad]
    double peak_position = 0;           ///< of the largest p [rad]
    double peak_pressure = 0;           ///< [MPa]
    /// The nip shift: the angle of the contact forces' centre [rad].
    double       pressure_centre = 0;
    double       half_width      = 0; ///< half the chord between the edges [mm]
    unsigned int fixed_point_iterations = 0, newton_steps = 0;
    /// Contact pressure [MPa] at the surface nodes, by angle [rad].
    std::vector<std::pair<double, double>> pressure;
  };

  /**
   * The full steady rolling of a viscoelastic cover (doc/rolling.md,
   * section 7) on the whole circle, in the frame of the nip: a material
   * point at reference radius r travels along its circle at Omega = V / R0
   * towards increasing theta, so every field is a function of the
   * reference position and the Prony overstress at a sample point (cell
   * centre along the circle, radial Gauss line) follows from its circle's
   * upstream history (periodic_branch()). The equilibrium of the
   * long-term law plus that overstress, with frictionless contact against
   * the rigid mating roll at a prescribed approach u0 (an active set on
   * the surface nodes' gaps), and the history are iterated to a fixed
   * point, one Newton step per history update. Serial (one process).
   */
  class SteadyRolling
  {
  public:
    explicit SteadyRolling(const SteadyRollingScene &scene);
    ~SteadyRolling();

    /// The elastic nip (V = 0) at approach @p u0 [mm], in @p steps equal
    /// steps from the current state. False if Newton fails.
    bool
    solve_elastic(const double u0, const unsigned int steps);

    /// The steady state at speed @p V [m/s] from the current state (the
    /// continuation's previous speed). False if it does not converge.
    bool
    solve_speed(const double V);

    /// The numbers of the current state.
    SteadyRollingResult
    result() const;

    /// The circles of the current state, samples over the whole turn
    /// (theta in [-pi, pi)), with the long-term law's S_iso: the input of
    /// the first-order route (first_order_loss()).
    std::vector<MaterialCircle>
    circles() const;

    /// The heat source of the current state: per circle (by increasing
    /// radius, two per ring at its radial Gauss points) the dissipation
    /// density averaged over a turn [W/m^3], whose area integral is the
    /// dissipated power of result(); zero at zero speed. The input of the
    /// temperature solve (radial_heat_source(), degree 1). The peak is not
    /// computed (0).
    std::vector<CircleLoss>
    heat_source() const;

    /// The whole-circle mesh's layout (for the temperature's own mesh).
    const AnnulusMesh &
    annulus() const
    {
      return layout;
    }

    unsigned int
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

  private:
    /// A point where the circles sample the strain history and where the
    /// overstress acts: in every cell at its centre along the circle
    /// (where the Q1 gradient is most accurate) on each radial Gauss line,
    /// with the weight of that line's two Gauss points. The overstress
    /// there, S_v = c S_iso(F) + H, with H in polar and Cartesian
    /// (reference frame) components.
    struct Sample
    {
      double         theta = 0, radius = 0, JxW = 0;
      unsigned int   layer = 0;
      double         c     = 0;
      PolarTensor    H{{0, 0, 0}};
      Tensor<2, dim> H_cartesian;
    };
    /// A surface node: its DoFs (x, y) and reference position.
    struct SurfaceNode
    {
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               X;
    };

    /// A surface node's contact force and place.
    struct NodeForce
    {
      double         theta = 0, lambda = 0, p = 0;
      bool           active = false;
      Tensor<1, dim> normal;
      Point<dim>     x, arm;
    };
    std::vector<NodeForce>
    contact_forces() const;

    void
    setup();
    void
    make_samples();
    void
    assemble();
    void
    add_cell(const DoFHandler<dim>::active_cell_iterator &cell,
             FEValues<dim>                               &fe_values,
             FullMatrix<double>                          &K,
             dealii::Vector<double>                      &R) const;
    void
    add_overstress(const DoFHandler<dim>::active_cell_iterator &cell,
                   FEValues<dim>                               &at_samples,
                   FullMatrix<double>                          &K,
                   dealii::Vector<double>                      &R) const;
    void
    make_constraints();
    bool
    update_active_set();
    double
    newton_step(bool &changed);
    bool
    newton(const unsigned int max_iterations);
    /// Recomputes every point's c and H from the current state (and the
    /// dissipated power); returns the largest change of H [MPa].
    double
    update_history();
    /// The samples' c and H from the current state; returns the power
    /// dissipated [W/m].
    double
    circle_histories();
    /// The polar S_iso and E at every sample of the current state.
    /// The reference radius of circle @p k [mm]: its radial Gauss point
    /// between the ring's node radii (the radius the temperature's source
    /// is taken at, CoverTemperature).
    double
    circle_radius(const unsigned int k) const;
    void
    point_fields(std::vector<PolarTensor> &S,
                 std::vector<PolarTensor> &E) const;

    Point<dim>
    deformed(const SurfaceNode &node) const;
    double
    gap(const SurfaceNode &node) const;
    Tensor<1, dim>
    gap_normal(const SurfaceNode &node) const;
    Point<dim>
    indenter_centre() const;

    SteadyRollingScene                             scene;
    AnnulusMesh                                    layout;
    Triangulation<dim>                             triangulation;
    MappingQ<dim>                                  mapping;
    FESystem<dim>                                  fe;
    DoFHandler<dim>                                dof_handler;
    std::vector<std::unique_ptr<MaterialLaw<dim>>> laws;

    AffineConstraints<double>                      constraints;
    std::vector<types::global_dof_index>           bond_dofs;
    std::map<types::global_dof_index, SurfaceNode> surface;
    std::set<types::global_dof_index>              active;

    SparsityPattern        pattern;
    SparseMatrix<double>   matrix;
    dealii::Vector<double> rhs, reactions, solution;

    std::vector<Sample> samples;
    /// The samples of each circle, by increasing angle.
    std::vector<std::vector<unsigned int>> circle_samples;
    std::vector<double>                    circle_weight;
    /// Each circle's dissipation density, mean over a turn [W/m^3].
    std::vector<double> circle_dissipation;

    double       u0 = 0, speed = 0, dissipated = 0;
    unsigned int newton_count = 0, fixed_point_count = 0;
    bool         converged = false;
  };
} // namespace rollnip

#endif
