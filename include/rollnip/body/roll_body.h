#ifndef rollnip_body_roll_body_h
#define rollnip_body_roll_body_h

#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/geometry/nip_fitted_mesh.h>
#include <rollnip/global.h>
#include <rollnip/loading/follower_load.h>
#include <rollnip/material/material_table.h>
#include <rollnip/parameters.h>

#include <memory>
#include <vector>

namespace rollnip
{
  /**
   * One discretised cover: its mesh, the mixed Q1-P0 (or Q2-P1) fields,
   * the constraints of its boundary conditions, its state u, q, its
   * materials and its follower load; it assembles the residual and the
   * tangent of that state. The algorithms that drive it (Newton, load
   * stepping, contact) and the output live elsewhere. Implemented in
   * source/body/: roll_body.cc (set-up, constraints, state) and
   * roll_body_assembly.cc (residual, tangent, load derivative).
   */
  class RollBody
  {
  public:
    /// @p timer times the set-up and the assembly.
    RollBody(const Parameters::AllParameters &parameters,
             const MPI_Comm                   mpi_communicator,
             TimerOutput                     &timer);
    ~RollBody();

    /// Mesh, DoFs, constraints, sparsity, zero state.
    void
    setup();

    /// Whether the mesh follows the nip (Mesh/Nip fitting).
    bool
    has_nip_fitted_mesh() const
    {
      return static_cast<bool>(nip_mesh);
    }

    /// Moves the vertices of the nip-fitted mesh so that the contact edge
    /// is the surface vertex at @p theta0 [rad]; DoFs, pattern and state
    /// stay.
    void
    fit_mesh_to_nip(const double theta0);

    /// The largest theta0 [rad] fit_mesh_to_nip() takes (0: not fitted).
    double
    max_nip_angle() const
    {
      return nip_mesh ? nip_mesh->max_nip_angle() : 0.;
    }

    MeshQuality
    cell_quality() const
    {
      return mesh_quality(triangulation);
    }

    /**
     * The residual R(u, q; lambda) of the current state into residual()
     * (and the load part into external_force()) and, if asked, the
     * consistent tangent, and for Linear solver/Method = gmres-amg its
     * preconditioner matrix. Returns the smallest J at a quadrature point
     * (<= 0 flags an inverted cell).
     */
    double
    assemble(const double load_fraction, const bool with_matrix);

    /// d R_u / d s for an extra follower pressure s g(Theta) at the
    /// current state: int g (cof F N) . v dA, constraints applied.
    TrilinosWrappers::MPI::Vector
    pressure_load_derivative(const std::function<double(double)> &g) const;

    /// G times the inverse pressure mass matrix of every owned cell, for
    /// the Schur complement of the gmres-amg solver.
    void
    pressure_mass_inverses(
      std::vector<std::vector<types::global_dof_index>> &blocks,
      std::vector<FullMatrix<double>>                   &inverses) const;

    FollowerLoad &
    load()
    {
      return follower_load;
    }
    const FollowerLoad &
    load() const
    {
      return follower_load;
    }

    /// The state with ghosts.
    const TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return locally_relevant_solution;
    }
    /// Sets the state from its owned entries and updates the ghosts.
    void
    set_solution(const TrilinosWrappers::MPI::Vector &owned);
    /// The owned entries of the state (zero vector layout for updates).
    const TrilinosWrappers::MPI::Vector &
    owned_solution() const
    {
      return solution_owned;
    }

    /// The named point where a converged load step is accepted: the laws
    /// commit their internal variables (MaterialLaw::commit()).
    void
    commit_state()
    {
      material_table.commit();
    }
    /// The named point where a solve is discarded and the state goes back
    /// to the last converged one: the laws roll their internal variables
    /// back (MaterialLaw::rollback()).
    void
    rollback_state()
    {
      material_table.rollback();
    }

    const TrilinosWrappers::MPI::Vector &
    residual() const
    {
      return system_rhs;
    }
    const TrilinosWrappers::MPI::Vector &
    external_force() const
    {
      return load_vector;
    }
    const TrilinosWrappers::SparseMatrix &
    tangent() const
    {
      return system_matrix;
    }
    const TrilinosWrappers::SparseMatrix &
    preconditioner() const
    {
      return preconditioner_matrix;
    }
    /// Rigid-body modes of the displacement, for the AMG.
    const std::vector<std::vector<bool>> &
    displacement_modes() const
    {
      return constant_modes;
    }

    const DoFHandler<dim> &
    dofs() const
    {
      return dof_handler;
    }
    const FESystem<dim> &
    fe() const
    {
      return *element;
    }
    const Mapping<dim> &
    mapping() const
    {
      return *cell_mapping;
    }
    const MaterialTable &
    materials() const
    {
      return material_table;
    }
    /// The laws, to set a modulus factor (a softened cover) before a solve.
    MaterialTable &
    materials()
    {
      return material_table;
    }
    const AffineConstraints<double> &
    constraints() const
    {
      return boundary_constraints;
    }
    const IndexSet &
    locally_owned() const
    {
      return locally_owned_dofs;
    }
    /// The owned DoFs of the pressure unknown q.
    const IndexSet &
    pressure_dofs() const
    {
      return owned_pressure_dofs;
    }
    /// The reference area of the mesh [mm^2].
    double
    area() const
    {
      return domain_area;
    }
    unsigned int
    n_cells() const
    {
      return triangulation.n_global_active_cells();
    }
    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }
    const parallel::distributed::Triangulation<dim> &
    mesh() const
    {
      return triangulation;
    }
    MPI_Comm
    communicator() const
    {
      return mpi_communicator;
    }
    const Parameters::AllParameters &
    scene() const
    {
      return parameters;
    }
    unsigned int
    n_assemblies() const
    {
      return assembly_count;
    }

  private:
    void
    make_constraints();
    /// u . n = 0 on the symmetry edges.
    void
    add_symmetry_constraints();
    void
    make_sparsity_and_vectors();
    double
    measure_area() const;

    const Parameters::AllParameters &parameters;
    MPI_Comm                         mpi_communicator;
    TimerOutput                     &timer;
    const bool                       with_preconditioner;

    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<NipFittedMesh>            nip_mesh; ///< or none
    MaterialTable                             material_table;
    FollowerLoad                              follower_load;

    std::unique_ptr<MappingQ<dim>> cell_mapping;
    std::unique_ptr<FESystem<dim>> element;
    DoFHandler<dim>                dof_handler;
    IndexSet                       locally_owned_dofs;
    IndexSet                       locally_relevant_dofs;
    IndexSet                       owned_pressure_dofs;
    AffineConstraints<double>      boundary_constraints;

    TrilinosWrappers::SparseMatrix system_matrix;
    /// [A 0; 0 M_p/G] for the AMG of Linear solver/Method = gmres-amg.
    TrilinosWrappers::SparseMatrix preconditioner_matrix;
    std::vector<std::vector<bool>> constant_modes;
    TrilinosWrappers::MPI::Vector  solution_owned;
    TrilinosWrappers::MPI::Vector  locally_relevant_solution;
    TrilinosWrappers::MPI::Vector  system_rhs;  ///< residual R
    TrilinosWrappers::MPI::Vector  load_vector; ///< surface load part

    double       domain_area    = 0;
    unsigned int assembly_count = 0;
  };
} // namespace rollnip

#endif
