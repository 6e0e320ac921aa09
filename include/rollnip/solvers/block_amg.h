#ifndef rollnip_solvers_block_amg_h
#define rollnip_solvers_block_amg_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <rollnip/global.h>
#include <rollnip/solvers/sparse_direct.h>

#include <vector>

namespace rollnip
{
  /**
   * GMRES on the saddle-point Newton system K = [A B^T; B 0] with the block
   * lower-triangular preconditioner
   *   P = [A 0; B -S],  A^-1 ~ one AMG V-cycle (Trilinos ML),
   *                     S^-1 ~ G M_p^-1  (G the shear modulus, M_p the
   *                     pressure mass matrix, block diagonal: one block
   *                     per cell for a discontinuous pressure),
   * since for a nearly rigid incompressible solid B A^-1 B^T is spectrally
   * close to the pressure mass matrix over G. The AMG works on an
   * augmented matrix [A 0; 0 M_p/G] (diagonal of M_p), assembled beside K,
   * so that every row has a diagonal. An alternative to the direct solver
   * for large meshes: the cost per solve grows about linearly with size.
   */
  class BlockAMGSolver
  {
  public:
    /// Iterates until |b - K x| <= tolerance |b|, at most max_iterations.
    BlockAMGSolver(const double tolerance, const unsigned int max_iterations);

    /// One block per cell of the discontinuous pressure: its DoFs and
    /// G M_K^-1 (the inverse of the cell's pressure mass matrix, times G).
    void
    set_schur_blocks(std::vector<std::vector<types::global_dof_index>> &&dofs,
                     std::vector<FullMatrix<double>> &&inverse_masses);

    /// Builds the AMG hierarchy of @p augmented; K is used by solve().
    /// @p constant_modes: the displacement components' constant modes
    /// (DoFTools). The pressure DoFs are those of set_schur_blocks().
    void
    initialize(const TrilinosWrappers::SparseMatrix &K,
               const TrilinosWrappers::SparseMatrix &augmented,
               const std::vector<std::vector<bool>> &constant_modes,
               const bool                            higher_order);

    /// x = K^-1 b to the tolerance; throws with the residual reached.
    void
    solve(const TrilinosWrappers::MPI::Vector &b,
          TrilinosWrappers::MPI::Vector       &x);

    /// z = P^-1 r (the preconditioner, for deal.II's solvers).
    void
    vmult(TrilinosWrappers::MPI::Vector       &z,
          const TrilinosWrappers::MPI::Vector &r) const;

    unsigned int n_setups     = 0;
    unsigned int n_solves     = 0;
    unsigned int n_iterations = 0; ///< GMRES iterations, all solves

  private:
    const double                                      tolerance;
    const unsigned int                                max_iterations;
    const TrilinosWrappers::SparseMatrix             *matrix = nullptr;
    TrilinosWrappers::PreconditionAMG                 amg;
    std::vector<std::vector<types::global_dof_index>> block_dofs;
    std::vector<FullMatrix<double>>                   block_inverses;
    mutable TrilinosWrappers::MPI::Vector             tmp;
  };
} // namespace rollnip

#endif
