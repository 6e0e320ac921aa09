#include <deal.II/lac/vector.h>

#include <rollnip/solvers/block_amg.h>
#include <rollnip/solvers/gmres_solve.h>


namespace rollnip
{
  BlockAMGSolver::BlockAMGSolver(const double       tolerance,
                                 const unsigned int max_iterations)
      : tolerance(tolerance)
      , max_iterations(max_iterations)
  {}

  void
  BlockAMGSolver::set_schur_blocks(
    std::vector<std::vector<types::global_dof_index>> &&dofs,
    std::vector<FullMatrix<double>>                   &&inverse_masses)
  {
    block_dofs     = std::move(dofs);
    block_inverses = std::move(inverse_masses);
  }

  void
  BlockAMGSolver::initialize(
    const TrilinosWrappers::SparseMatrix &K,
    const TrilinosWrappers::SparseMatrix &augmented,
    const std::vector<std::vector<bool>> &constant_modes,
    const bool                            higher_order)
  {
    matrix = &K;

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = higher_order;
    data.constant_modes        = constant_modes;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    amg.initialize(augmented, data);

    ++n_setups;
  }

  void
  BlockAMGSolver::vmult(TrilinosWrappers::MPI::Vector       &z,
                        const TrilinosWrappers::MPI::Vector &r) const
  {
    // z_u = A^-1 r_u (AMG on [A 0; 0 M_p/G] applied to [r_u; 0]).
    auto set_pressure_to_zero = [this](TrilinosWrappers::MPI::Vector &v) {
      for (const auto &dofs : block_dofs)
        for (const auto i : dofs)
          v[i] = 0;
      v.compress(VectorOperation::insert);
    };
    tmp = r;
    set_pressure_to_zero(tmp);
    amg.vmult(z, tmp);
    set_pressure_to_zero(z);
    // z_p = S^-1 (B z_u - r_p), with B z_u the pressure rows of K [z_u; 0].
    matrix->vmult(tmp, z);
    Vector<double> local, result;
    for (unsigned int b = 0; b < block_dofs.size(); ++b)
      {
        const auto &dofs = block_dofs[b];
        local.reinit(dofs.size());
        result.reinit(dofs.size());
        for (unsigned int k = 0; k < dofs.size(); ++k)
          local(k) = tmp[dofs[k]] - r[dofs[k]];
        block_inverses[b].vmult(result, local);
        for (unsigned int k = 0; k < dofs.size(); ++k)
          z[dofs[k]] = result(k);
      }
    z.compress(VectorOperation::insert);
  }

  void
  BlockAMGSolver::solve(const TrilinosWrappers::MPI::Vector &b,
                        TrilinosWrappers::MPI::Vector       &x)
  {
    Assert(matrix, ExcMessage("initialize() first"));
    ++n_solves;
    tmp.reinit(b, true);
    n_iterations +=
      gmres_solve(*matrix, *this, b, x, tolerance, max_iterations);
  }
} // namespace rollnip
