#ifndef rollnip_problem_h
#define rollnip_problem_h

#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/geometry/nip_fitted_mesh.h>
#include <rollnip/global.h>
#include <rollnip/material/mooney_rivlin.h>
#include <rollnip/parameters.h>
#include <rollnip/postprocess/surface_data.h>
#include <rollnip/solvers/block_amg.h>
#include <rollnip/solvers/sparse_direct.h>

#include <functional>
#include <memory>
#include <vector>

namespace rollnip
{
  /// One Newton iteration, as logged (doc/intro.md, section 5).
  struct NewtonRecord
  {
    unsigned int step;
    unsigned int iteration;
    double       load_fraction;
    double       residual;   ///< |R_u| / |F_ext|
    double       constraint; ///< sum |integral (J - 1)| / |Omega|
    double       increment;  ///< |du| / |u|
    double       step_length;
  };

  /// One converged load step.
  struct StepRecord
  {
    unsigned int step;
    double       load_fraction;
    unsigned int newton_iterations;
    double       residual;
    double       nip_load;   ///< P [N/mm]
    double       u_r_centre; ///< [mm]
    double       wall_time;  ///< [s] since the start of the solve
  };

  /// How a run ended.
  struct RunStatus
  {
    bool        converged     = false;
    double      load_fraction = 0; ///< the last converged load fraction
    std::string message;           ///< why it stopped, if it did not converge
  };

  /**
   * The finite-strain cover problem: mesh, Q1-P0 (or Q2-P1) mixed system,
   * follower pressure, Newton with load stepping, and output. One object
   * per run. Implemented by concern:
   *  - source/problem/setup.cc: constructor, setup()
   *  - source/problem/assembly.cc: assemble()
   *  - source/problem/newton.cc: run(), solve_load_step(), the linear solve
   *  - source/problem/postprocess.cc: surface data and scalars
   *  - source/problem/output.cc: VTU/PVD, CSV and summary files
   */
  class RollProblem
  {
  public:
    RollProblem(const Parameters::AllParameters &parameters,
                const MPI_Comm                   mpi_communicator);
    ~RollProblem();

    /// Mesh, DoFs, constraints, sparsity (setup.cc).
    void
    setup();

    /// Whether the mesh follows the nip (Mesh/Nip fitting).
    bool
    has_nip_fitted_mesh() const
    {
      return static_cast<bool>(nip_mesh);
    }

    /// Moves the vertices of the nip-fitted mesh so that the contact edge
    /// is the surface vertex at @p theta0 [rad]; the DoFs, the pattern and
    /// the state vector stay (setup.cc).
    void
    fit_mesh_to_nip(const double theta0);

    /// The largest theta0 [rad] fit_mesh_to_nip() takes.
    double
    max_nip_angle() const
    {
      return nip_mesh ? nip_mesh->max_nip_angle() : 0.;
    }

    /// The smallest corner Jacobian ratio and largest aspect ratio.
    MeshQuality
    cell_quality() const
    {
      return mesh_quality(triangulation);
    }

    /// Ramps the load from 0 to 1 with adaptive steps; writes output for
    /// converged steps; never throws for a load it cannot reach but
    /// reports it in the status (newton.cc). The first increment is
    /// @p first_increment if positive, else 1 / (Initial steps).
    RunStatus
    run(const bool   from_current_state = false,
        const double first_increment    = 0);

    /**
     * Replaces the follower pressure of Load/Pressure function, by default
     * lambda f(Theta), by @p pressure(Theta, lambda) [MPa] with Theta the
     * reference angle and lambda the load fraction in [0, 1]. This is how
     * the contact iteration drives the solver: it ramps from the pressure
     * of the last solution to a new one.
     */
    void
    set_pressure(std::function<double(double, double)> pressure);

    /**
     * Derivative of the residual with respect to the amplitude of an extra
     * follower pressure g(Theta) at the current state, i.e. the load vector
     * int g (cof F N) . v dA with the constraints applied (assembly.cc).
     */
    TrilinosWrappers::MPI::Vector
    pressure_load_derivative(const std::function<double(double)> &g) const;

    /// Factorises the current tangent (after assemble(..., true)) for
    /// repeated solves (newton.cc).
    void
    factorize_tangent();

    /// Solves K x = rhs with the last factorisation; x is distributed
    /// through the constraints.
    void
    solve_with_tangent(const TrilinosWrappers::MPI::Vector &rhs,
                       TrilinosWrappers::MPI::Vector       &x);

    /**
     * Assembles the residual R(u, q; load fraction) of the current solution
     * and, if asked, the consistent tangent (assembly.cc). Returns the
     * smallest J at a quadrature point (<= 0 flags an inverted cell).
     */
    double
    assemble(const double load_fraction, const bool with_matrix);

    /// No timing table when the object goes away (after an error).
    void
    silence_timer()
    {
      timer.disable_output();
    }

    /// Where write_vtu() and write_results() put files (default
    /// Output/Directory); a new directory starts a new PVD record.
    void
    set_output_directory(const std::string &directory)
    {
      if (directory != output_directory)
        pvd_records.clear();
      output_directory = directory;
    }

    /// Whether run() prints one line per load step and writes VTU (on by
    /// default; the contact iteration turns it off for its inner solves).
    void
    set_step_log(const bool on)
    {
      log_steps = on;
    }

    /// Outer and bond surface values of the current state (postprocess.cc).
    SurfaceData
    surface_data(const double load_fraction) const;

    /// Resultant of the applied surface load on the model [N/mm].
    Tensor<1, dim>
    load_resultant(const double load_fraction) const;

    /// Radial displacement of the surface point (R0, 0) [mm].
    double
    radial_displacement_on_line_of_centres() const;

    /// Radial displacement [mm] of the mesh vertex at @p X (NaN if none).
    double
    radial_displacement_at(const Point<dim> &X) const;

    /// Writes VTU (and the PVD record) for the current state (output.cc).
    void
    write_vtu(const unsigned int step, const double load_fraction);

    /// Writes the CSV files and summary.txt for the current state.
    void
    write_results(const RunStatus &status);

    // Read access for tests and drivers.
    const std::vector<NewtonRecord> &
    newton_log() const
    {
      return newton_records;
    }
    /// GMRES iterations of all solves so far (Method = gmres-amg).
    unsigned int
    gmres_iterations() const
    {
      return iterative_solver.n_iterations;
    }
    const std::vector<StepRecord> &
    step_log() const
    {
      return step_records;
    }
    const TrilinosWrappers::MPI::Vector &
    current_solution() const
    {
      return locally_relevant_solution;
    }
    /// Sets the state (owned entries) and updates ghosts.
    void
    set_solution(const TrilinosWrappers::MPI::Vector &owned);
    const TrilinosWrappers::MPI::Vector &
    residual() const
    {
      return system_rhs;
    }
    const TrilinosWrappers::SparseMatrix &
    tangent() const
    {
      return system_matrix;
    }
    const IndexSet &
    locally_owned() const
    {
      return locally_owned_dofs;
    }
    const AffineConstraints<double> &
    constraints_object() const
    {
      return constraints;
    }
    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }
    unsigned int
    n_cells() const
    {
      return triangulation.n_global_active_cells();
    }
    const DoFHandler<dim> &
    dofs() const
    {
      return dof_handler;
    }

  private:
    // newton.cc
    bool
    solve_load_step(const double load_fraction, const unsigned int step);
    void
    solve_linear_system(TrilinosWrappers::MPI::Vector &newton_update);
    double
    pressure_part_norm(const TrilinosWrappers::MPI::Vector &v) const;

    // setup.cc
    void
    make_constraints();
    void
    set_up_schur_blocks();
    /// The area of the mesh [mm^2] (for the constraint norm).
    double
    measure_area() const;

    /// The round-off floor of |R_u| [N/mm] (newton.cc): relative to a tiny
    /// load it can exceed Residual tolerance, so the Newton test adds it
    /// and any load scale stays reachable.
    double
    residual_round_off_floor() const;

    /// Solves load step @p step at @p target from the state extrapolated
    /// through the converged states at @p previous_lambda (@p previous)
    /// and @p lambda (the current one); restores the current state if
    /// Newton fails from there (newton.cc).
    bool
    solve_from_prediction(const double                         lambda,
                          const double                         target,
                          const double                         previous_lambda,
                          const TrilinosWrappers::MPI::Vector &previous,
                          const unsigned int                   step);

    /// The screen line of converged load step @p step at @p lambda, and
    /// its VTU and surface CSV when asked for every step (newton.cc).
    void
    log_step(const unsigned int step, const double lambda, const StepRecord &r);
    bool
    use_iterative_solver() const
    {
      return parameters.linear_solver.method == "gmres-amg";
    }

    /// Whether face @p f of @p cell carries the follower pressure
    /// (assembly.cc).
    bool
    is_pressure_face(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     const unsigned int f) const;

    /// Face values for the follower-load integrals: Gauss(degree + 1) on
    /// the faces, values, gradients, normals, points, JxW (assembly.cc).
    std::unique_ptr<FEFaceValues<dim>>
    make_pressure_face_values() const;

    /// n da / dA of eq. 4.1: cof(F) N, or N in linear theory (assembly.cc).
    Tensor<1, dim>
    current_area_normal(const Tensor<2, dim> &grad_u,
                        const Tensor<1, dim> &N) const;

    // output.cc
    void
    write_csv(const SurfaceData &data) const;
    /// outer_surface<suffix>.csv and bond_surface<suffix>.csv (rank 0).
    void
    write_surface_csv(const SurfaceData &data, const std::string &suffix) const;
    void
    write_summary(const RunStatus      &status,
                  const SurfaceData    &data,
                  const Tensor<1, dim> &resultant,
                  const double          u_r) const;

    const Parameters::AllParameters &parameters;
    MPI_Comm                         mpi_communicator;
    ConditionalOStream               pcout;
    mutable TimerOutput              timer;
    Timer                            wall_clock;

    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<NipFittedMesh>            nip_mesh; ///< or none
    const MooneyRivlin                        material;
    std::function<double(double, double)>     pressure;

    std::unique_ptr<MappingQ<dim>> mapping;
    std::unique_ptr<FESystem<dim>> fe;
    DoFHandler<dim>                dof_handler;
    IndexSet                       locally_owned_dofs;
    IndexSet                       locally_relevant_dofs;
    IndexSet                       pressure_dofs; ///< owned pressure DoFs
    AffineConstraints<double>      constraints;

    TrilinosWrappers::SparseMatrix system_matrix;
    SparseDirectSolver             direct_solver;
    BlockAMGSolver                 iterative_solver;
    /// [A 0; 0 M_p/G] for the AMG of Linear solver/Method = gmres-amg.
    TrilinosWrappers::SparseMatrix preconditioner_matrix;
    std::vector<std::vector<bool>> constant_modes;
    TrilinosWrappers::MPI::Vector  solution; ///< owned entries
    TrilinosWrappers::MPI::Vector  locally_relevant_solution;
    TrilinosWrappers::MPI::Vector  system_rhs;     ///< residual R
    TrilinosWrappers::MPI::Vector  external_force; ///< surface load part

    std::string output_directory;
    double      domain_area = 0;
    bool        log_steps   = true;

    std::vector<NewtonRecord>                   newton_records;
    std::vector<StepRecord>                     step_records;
    std::vector<std::pair<double, std::string>> pvd_records;
    unsigned int                                n_assemblies    = 0;
    unsigned int                                n_linear_solves = 0;
    unsigned int                                n_cutbacks      = 0;
  };
} // namespace rollnip

#endif
