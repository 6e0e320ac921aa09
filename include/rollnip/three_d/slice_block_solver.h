#ifndef rollnip_three_d_slice_block_solver_h
#define rollnip_three_d_slice_block_solver_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/material/material_law.h>
#include <rollnip/three_d/slice_mesh.h>

#include <vector>

namespace rollnip
{
  namespace three_d
  {
    /// The cell's pressure mass matrix M_K = int psi_a psi_b dX over the
    /// pressure dofs of @p fv's cell, in the order of the cell's pressure
    /// dofs: |cell| for P0, 4x4 for P1. @p fv carries values and JxW.
    FullMatrix<double>
    cell_pressure_mass(const FEValues<dim> &fv);

    /// The augmented Lagrangian of the cells of one law: the augmentation
    /// gamma and the modulus G' of the Schur block S_K^-1 ~ G' M_K^-1.
    struct CellAugmentation
    {
      double gamma;         ///< [MPa]
      double schur_modulus; ///< G' [MPa]
    };

    /**
     * The augmentation of the cells of @p law, from the cell's own moduli
     * (a cover layer and a steel core differ by 8e4 in G):
     * - incompressible: gamma = 10 G, G' = G + gamma;
     * - compressible with kappa = 1 / pressure_compliance() <= 10 G (the
     *   steel core, nu = 0.3): gamma = kappa, which takes the cell's
     *   pressure out of its displacement rows exactly (they get
     *   B^T - gamma/kappa B^T = 0), so A is the cell's displacement
     *   stiffness and S_K = M_K / kappa exactly: G' = kappa;
     * - compressible with kappa > 10 G: gamma = 10 G and, with
     *   B A_0^-1 B^T ~ M_K / G, S_K ~ M_K (kappa + G) / (kappa (G +
     *   gamma)), G' = (G + gamma) / (1 + G / kappa).
     */
    CellAugmentation
    cell_augmentation(const MaterialLaw<dim> &law);

    /**
     * GMRES with a block lower-triangular preconditioner for the Newton
     * system K = [A B^T; B 0] of the 3D body (Q1-P0 or Q2-P1), the 3D variant
     * of BlockAMGSolver (solvers/block_amg.h) for an augmented Lagrangian
     * system (A = A_0 + gamma B^T M_p^-1 B, SliceBody::assemble()):
     *   A^-1 ~ one AMG V-cycle (Trilinos ML) on [A 0; 0 M_p/G'], with the
     *          six rigid-body modes of the displacement at every support
     *          point (vertices for Q1; also edge, face and cell nodes for
     *          Q2) as ML's near-null space (with the three constant modes
     *          alone GMRES needs about 1.5 times the iterations on the
     *          slice),
     *   S^-1 ~ G' M_p^-1, G' = G + gamma of the cell's own law
     *          (cell_augmentation()), one block per cell for the
     *          discontinuous pressure: G' / |cell| for P0, G' M_K^-1 with
     *          the 4x4 mass matrix of the cell for P1.
     */
    class SliceBlockSolver
    {
    public:
      /// Iterates until |b - K x| <= tolerance |b|, at most max_iterations.
      SliceBlockSolver(const double       tolerance,
                       const unsigned int max_iterations);

      /// The rigid-body modes and the Schur blocks of @p dof_handler's
      /// mesh (FE_Q(k)^3 x a discontinuous pressure), the support points
      /// and the cells' pressure mass through @p mapping (QGauss(k + 1));
      /// @p schur_modulus G' [MPa] of the cells by their material id.
      void
      setup(const Mapping<dim>        &mapping,
            const DoFHandler<dim>     &dof_handler,
            const std::vector<double> &schur_modulus);

      /// Builds the AMG hierarchy of @p augmented; K is used by solve().
      /// A new AMG hierarchy for @p augmented, or the last one kept when
      /// its GMRES iterations have not grown (reuse()).
      void
      initialize(const TrilinosWrappers::SparseMatrix &K,
                 const TrilinosWrappers::SparseMatrix &augmented);

      /// x = K^-1 b to the tolerance; throws with the residual reached.
      void
      solve(const TrilinosWrappers::MPI::Vector &b,
            TrilinosWrappers::MPI::Vector       &x);

      /// z = P^-1 r (the preconditioner, for deal.II's solvers).
      void
      vmult(TrilinosWrappers::MPI::Vector       &z,
            const TrilinosWrappers::MPI::Vector &r) const;

      unsigned int n_iterations = 0; ///< GMRES iterations, all solves
      unsigned int n_setups     = 0; ///< AMG hierarchies built

    private:
      /// Whether the next solve can keep the hierarchy of an earlier
      /// Newton step: ML smooths with the current fine matrix (it wraps
      /// it, not a copy), so an old hierarchy stays a good preconditioner
      /// while the iterations stay within 1.5 times the fresh count.
      bool
      reuse() const;

      void
      build_hierarchy();

      /// The rigid-body modes and the displacement mask at every locally
      /// owned displacement dof, at its support point on @p mapping.
      void
      collect_rigid_modes(const Mapping<dim>    &mapping,
                          const DoFHandler<dim> &dof_handler);

      /// G' M_K^-1 and the local pressure rows of every owned cell.
      void
      collect_schur_blocks(const Mapping<dim>        &mapping,
                           const DoFHandler<dim>     &dof_handler,
                           const std::vector<double> &schur_modulus);

      const double                          tolerance;
      const unsigned int                    max_iterations;
      const TrilinosWrappers::SparseMatrix *matrix           = nullptr;
      const TrilinosWrappers::SparseMatrix *augmented_matrix = nullptr;
      TrilinosWrappers::PreconditionAMG     amg;
      /// The six rigid-body modes, locally owned rows, one mode after
      /// the other (ML's "null space: vectors").
      std::vector<double> rigid_modes;
      /// The displacement constant modes (for ML's defaults).
      std::vector<std::vector<bool>> constant_modes;
      /// The pressure dofs of the locally owned cells as indices into the
      /// locally owned rows, n_pressure per cell, cell after cell.
      std::vector<unsigned int> schur_rows;
      /// G' M_K^-1 of those cells, n_pressure^2 per cell (row major).
      std::vector<double> schur_blocks;
      /// Pressure dofs per cell: 1 (P0) or 4 (P1).
      unsigned int n_pressure = 0;
      /// 1 at the displacement dofs, 0 at the pressure dofs.
      TrilinosWrappers::MPI::Vector         displacement_mask;
      mutable TrilinosWrappers::MPI::Vector tmp;
      /// GMRES iterations of the first and of the last solve with the
      /// current hierarchy (0: none yet).
      unsigned int fresh_iterations = 0, last_iterations = 0;
    };
  } // namespace three_d
} // namespace rollnip

#endif
