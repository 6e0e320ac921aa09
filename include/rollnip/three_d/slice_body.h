#ifndef rollnip_three_d_slice_body_h
#define rollnip_three_d_slice_body_h

#include <deal.II/base/index_set.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/contact/counter_surface.h>
#include <rollnip/material/material_law.h>
#include <rollnip/parameters.h>
#include <rollnip/solvers/sparse_direct.h>
#include <rollnip/three_d/core_deflection.h>
#include <rollnip/three_d/slice_block_solver.h>
#include <rollnip/three_d/slice_mesh.h>
#include <rollnip/three_d/three_d_parameters.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>

namespace rollnip
{
  namespace three_d
  {
    /// One converged approach of the slice.
    struct SliceNip
    {
      double u0         = 0; ///< approach [mm]
      double P          = 0; ///< line load of the full nip [N/mm]
      double half_chord = 0; ///< deformed x2 of the last active node [mm]
      /// Extent along the roll axis of the active nodes [mm].
      double       contact_length  = 0;
      unsigned int active_nodes    = 0;
      unsigned int newton_steps    = 0; ///< over all load steps
      double       max_penetration = 0; ///< max(-gap) over the surface [mm]
      /// GMRES iterations over all Newton steps (0 with the direct solver).
      unsigned int linear_iterations = 0;
    };

    /// Where and how hard the indenter presses (slice_patch.cc).
    struct ContactPatch
    {
      /// Largest nodal contact pressure: the normal contact force of an
      /// active node over its share of the deformed outer surface [MPa].
      double peak_pressure = 0;
      double peak_z        = 0; ///< z of that node [mm]
      /// Deformed x2 of the last active node in the plane z = 0 [mm].
      double half_chord_middle = 0;
      /// The same in the plane z = Slice thickness [mm].
      double half_chord_far = 0;
      /// Line load at z = 0 (consistent recovery) [N/mm].
      double line_load_middle = 0;
    };

    /// @p patch of the last approach @p nip as "key = value" lines at
    /// @p path, with the face's total force for a face of 2 L (a symmetry
    /// plane at z = 0) [N].
    void
    write_contact_patch(const std::string        &path,
                        const ContactPatch       &patch,
                        const SliceNip           &nip,
                        const Parameters::ThreeD &three_d);

    /**
     * The cover as a 3D body (slice_mesh.h): Discretization/Element selects
     * Q1-P0 (FE_Q(1)^3 x FE_DGP(0), 2x2x2 Gauss) or Q2-P1 (FE_Q(2)^3 x
     * FE_DGPNonparametric(1), 3x3x3 Gauss, MappingQ(2) on the cylindrical
     * manifold), as the 2D body does; total Lagrangian, the surface layer's law
     * from make_layer_law<3>() (incompressible or compressible), pressed by the
     * rigid indenter (a cylinder parallel to the roll axis, or a plane) of
     * Contact. The contact is frictionless and solved by a primal-dual active
     * set on the nodes of the outer surface inside Newton (semismooth Newton):
     * a node is active when its normal contact force over its lumped area (the
     * row sum of the face mass matrix) minus c times its gap is positive, and
     * an active node's Newton update is constrained to the linearised gap, g +
     * n . du = 0. Conditions: bonded at R1, u_theta = 0 on the plane through
     * the nip, the far edge as Boundary conditions/Far edge, u_z = 0 on z = 0
     * and (Far face) on z = L. A layered cover: every cell has its layer's
     * law (by material id).
     */
    class SliceBody
    {
    public:
      SliceBody(const Parameters::AllParameters &parameters,
                const Parameters::ThreeD        &three_d,
                const unsigned int               level,
                const MPI_Comm                   communicator);

      /// Moves the indenter from the current approach to @p u0 in load
      /// steps and returns the converged state; throws if Newton fails.
      SliceNip
      solve(const double u0);

      /// The line load along the roll axis: (z [mm], q [N/mm]) at every
      /// plane of surface nodes (Q2: vertex and mid-layer planes), the
      /// full nip's normal force of the plane's
      /// active nodes over the plane's share of the slice length. On a
      /// drawn mesh not in layers, at its stations: each active node's
      /// force shared between the two stations around it by the linear hat
      /// functions of the stations, over the hat's integral (a weighted
      /// mean of q about the station; the total force is kept).
      std::vector<std::pair<double, double>>
      line_load_profile() const;

      /// The z of the planes of nodes along the axis [mm]: the layer
      /// boundaries, and with Q2 the layers' middles too (a drawn mesh not
      /// in layers: its stations).
      std::vector<double>
      node_planes() const;

      /// The share of the slice length [mm] of every plane of
      /// line_load_profile(): half the layers on either side (Q1), the
      /// lumped Q2 weights h/6 + h/6 at a vertex plane and 2h/3 at a
      /// mid-layer plane (Q2), half the gaps on either side of a station.
      /// They sum to the slice thickness.
      std::vector<double>
      line_load_widths() const;

      /// A drawn mesh not in layers: adds to @p f (one entry per station of
      /// @p stations) this process's contact force [N] shared by the
      /// stations' hat functions in z.
      void
      add_station_forces(const std::vector<double> &stations,
                         std::vector<double>       &f) const;

      /// Whether node_planes() are planes of nodes (false: the stations of
      /// a drawn mesh not in layers).
      bool
      has_node_planes() const
      {
        return layered;
      }

      /// 1 (Q1-P0) or 2 (Q2-P1).
      unsigned int
      displacement_degree() const
      {
        return degree;
      }

      /// Peak pressure and the contact's extent at the last approach.
      ContactPatch
      contact_patch() const;

      /// Displacement, q, J, Cauchy stress and contact status as
      /// DIRECTORY/NAME_COUNTER.pvtu with one .vtu per process.
      void
      write_vtu(const std::string &directory,
                const std::string &name,
                const unsigned int counter) const;

      types::global_dof_index
      n_dofs() const
      {
        return dof_handler.n_dofs();
      }

      /// The linear solver of the Newton steps, as printed at the start.
      std::string
      linear_solver_name() const;

      /// Symbolic analyses and numeric factorisations of the direct solver
      /// so far (0 with gmres-amg).
      std::pair<unsigned int, unsigned int>
      direct_factorisations() const
      {
        if (!direct)
          return {0, 0};
        return {direct->n_analyses, direct->n_factorisations};
      }

      unsigned int
      n_cells() const
      {
        return triangulation.n_global_active_cells();
      }

      /// Read access for the free-end measures (free_end.h).
      const DoFHandler<dim> &
      get_dof_handler() const
      {
        return dof_handler;
      }
      /// The displacements and q, ghosted.
      const TrilinosWrappers::MPI::Vector &
      current_solution() const
      {
        return solution;
      }
      /// The unconstrained residual: at supported dofs the nodal forces
      /// the supports apply to the cover [N], ghosted.
      const TrilinosWrappers::MPI::Vector &
      nodal_reactions() const
      {
        return reactions;
      }
      MPI_Comm
      mpi_communicator() const
      {
        return communicator;
      }
      const Parameters::AllParameters &
      parameters_of_mesh() const
      {
        return parameters;
      }
      const Parameters::ThreeD &
      three_d_parameters() const
      {
        return three_d;
      }

      /// Read access for the free-end measures (free_end.h) too.
      /// The three displacement dofs and the reference position of a
      /// node (a support point of the displacement) of a boundary.
      struct SurfaceNode
      {
        std::array<types::global_dof_index, dim> dofs;
        Point<dim>                               X;
        /// Lumped (row-sum) reference area int phi dA of the node on the
        /// outer surface [mm^2], positive for Q1 and Q2; 0 elsewhere.
        double weight = 0;
      };

      /// Every node on the boundary @p id of the locally owned and ghost
      /// cells, by x dof (slice_nodes.cc): all the displacement dofs there,
      /// at their support points on the mapped (curved) geometry.
      std::map<types::global_dof_index, SurfaceNode>
      boundary_nodes(const types::boundary_id id) const;
      /// The lumped areas int phi_i dA of the nodes on boundary @p id over
      /// the reference (@p deformed false) or current surface, by x dof,
      /// ghosted [mm^2] (slice_nodes.cc).
      TrilinosWrappers::MPI::Vector
      lumped_areas(const types::boundary_id id, const bool deformed) const;

    private:
      void
      setup_system();
      void
      collect_surface_nodes();
      /// K, the condensed Newton right-hand side, the unconstrained
      /// residual (the nodal reactions) and the condensed residual norms.
      void
      assemble();
      /// Fixed, symmetry and face constraints of the Newton update.
      void
      make_support_constraints(AffineConstraints<double> &c) const;
      /// The active set at approach u0 from the current gaps and reactions;
      /// returns whether it changed.
      bool
      update_active_set(const double u0);
      void
      make_constraints(const double u0);
      /// du = K^-1 system_rhs by Linear solver/Method (slice_linear_solve.cc).
      void
      solve_linear(TrilinosWrappers::MPI::Vector &du);
      /// Newton with the active set at fixed u0; false if it failed.
      bool
      newton(const double u0, unsigned int &steps);
      Point<dim>
      deformed(const SurfaceNode &node) const;
      double
      gap(const SurfaceNode &node, const double u0) const;
      Tensor<1, dim>
      gap_normal(const SurfaceNode &node, const double u0) const;
      SliceNip
      evaluate(const double u0) const;
      /// max |gap| over the active nodes [mm].
      double
      active_gap(const double u0) const;

      MPI_Comm                                  communicator;
      const Parameters::AllParameters           parameters;
      const Parameters::ThreeD                  three_d;
      parallel::distributed::Triangulation<dim> triangulation;
      /// The z of the planes between the layers of cells [mm], 0 to
      /// Slice thickness: the extruded layers, or a drawn mesh's own (for
      /// a drawn mesh not in layers: its stations, AxialPlanes).
      std::vector<double> layer_planes;
      /// AxialPlanes::layered: false for a drawn mesh not in layers.
      bool layered = true;
      /// 1 (Q1-P0) or 2 (Q2-P1): Discretization/Element.
      const unsigned int degree;
      /// MappingQ(degree): the Q2 cells follow the cylindrical manifold.
      const std::unique_ptr<const Mapping<dim>>     mapping;
      FESystem<dim>                                 fe;
      DoFHandler<dim>                               dof_handler;
      const std::unique_ptr<const MaterialLaw<dim>> law;
      std::unique_ptr<CounterSurface>               indenter;
      /// c of the active-set rule, pressure / gap [MPa/mm]: a node is
      /// active while its force over its lumped area exceeds c g.
      double active_set_scale;

      IndexSet                                       owned, relevant;
      AffineConstraints<double>                      constraints;
      AffineConstraints<double>                      homogeneous_constraints;
      std::map<types::global_dof_index, SurfaceNode> surface; ///< by x dof
      std::set<types::global_dof_index>              active;  ///< x dofs

      TrilinosWrappers::SparseMatrix system_matrix;
      TrilinosWrappers::MPI::Vector  solution;   ///< ghosted
      TrilinosWrappers::MPI::Vector  system_rhs; ///< condensed, owned
      TrilinosWrappers::MPI::Vector  reactions;  ///< unconstrained, ghosted
      double                         residual_u = 0, residual_q = 0;
      double                         current_u0 = 0;

      // Linear solver/Method = gmres-amg (slice_linear_solve.cc).
      const bool iterative;
      /// gamma of the augmented Lagrangian and G' of the Schur blocks by
      /// the cells' material id (layer_laws, cell_augmentation()): the
      /// Newton system is solved as [A + gamma B^T M_p^-1 B, B^T; B, 0]
      /// (the same du; M_p block diagonal, one block per cell: |cell| for
      /// P0, 4x4 for P1), whose Schur complement G M_p^-1 + gamma M_p^-1
      /// approximates well whatever the inf-sup constant of Q1-P0; empty
      /// with the direct solver.
      std::vector<CellAugmentation> augmentation;
      /// [A 0; 0 M_p/G'], the AMG's matrix, assembled beside K.
      TrilinosWrappers::SparseMatrix    preconditioner_matrix;
      std::unique_ptr<SliceBlockSolver> block_amg;
      /// Linear solver/Method = direct: MUMPS or KLU, which analyses the
      /// fixed pattern once and refactorises numerically at each Newton
      /// step.
      std::unique_ptr<SparseDirectSolver> direct;

      // The prescribed core deflection (slice_core.cc).
      /// The bonded nodes' x dofs at R1 and their v(z) [mm].
      void
      collect_bonded_nodes();
      /// The bonded nodes' u_x = -core_factor v(z) as inhomogeneities of
      /// the Newton update in @p c (their lines are in it already).
      void
      add_core_displacement(AffineConstraints<double> &c) const;

      CoreDeflection                            core;
      std::map<types::global_dof_index, double> bonded; ///< x dof -> v(z)
      /// max |v| over the bonded nodes [mm].
      double core_amplitude = 0;
      /// The share of v applied so far: ramped to 1 with the approach.
      double core_factor = 0;

      // The contact patch (slice_patch.cc).
      /// The x dofs of the four vertices of every locally owned face on
      /// the outer surface (Q1: its nodal areas on the deformed surface).
      void
      collect_surface_faces();
      std::vector<std::array<types::global_dof_index, 4>> surface_faces;
      /// Q1: each outer node's share of the deformed outer surface, a
      /// quarter of its faces' areas, by x dof, ghosted [mm^2].
      TrilinosWrappers::MPI::Vector
      vertex_areas() const;

      /// Every cover layer's law, by the cells' material id (0: on the
      /// core), and with the elastic core the steel's after them; law
      /// above is the surface layer's, the scale of the contact rule.
      std::vector<std::unique_ptr<const MaterialLaw<dim>>> layer_laws;
    };
  } // namespace three_d
} // namespace rollnip

#endif
