#ifndef rollnip_three_d_slice_block_solver_h
#define rollnip_three_d_slice_block_solver_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/three_d/slice_mesh.h>

#include <vector>

namespace rollnip
{
  namespace three_d
  {
    /**
     * GMRES with a block lower-triangular preconditioner for the Newton
     * system K = [A B^T; B 0] of the 3D body (Q1-P0), the 3D variant of
     * BlockAMGSolver (solvers/block_amg.h) for an augmented Lagrangian
     * system (A = A_0 + gamma B^T M_p^-1 B, SliceBody::assemble()):
     *   A^-1 ~ one AMG V-cycle (Trilinos ML) on [A 0; 0 M_p/G'], with the
     *          six rigid-body modes of the displacement as ML's near-null
     *          space (with the three constant modes alone GMRES needs about
     *          1.5 times the iterations on the slice),
     *   S^-1 ~ G' M_p^-1, G' = G + gamma, diagonal for the P0 pressure:
     *          G' / |cell|.
     */
    class SliceBlockSolver
    {
    public:
      /// Iterates until |b - K x| <= tolerance |b|, at most max_iterations.
      SliceBlockSolver(const double       tolerance,
                       const unsigned int max_iterations);

      /// The rigid-body modes and the Schur diagonal of @p dof_handler's
      /// mesh (FE_Q(1)^3 x FE_DGP(0)); @p schur_modulus G' [MPa].
      void
      setup(const DoFHandler<dim> &dof_handler, const double schur_modulus);

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
      /// G' / |cell| at the pressure dofs, 0 at the displacement dofs.
      TrilinosWrappers::MPI::Vector schur_diagonal;
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
