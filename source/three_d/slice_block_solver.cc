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

    FullMatrix<double>
    cell_pressure_mass(const FEValues<dim> &fv)
    {
      const auto               &fe = fv.get_fe();
      std::vector<unsigned int> p;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (fe.system_to_component_index(i).first == dim)
          p.push_back(i);
      FullMatrix<double> M(p.size(), p.size());
      for (unsigned int k = 0; k < fv.n_quadrature_points; ++k)
        for (unsigned int a = 0; a < p.size(); ++a)
          for (unsigned int b = 0; b < p.size(); ++b)
            M(a, b) += fv.shape_value_component(p[a], k, dim) *
                       fv.shape_value_component(p[b], k, dim) * fv.JxW(k);
      return M;
    }

    CellAugmentation
    cell_augmentation(const MaterialLaw<dim> &law)
    {
      const double G     = law.shear_modulus();
      const double c     = law.pressure_compliance(); // 1 / kappa
      const double gamma = 10. * G;
      if (c > 0 && c * gamma >= 1.)
        return {1. / c, 1. / c};
      return {gamma, (G + gamma) / (1. + G * c)};
    }

    void
    SliceBlockSolver::setup(const Mapping<dim>        &mapping,
                            const DoFHandler<dim>     &dof_handler,
                            const std::vector<double> &schur_modulus)
    {
      fresh_iterations = last_iterations = 0;
      std::vector<bool> u_components(dim + 1, true);
      u_components[dim] = false;
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(u_components),
                                       constant_modes);
      collect_rigid_modes(mapping, dof_handler);
      collect_schur_blocks(mapping, dof_handler, schur_modulus);
    }

    void
    SliceBlockSolver::collect_rigid_modes(const Mapping<dim>    &mapping,
                                          const DoFHandler<dim> &dof_handler)
    {
      // Every owned dof lies on an owned cell; with Q2 the edge, face and
      // cell nodes sit on the mapped (curved) cell, where the dofs live.
      const IndexSet       &owned   = dof_handler.locally_owned_dofs();
      const auto           &fe      = dof_handler.get_fe();
      const unsigned int    n_owned = owned.n_elements();
      const Quadrature<dim> support(
        fe.base_element(0).get_unit_support_points());
      FEValues<dim> fv(mapping, fe, support, update_quadrature_points);
      rigid_modes.assign(2 * dim * n_owned, 0.);
      displacement_mask.reinit(owned, dof_handler.get_communicator());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const auto [c, k] = fe.system_to_component_index(i);
                if (c >= dim || !owned.is_element(dofs[i]))
                  continue;
                displacement_mask[dofs[i]] = 1.;
                const auto row             = owned.index_within_set(dofs[i]);
                for (unsigned int m = 0; m < 2 * dim; ++m)
                  rigid_modes[m * n_owned + row] =
                    rigid_mode(m, c, fv.quadrature_point(k));
              }
          }
      displacement_mask.compress(VectorOperation::insert);
    }

    void
    SliceBlockSolver::collect_schur_blocks(
      const Mapping<dim>        &mapping,
      const DoFHandler<dim>     &dof_handler,
      const std::vector<double> &schur_modulus)
    {
      // The element's quadrature, so that M_K is the mass matrix of the
      // augmentation (SliceBody::assemble()) and exact for P1 x P1 on
      // the cell. The reference volume is the current one of an
      // incompressible body.
      const IndexSet   &owned = dof_handler.locally_owned_dofs();
      const auto       &fe    = dof_handler.get_fe();
      const QGauss<dim> quadrature(fe.base_element(0).degree + 1);
      FEValues<dim>     fv(mapping,
                       fe,
                       quadrature,
                       update_values | update_JxW_values);
      n_pressure = fe.base_element(1).n_dofs_per_cell();
      schur_rows.clear();
      schur_blocks.clear();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              if (fe.system_to_component_index(i).first == dim)
                schur_rows.push_back(owned.index_within_set(dofs[i]));
            FullMatrix<double> inverse = cell_pressure_mass(fv);
            inverse.gauss_jordan();
            const double modulus = schur_modulus.at(cell->material_id());
            for (unsigned int a = 0; a < n_pressure; ++a)
              for (unsigned int b = 0; b < n_pressure; ++b)
                schur_blocks.push_back(modulus * inverse(a, b));
          }
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
      // Four symmetric Gauss-Seidel sweeps. On a roll's face the axial
      // layers are up to 50 times as long as the radial cells are thick;
      // there the Chebyshev-Jacobi smoother left GMRES above 500
      // iterations per solve, and Gauss-Seidel, which relaxes each node
      // with its neighbours' updated values, takes 2 to 3 times fewer.
      data.smoother_type         = "symmetric Gauss-Seidel";
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
      // z_p = S^-1 (B z_u - r_p), B z_u the pressure rows of K [z_u; 0],
      // cell by cell on the locally owned rows (a cell's pressure dofs
      // are owned with it).
      matrix->vmult(tmp, z);
      tmp -= r;
      const double *t     = tmp.begin();
      double       *z_own = z.begin();
      const double *block = schur_blocks.data();
      for (std::size_t first = 0; first < schur_rows.size();
           first += n_pressure, block += n_pressure * n_pressure)
        for (unsigned int a = 0; a < n_pressure; ++a)
          {
            double value = 0;
            for (unsigned int b = 0; b < n_pressure; ++b)
              value += block[a * n_pressure + b] * t[schur_rows[first + b]];
            z_own[schur_rows[first + a]] = value;
          }
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
