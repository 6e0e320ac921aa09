#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_values.h>

#include <rollnip/solvers/gmres_solve.h>
#include <rollnip/three_d/slice_block_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>


namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// Component @p c at point @p x of rigid-body mode @p m: translations
      /// along x, y, z, then rotations about the x, y and z axes.
      double
      rigid_mode(const unsigned int m,
                 const unsigned int c,
                 const Point<dim>  &x)
      {
        if (m < dim)
          return m == c ? 1. : 0.;
        const unsigned int a = m - dim; // e_a x X
        const unsigned int b = (a + 1) % dim, d = (a + 2) % dim;
        if (c == d)
          return x[b];
        if (c == b)
          return -x[d];
        return 0.;
      }
    } // namespace

    SliceBlockSolver::SliceBlockSolver(const double       tolerance,
                                       const unsigned int max_iterations)
        : tolerance(tolerance)
        , max_iterations(max_iterations)
    {}

    void
    SliceBlockSolver::setup(const DoFHandler<dim> &dof_handler,
                            const double           schur_modulus)
    {
      fresh_iterations = last_iterations = 0;
      const IndexSet   &owned            = dof_handler.locally_owned_dofs();
      const MPI_Comm    communicator     = dof_handler.get_communicator();
      const auto       &fe               = dof_handler.get_fe();
      std::vector<bool> u_components(dim + 1, true);
      u_components[dim] = false;
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(u_components),
                                       constant_modes);
      const unsigned int n_owned = owned.n_elements();
      rigid_modes.assign(2 * dim * n_owned, 0.);
      schur_diagonal.reinit(owned, communicator);
      displacement_mask.reinit(owned, communicator);
      // M_p of the P0 pressure is |cell| (the reference volume is the
      // current one of an incompressible body).
      const QGauss<dim>  quadrature(2);
      FEValues<dim>      fv(fe, quadrature, update_JxW_values);
      const unsigned int p_local = fe.component_to_system_index(dim, 0);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            double volume = 0;
            for (unsigned int k = 0; k < quadrature.size(); ++k)
              volume += fv.JxW(k);
            cell->get_dof_indices(dofs);
            schur_diagonal[dofs[p_local]] = schur_modulus / volume;
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const auto dof = cell->vertex_dof_index(v, c);
                  if (!owned.is_element(dof))
                    continue;
                  displacement_mask[dof] = 1.;
                  const auto row         = owned.index_within_set(dof);
                  for (unsigned int m = 0; m < 2 * dim; ++m)
                    rigid_modes[m * n_owned + row] =
                      rigid_mode(m, c, cell->vertex(v));
                }
          }
      schur_diagonal.compress(VectorOperation::insert);
      displacement_mask.compress(VectorOperation::insert);
    }

    void
    SliceBlockSolver::initialize(
      const TrilinosWrappers::SparseMatrix &K,
      const TrilinosWrappers::SparseMatrix &augmented)
    {
      matrix           = &K;
      augmented_matrix = &augmented;
      if (reuse())
        return;
      build_hierarchy();
    }

    void
    SliceBlockSolver::build_hierarchy()
    {
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic       = true;
      data.constant_modes = constant_modes;
      // Four Chebyshev sweeps: half the GMRES iterations of two on the
      // augmented A of the slice, for less than twice the V-cycle's work.
      data.smoother_sweeps       = 4;
      data.aggregation_threshold = 0.02;
      Teuchos::ParameterList              list;
      std::unique_ptr<Epetra_MultiVector> constant;
      data.set_parameters(list, constant, *augmented_matrix);
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", static_cast<int>(2 * dim));
      list.set("null space: vectors", rigid_modes.data());
      amg.initialize(*augmented_matrix, list);
      ++n_setups;
      fresh_iterations = last_iterations = 0;
    }

    bool
    SliceBlockSolver::reuse() const
    {
      return fresh_iterations > 0 &&
             2 * last_iterations <= 3 * fresh_iterations;
    }

    void
    SliceBlockSolver::vmult(TrilinosWrappers::MPI::Vector       &z,
                            const TrilinosWrappers::MPI::Vector &r) const
    {
      // z_u = A^-1 r_u: the AMG on [A 0; 0 M_p/G] applied to [r_u; 0].
      tmp = r;
      tmp.scale(displacement_mask);
      amg.vmult(z, tmp);
      z.scale(displacement_mask);
      // z_p = S^-1 (B z_u - r_p), B z_u the pressure rows of K [z_u; 0].
      matrix->vmult(tmp, z);
      tmp -= r;
      tmp.scale(schur_diagonal);
      z += tmp;
    }

    void
    SliceBlockSolver::solve(const TrilinosWrappers::MPI::Vector &b,
                            TrilinosWrappers::MPI::Vector       &x)
    {
      Assert(matrix, ExcMessage("initialize() first"));
      tmp.reinit(b, true);
      try
        {
          last_iterations =
            gmres_solve(*matrix, *this, b, x, tolerance, max_iterations);
        }
      catch (const ExceptionBase &)
        {
          // A kept hierarchy that no longer suffices: one fresh try.
          if (fresh_iterations == 0)
            throw;
          build_hierarchy();
          last_iterations =
            gmres_solve(*matrix, *this, b, x, tolerance, max_iterations);
        }
      if (fresh_iterations == 0)
        fresh_iterations = last_iterations;
      n_iterations += last_iterations;
    }
  } // namespace three_d
} // namespace rollnip
