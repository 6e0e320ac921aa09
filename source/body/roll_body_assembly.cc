#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/grid/filtered_iterator.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/fe_fields.h>
#include <rollnip/kinematics.h>

#include <cmath>

namespace rollnip
{
  namespace
  {
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /// Per-thread FEValues and work arrays of the cell integrals.
    struct AssemblyScratch
    {
      AssemblyScratch(const Mapping<dim>                &mapping,
                      const FiniteElement<dim>          &fe,
                      const Quadrature<dim>             &quadrature,
                      std::unique_ptr<FEFaceValues<dim>> face_values)
          : fe_values(mapping,
                      fe,
                      quadrature,
                      update_values | update_gradients | update_JxW_values)
          , fe_face_values(std::move(face_values))
          , grad_u(quadrature.size())
          , q_values(quadrature.size())
          , grad_phi(fe.n_dofs_per_cell())
          , psi(fe.n_dofs_per_cell())
          , dP(fe.n_dofs_per_cell())
          , dc(fe.n_dofs_per_cell())
          , component(fe.n_dofs_per_cell())
      {
        for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
          component[k] = fe.system_to_component_index(k).first;
      }

      // WorkStream copies the scratch object once per thread.
      AssemblyScratch(const AssemblyScratch &other)
          : AssemblyScratch(other.fe_values.get_mapping(),
                            other.fe_values.get_fe(),
                            other.fe_values.get_quadrature(),
                            std::make_unique<FEFaceValues<dim>>(
                              other.fe_face_values->get_mapping(),
                              other.fe_face_values->get_fe(),
                              other.fe_face_values->get_quadrature(),
                              other.fe_face_values->get_update_flags()))
      {}

      FEValues<dim>                      fe_values;
      std::unique_ptr<FEFaceValues<dim>> fe_face_values;
      std::vector<Tensor<2, dim>>        grad_u;
      std::vector<double>                q_values;
      std::vector<Tensor<2, dim>>        grad_phi;
      std::vector<double>                psi;
      std::vector<Tensor<2, dim>>        dP;
      std::vector<double>                dc; ///< dP/dq : Grad phi_k
      /// The vector component of each shape function: the pressure's, or the
      /// one row of its (primitive) gradient.
      std::vector<unsigned int>   component;
      std::vector<Tensor<2, dim>> face_grad_u;
    };

    /// One cell's contributions, handed to the (serial) copier.
    struct AssemblyCopy
    {
      explicit AssemblyCopy(const unsigned int n_dofs)
          : cell_matrix(n_dofs, n_dofs)
          , cell_rhs(n_dofs)
          , cell_load(n_dofs)
          , dof_indices(n_dofs)
          , pressure_mass(n_dofs)
      {}

      void
      reset()
      {
        cell_matrix   = 0;
        cell_rhs      = 0;
        cell_load     = 0;
        pressure_mass = 0;
        min_J         = std::numeric_limits<double>::max();
      }

      FullMatrix<double>                   cell_matrix;
      Vector<double>                       cell_rhs;
      Vector<double>                       cell_load;
      std::vector<types::global_dof_index> dof_indices;
      Vector<double>     pressure_mass; ///< diagonal of int psi_i psi_j dV
      FullMatrix<double> preconditioner_matrix; ///< [A 0; 0 M_p/G], cell
      double             min_J = 0;
    };

    /**
     * The volume part of the residual of the mixed problem (doc/intro.md,
     * eq. 3.1), R_u = int P(F, q) : Grad v dV, R_q = int w c(F, q) dV with
     * c = (J - 1) - q/kappa (1/kappa = 0: incompressible), and of its
     * tangent, on one cell.
     */
    void
    add_cell_terms(const MaterialLaw<dim>              &material,
                   const TrilinosWrappers::MPI::Vector &solution,
                   const bool                           with_matrix,
                   AssemblyScratch                     &scratch,
                   AssemblyCopy                        &copy)
    {
      using FEFields::displacement;
      const auto          &pressure_unknown = FEFields::pressure;
      const FEValues<dim> &fe_values        = scratch.fe_values;
      const double         compliance       = material.pressure_compliance();
      const unsigned int   n_dofs           = copy.dof_indices.size();
      const Tensor<2, dim> I                = unit_symmetric_tensor<dim>();
      auto                &grad_phi = scratch.grad_phi, &dP = scratch.dP;
      auto                &psi = scratch.psi;
      fe_values[displacement].get_function_gradients(solution, scratch.grad_u);
      fe_values[pressure_unknown].get_function_values(solution,
                                                      scratch.q_values);
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          const Tensor<2, dim> F     = I + scratch.grad_u[q];
          copy.min_J                 = std::min(copy.min_J, determinant(F));
          const double         p     = scratch.q_values[q];
          const Tensor<2, dim> P     = material.piola(F, p);
          const Tensor<2, dim> dP_dq = material.pressure_direction(F);
          const double         g     = material.constraint(F) - compliance * p;
          const double         JxW   = fe_values.JxW(q);
          for (unsigned int k = 0; k < n_dofs; ++k)
            {
              grad_phi[k] = fe_values[displacement].gradient(k, q);
              psi[k]      = fe_values[pressure_unknown].value(k, q);
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              copy.cell_rhs(i) +=
                (scalar_product(P, grad_phi[i]) + psi[i] * g) * JxW;
              copy.pressure_mass(i) += psi[i] * psi[i] * JxW;
            }
          if (!with_matrix)
            continue;
          // dP[dF] is linear in dF: the law is called once per entry of
          // dF, not once per shape function. Each displacement shape
          // function's gradient has one nonzero row (its component); a
          // pressure one has none, and psi vanishes on the others.
          Tensor<2, dim> dP_dF[dim][dim];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              {
                Tensor<2, dim> E;
                E[a][b]     = 1;
                dP_dF[a][b] = material.piola_derivative(F, p, E);
              }
          for (unsigned int j = 0; j < n_dofs; ++j)
            {
              const unsigned int c = scratch.component[j];
              dP[j]                = Tensor<2, dim>();
              scratch.dc[j]        = 0;
              if (c == FEFields::pressure_component)
                continue;
              for (unsigned int b = 0; b < dim; ++b)
                dP[j] += grad_phi[j][c][b] * dP_dF[c][b];
              scratch.dc[j] = dP_dq[c] * grad_phi[j][c];
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const unsigned int ci = scratch.component[i];
              if (ci == FEFields::pressure_component)
                {
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    copy.cell_matrix(i, j) += psi[i] * scratch.dc[j] * JxW;
                  continue;
                }
              const Tensor<1, dim> g_i = grad_phi[i][ci] * JxW;
              const double         d_i = scratch.dc[i] * JxW;
              for (unsigned int j = 0; j < n_dofs; ++j)
                copy.cell_matrix(i, j) +=
                  scratch.component[j] == FEFields::pressure_component
                    ? d_i * psi[j]
                    : dP[j][ci] * g_i;
            }
          if (compliance != 0)
            for (unsigned int i = 0; i < n_dofs; ++i)
              for (unsigned int j = 0; j < n_dofs; ++j)
                copy.cell_matrix(i, j) -= compliance * psi[i] * psi[j] * JxW;
        }
    }

    /// The scale s of the pressure block M_p / s of the preconditioner:
    /// the Schur complement B A^-1 B^T + M_p/kappa is about M_p (1/G +
    /// 1/kappa), so s = G when incompressible (kept exactly so).
    double
    schur_scale(const MaterialLaw<dim> &material)
    {
      const double G = material.shear_modulus();
      const double c = material.pressure_compliance();
      return c == 0 ? G : 1. / (1. / G + c);
    }

    /**
     * The follower load on the loaded faces of one cell: h dA = -f cof(F) N
     * dA (eq. 4.1). cof F is linear in F in 2D, so its derivative
     * d(h dA)[du] = -f cof(Grad du) N dA is exact (and not symmetric); in
     * linear theory the load does not depend on u.
     */
    void
    add_face_terms(const FollowerLoad                  &load,
                   const CellIterator                  &cell,
                   const TrilinosWrappers::MPI::Vector &solution,
                   const double                         lambda,
                   const bool                           with_matrix,
                   AssemblyScratch                     &scratch,
                   AssemblyCopy                        &copy)
    {
      using FEFields::displacement;
      FEFaceValues<dim> &fv     = *scratch.fe_face_values;
      const unsigned int n_dofs = copy.dof_indices.size();
      load.for_each_point(
        cell,
        fv,
        solution,
        scratch.face_grad_u,
        [&](const unsigned int    q,
            const double          theta,
            const Tensor<2, dim> &grad_u,
            const Tensor<1, dim> &N,
            const double          JxW) {
          const double f = load.value(theta, lambda);
          // Traction per reference area, pointing into the body.
          const Tensor<1, dim> h = -f * load.current_area_normal(grad_u, N);
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const Tensor<1, dim> phi_i  = fv[displacement].value(i, q);
              const double         load_i = h * phi_i * JxW;
              copy.cell_rhs(i) -= load_i;
              copy.cell_load(i) += load_i;
              if (!with_matrix || load.is_linear())
                continue;
              for (unsigned int j = 0; j < n_dofs; ++j)
                copy.cell_matrix(i, j) +=
                  f * (cofactor(fv[displacement].gradient(j, q)) * N) * phi_i *
                  JxW;
            }
        });
    }

    /// The cell matrix of [A 0; 0 M_p/G]: the displacement block of the
    /// tangent and the lumped pressure mass over the cell's G (over
    /// schur_scale() for a compressible law).
    void
    make_preconditioner_block(const FiniteElement<dim> &fe,
                              const double              G,
                              AssemblyCopy             &copy)
    {
      const unsigned int n_dofs = copy.dof_indices.size();
      copy.preconditioner_matrix.reinit(n_dofs, n_dofs);
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          if (FEFields::is_pressure(fe, i))
            {
              copy.preconditioner_matrix(i, i) = copy.pressure_mass(i) / G;
              continue;
            }
          for (unsigned int j = 0; j < n_dofs; ++j)
            if (!FEFields::is_pressure(fe, j))
              copy.preconditioner_matrix(i, j) = copy.cell_matrix(i, j);
        }
    }
  } // namespace

  /**
   * The residual and tangent of the mixed problem: cell terms, follower
   * load, and the AMG's preconditioner matrix. The cell integrals run on
   * all threads deal.II was given (WorkStream); adding them into the
   * Trilinos objects is serial, in the copier.
   */
  double
  RollBody::assemble(const double load_fraction, const bool with_matrix)
  {
    TimerOutput::Scope t(timer,
                         with_matrix ? "assembly" : "assembly (residual)");
    ++assembly_count;
    const bool preconditioner = with_matrix && with_preconditioner;

    auto cell_worker = [&](const CellIterator &cell,
                           AssemblyScratch    &scratch,
                           AssemblyCopy       &copy) {
      const ScaledLaw<dim> material = material_table.law(*cell);
      scratch.fe_values.reinit(cell);
      copy.reset();
      add_cell_terms(
        material, locally_relevant_solution, with_matrix, scratch, copy);
      add_face_terms(follower_load,
                     cell,
                     locally_relevant_solution,
                     load_fraction,
                     with_matrix,
                     scratch,
                     copy);
      cell->get_dof_indices(copy.dof_indices);
      if (preconditioner)
        make_preconditioner_block(*element, schur_scale(material), copy);
    };

    double min_J  = std::numeric_limits<double>::max();
    auto   copier = [&](const AssemblyCopy &copy) {
      const auto &c = boundary_constraints;
      min_J         = std::min(min_J, copy.min_J);
      if (with_matrix)
        c.distribute_local_to_global(copy.cell_matrix,
                                     copy.cell_rhs,
                                     copy.dof_indices,
                                     system_matrix,
                                     system_rhs);
      else
        c.distribute_local_to_global(copy.cell_rhs,
                                     copy.dof_indices,
                                     system_rhs);
      c.distribute_local_to_global(copy.cell_load,
                                   copy.dof_indices,
                                   load_vector);
      if (preconditioner)
        c.distribute_local_to_global(copy.preconditioner_matrix,
                                     copy.dof_indices,
                                     preconditioner_matrix);
    };

    if (with_matrix)
      system_matrix = 0;
    if (preconditioner)
      preconditioner_matrix = 0;
    system_rhs  = 0;
    load_vector = 0;

    using CellFilter = FilteredIterator<CellIterator>;
    WorkStream::run(
      CellFilter(IteratorFilters::LocallyOwnedCell(),
                 dof_handler.begin_active()),
      CellFilter(IteratorFilters::LocallyOwnedCell(), dof_handler.end()),
      cell_worker,
      copier,
      AssemblyScratch(*cell_mapping,
                      *element,
                      FEFields::cell_quadrature(*element),
                      follower_load.make_face_values(*cell_mapping, *element)),
      AssemblyCopy(element->n_dofs_per_cell()));

    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    if (preconditioner)
      preconditioner_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    load_vector.compress(VectorOperation::add);
    return Utilities::MPI::min(min_J, mpi_communicator);
  }

  /**
   * From (4.1): int g (cof F N) . v dA (N dA in linear theory). The
   * contact iteration uses these as right-hand sides for the sensitivities
   * of the surface position to the parameters of the pressure.
   */
  TrilinosWrappers::MPI::Vector
  RollBody::pressure_load_derivative(
    const std::function<double(double)> &g) const
  {
    const auto face_values =
      follower_load.make_face_values(*cell_mapping, *element);
    using FEFields::displacement;
    const unsigned int                   n_dofs = element->n_dofs_per_cell();
    Vector<double>                       cell_vector(n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);
    std::vector<Tensor<2, dim>>          grad_u;
    TrilinosWrappers::MPI::Vector result(locally_owned_dofs, mpi_communicator);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_vector  = 0;
          bool touched = false;
          follower_load.for_each_point(
            cell,
            *face_values,
            locally_relevant_solution,
            grad_u,
            [&](const unsigned int    q,
                const double          theta,
                const Tensor<2, dim> &grad_u_q,
                const Tensor<1, dim> &N,
                const double          JxW) {
              const double gq = g(theta);
              if (gq == 0)
                return;
              touched = true;
              const Tensor<1, dim> nda =
                follower_load.current_area_normal(grad_u_q, N);
              for (unsigned int i = 0; i < n_dofs; ++i)
                cell_vector(i) +=
                  gq * nda * (*face_values)[displacement].value(i, q) * JxW;
            });
          if (!touched)
            continue;
          cell->get_dof_indices(dof_indices);
          boundary_constraints.distribute_local_to_global(cell_vector,
                                                          dof_indices,
                                                          result);
        }
    result.compress(VectorOperation::add);
    return result;
  }

  /**
   * The pressure is discontinuous, so M_p is block diagonal; the reference
   * volume is the current one of an incompressible body. G is the cell's.
   */
  void
  RollBody::pressure_mass_inverses(
    std::vector<std::vector<types::global_dof_index>> &blocks,
    std::vector<FullMatrix<double>>                   &inverses) const
  {
    FEValues<dim>             fe_values(*cell_mapping,
                            *element,
                            FEFields::cell_quadrature(*element),
                            update_values | update_JxW_values);
    const auto               &pressure_unknown = FEFields::pressure;
    std::vector<unsigned int> local_p;
    for (unsigned int i = 0; i < element->n_dofs_per_cell(); ++i)
      if (FEFields::is_pressure(*element, i))
        local_p.push_back(i);
    const unsigned int n_p = local_p.size();

    std::vector<types::global_dof_index> dof_indices(
      element->n_dofs_per_cell());
    FullMatrix<double> mass(n_p, n_p);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          mass = 0;
          for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
            for (unsigned int a = 0; a < n_p; ++a)
              for (unsigned int b = 0; b < n_p; ++b)
                mass(a, b) += fe_values[pressure_unknown].value(local_p[a], q) *
                              fe_values[pressure_unknown].value(local_p[b], q) *
                              fe_values.JxW(q);
          cell->get_dof_indices(dof_indices);
          std::vector<types::global_dof_index> block;
          for (const auto a : local_p)
            block.push_back(dof_indices[a]);
          FullMatrix<double> inverse(n_p, n_p);
          inverse.invert(mass);
          inverse *= schur_scale(material_table.law(*cell));
          blocks.push_back(std::move(block));
          inverses.push_back(std::move(inverse));
        }
  }
} // namespace rollnip
