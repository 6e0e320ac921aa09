#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_dgp_nonparametric.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <rollnip/material/law_factory.h>
#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/core_tube.h>
#include <rollnip/three_d/slice_body.h>
#include <rollnip/three_d/slice_run.h>

#include <cmath>
#include <iostream>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// The displacement's element: FE_Q(degree).
      std::unique_ptr<FiniteElement<dim>>
      displacement_element(const unsigned int degree)
      {
        return std::make_unique<FE_Q<dim>>(degree);
      }

      /// The pressure's: P0, or P1 as in 2D nonparametric, which on the
      /// curved (non-affine) Q2 cells still holds the linear functions.
      std::unique_ptr<FiniteElement<dim>>
      pressure_element(const unsigned int degree)
      {
        if (degree == 1)
          return std::make_unique<FE_DGP<dim>>(0);
        return std::make_unique<FE_DGPNonparametric<dim>>(1);
      }

      /// Throws the one-line message of the first entry the 3D body cannot
      /// take: the contact mode, the theory, the supports and the core
      /// deflection's far edge (the elastic core's own checks are
      /// check_elastic_core()'s).
      void
      check_slice_scene(const Parameters::AllParameters &parameters,
                        const Parameters::ThreeD        &three_d)
      {
        using Mode      = Parameters::ContactMode;
        const Mode mode = parameters.contact.mode;
        AssertThrow(mode == Mode::indentation || mode == Mode::load,
                    ExcMessage("Three d: Contact/Mode must be indentation (the "
                               "approaches u0 are Contact/Values) or load (the "
                               "line loads P)"));
        AssertThrow(parameters.material.theory == Parameters::Theory::nonlinear,
                    ExcMessage("Three d: Material/Theory must be nonlinear"));
        using BC            = Parameters::BoundaryCondition;
        const auto  &bc     = parameters.boundary_conditions.condition;
        const double alpha  = parameters.geometry.sector_angle;
        const bool   ninety = std::abs(alpha - numbers::PI / 2) < 1e-12;
        const bool   half   = std::abs(alpha - numbers::PI) < 1e-12;
        AssertThrow(bc[SliceIds::inner_arc] == BC::fixed,
                    ExcMessage("Three d: Boundary conditions/Inner arc must "
                               "be fixed (the bonded core)"));
        AssertThrow(bc[SliceIds::far_edge] != BC::symmetry || ninety || half,
                    ExcMessage("Three d: Boundary conditions/Far edge = "
                               "symmetry needs a sector angle of 90 or "
                               "180 deg"));
        AssertThrow(bc[SliceIds::far_edge] == BC::fixed ||
                      bc[SliceIds::far_edge] == BC::symmetry ||
                      bc[SliceIds::far_edge] == BC::free,
                    ExcMessage("Three d: Boundary conditions/Far edge must "
                               "be fixed, free or symmetry"));
        // The core moves along x1: a fixed far edge, or the symmetry plane
        // x1 = 0 of a 90 deg sector, would hold the cover's edge against it.
        AssertThrow(CoreDeflection(three_d.core_deflection).is_zero() ||
                      bc[SliceIds::far_edge] == BC::free ||
                      (bc[SliceIds::far_edge] == BC::symmetry && half),
                    ExcMessage("Three d/Core deflection needs Boundary "
                               "conditions/Far edge = free, or symmetry with a "
                               "sector angle of 180 deg (the core moves along "
                               "x1)"));
        if (three_d.elastic_core)
          check_elastic_core(parameters, three_d);
      }

      /// The body's mesh at @p level into @p triangulation: the cover
      /// (make_slice_mesh()) or, with Core = elastic, the cover on the tube
      /// (make_core_tube_mesh(), whose planes are the cover's layers).
      AxialPlanes
      make_body_mesh(const Parameters::AllParameters           &parameters,
                     const Parameters::ThreeD                  &three_d,
                     const unsigned int                         level,
                     parallel::distributed::Triangulation<dim> &triangulation)
      {
        check_slice_scene(parameters, three_d);
        if (!three_d.elastic_core)
          return make_slice_mesh(parameters,
                                 level,
                                 three_d.slice_thickness,
                                 three_d.layers,
                                 triangulation,
                                 three_d.axial_grading);
        make_core_tube_mesh(parameters, three_d, level, triangulation);
        return {axial_planes(three_d.slice_thickness,
                             three_d.layers,
                             three_d.axial_grading),
                true};
      }

      Point<2>
      in_plane(const Point<dim> &x)
      {
        return Point<2>(x[0], x[1]);
      }

      /// The cell's pressure dofs (local indices).
      std::vector<unsigned int>
      pressure_dofs(const FESystem<dim> &fe)
      {
        std::vector<unsigned int> p;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (fe.system_to_component_index(i).first == dim)
            p.push_back(i);
        return p;
      }

      /// The augmented Lagrangian form of the cell's Newton system: every
      /// displacement row plus gamma B_K^T M_K^-1 times the cell's
      /// pressure rows (the linearised constraint, tested with the cell's
      /// discontinuous pressure functions, involves this cell alone), so
      /// that A becomes A + gamma B^T M_p^-1 B with the same solution.
      /// @p inverse_mass: M_K^-1 (1 / |cell| for P0, 4x4 for P1).
      void
      augment_cell_system(const FESystem<dim>      &fe,
                          const FullMatrix<double> &inverse_mass,
                          const double              gamma,
                          FullMatrix<double>       &K,
                          Vector<double>           &R)
      {
        if (gamma == 0)
          return;
        const unsigned int              n = fe.n_dofs_per_cell();
        const std::vector<unsigned int> p = pressure_dofs(fe);
        std::vector<double>             b(p.size());
        for (unsigned int i = 0; i < n; ++i)
          if (fe.system_to_component_index(i).first < dim)
            {
              // b = gamma M_K^-1 B_K(:, i), from row i before it changes.
              for (unsigned int a = 0; a < p.size(); ++a)
                {
                  b[a] = 0;
                  for (unsigned int c = 0; c < p.size(); ++c)
                    b[a] += gamma * inverse_mass(a, c) * K(i, p[c]);
                }
              // The pressure columns too: a compressible cover's K(p, p)
              // = -M_K / kappa.
              for (unsigned int a = 0; a < p.size(); ++a)
                {
                  for (unsigned int j = 0; j < n; ++j)
                    K(i, j) += b[a] * K(p[a], j);
                  R(i) += b[a] * R(p[a]);
                }
            }
      }

      /// The cell matrix of [A 0; 0 M_p/G'] for the AMG: the displacement
      /// block of @p K and the cell's pressure mass @p mass over G'.
      void
      make_augmented_cell_matrix(const FESystem<dim>      &fe,
                                 const FullMatrix<double> &K,
                                 const FullMatrix<double> &mass,
                                 const double              schur_modulus,
                                 FullMatrix<double>       &augmented)
      {
        const unsigned int              n = fe.n_dofs_per_cell();
        const std::vector<unsigned int> p = pressure_dofs(fe);
        augmented.reinit(n, n);
        for (unsigned int i = 0; i < n; ++i)
          if (fe.system_to_component_index(i).first < dim)
            for (unsigned int j = 0; j < n; ++j)
              if (fe.system_to_component_index(j).first < dim)
                augmented(i, j) = K(i, j);
        for (unsigned int a = 0; a < p.size(); ++a)
          for (unsigned int b = 0; b < p.size(); ++b)
            augmented(p[a], p[b]) = mass(a, b) / schur_modulus;
      }

      /// Adds the cell's tangent @p K and residual @p R of the mixed (u, q)
      /// form with @p law at the quadrature points of @p fv, where u has
      /// the gradients @p grad_u and q the values @p q; c(F, q) = J - 1 -
      /// q/kappa gives the pressure block -M_p/kappa. Returns the integral
      /// of c over the cell.
      double
      add_cell_terms(const FEValues<dim>               &fv,
                     const MaterialLaw<dim>            &law,
                     const std::vector<Tensor<2, dim>> &grad_u,
                     const std::vector<double>         &q,
                     FullMatrix<double>                &K,
                     Vector<double>                    &R)
      {
        const FEValuesExtractors::Vector u_ex(0);
        const FEValuesExtractors::Scalar q_ex(dim);
        const unsigned int               n = K.m();
        std::vector<Tensor<2, dim>>      grad_phi(n), dP(n);
        std::vector<double>              psi(n);
        const double                     compliance = law.pressure_compliance();
        double                           cell_constraint = 0;
        for (unsigned int k = 0; k < grad_u.size(); ++k)
          {
            const Tensor<2, dim> F   = unit_symmetric_tensor<dim>() + grad_u[k];
            const Tensor<2, dim> P   = law.piola(F, q[k]);
            const Tensor<2, dim> cof = law.pressure_direction(F);
            const double         g   = law.constraint(F) - compliance * q[k];
            const double         dx  = fv.JxW(k);
            cell_constraint += g * dx;
            for (unsigned int i = 0; i < n; ++i)
              {
                grad_phi[i] = fv[u_ex].gradient(i, k);
                psi[i]      = fv[q_ex].value(i, k);
                dP[i]       = law.piola_derivative(F, q[k], grad_phi[i]);
              }
            for (unsigned int i = 0; i < n; ++i)
              {
                R(i) += (scalar_product(P, grad_phi[i]) + psi[i] * g) * dx;
                const double cof_i = scalar_product(cof, grad_phi[i]);
                for (unsigned int j = 0; j < n; ++j)
                  K(i, j) +=
                    (scalar_product(dP[j], grad_phi[i]) + psi[j] * cof_i +
                     psi[i] * scalar_product(cof, grad_phi[j]) -
                     compliance * psi[i] * psi[j]) *
                    dx;
              }
          }
        return cell_constraint;
      }
    } // namespace

    SliceBody::SliceBody(const Parameters::AllParameters &parameters,
                         const Parameters::ThreeD        &three_d,
                         const unsigned int               level,
                         const MPI_Comm                   communicator)
        : communicator(communicator)
        , parameters(parameters)
        , three_d(three_d)
        , triangulation(communicator)
        , degree(parameters.discretization.displacement_degree())
        , mapping(std::make_unique<MappingQ<dim>>(degree))
        , fe(*displacement_element(degree), dim, *pressure_element(degree), 1)
        , dof_handler(triangulation)
        , law(make_layer_law<dim>(parameters.material,
                                  parameters.material.n_layers() - 1))
        , indenter(make_counter_surface(parameters.geometry.outer_radius,
                                        parameters.contact.indenter_radius))
        , iterative(parameters.linear_solver.method == "gmres-amg")
        , core(three_d.core_deflection)
    {
      for (unsigned int j = 0; j < parameters.material.n_layers(); ++j)
        layer_laws.emplace_back(make_layer_law<dim>(parameters.material, j));
      if (three_d.elastic_core)
        layer_laws.emplace_back(make_core_law(three_d));
      const AxialPlanes planes =
        make_body_mesh(parameters, three_d, level, triangulation);
      layer_planes = planes.z;
      layered      = planes.layered;
      if (iterative)
        for (const auto &cell_law : layer_laws)
          augmentation.push_back(cell_augmentation(*cell_law));
      // c of the active-set rule, a pressure per mm of gap of the order of
      // the cover's stiffness G / h; any c > 0 gives the same converged set.
      active_set_scale =
        law->shear_modulus() /
        (parameters.geometry.outer_radius - parameters.geometry.inner_radius);
      setup_system();
      collect_surface_nodes();
      collect_bonded_nodes();
      collect_surface_faces();
    }

    void
    SliceBody::setup_system()
    {
      dof_handler.distribute_dofs(fe);
      owned    = dof_handler.locally_owned_dofs();
      relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);
      // Contact constraints couple the dofs of one node only, so the
      // pattern without constraints holds every condensed entry.
      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(dof_handler, dsp);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 communicator,
                                                 relevant);
      system_matrix.reinit(owned, owned, dsp, communicator);
      solution.reinit(owned, relevant, communicator);
      reactions.reinit(owned, relevant, communicator);
      system_rhs.reinit(owned, communicator);
      if (iterative)
        {
          preconditioner_matrix.reinit(owned, owned, dsp, communicator);
          block_amg = std::make_unique<SliceBlockSolver>(
            parameters.linear_solver.iterative_tolerance,
            parameters.linear_solver.max_iterations);
          std::vector<double> schur_modulus;
          for (const CellAugmentation &a : augmentation)
            schur_modulus.push_back(a.schur_modulus);
          block_amg->setup(*mapping, dof_handler, schur_modulus);
        }
      else
        direct = std::make_unique<SparseDirectSolver>(
          parameters.linear_solver.direct_solver);
    }

    void
    SliceBody::collect_surface_nodes()
    {
      surface = boundary_nodes(SliceIds::outer_arc);
      const TrilinosWrappers::MPI::Vector weight =
        lumped_areas(SliceIds::outer_arc, false);
      for (auto &[x_dof, node] : surface)
        node.weight = weight[x_dof];
    }

    Point<dim>
    SliceBody::deformed(const SurfaceNode &node) const
    {
      Point<dim> x = node.X;
      for (unsigned int c = 0; c < dim; ++c)
        x[c] += solution[node.dofs[c]];
      return x;
    }

    double
    SliceBody::gap(const SurfaceNode &node, const double u0) const
    {
      return indenter->gap(in_plane(deformed(node)), u0);
    }

    Tensor<1, dim>
    SliceBody::gap_normal(const SurfaceNode &node, const double u0) const
    {
      const Tensor<1, 2> n2 =
        indenter->gap_gradient(in_plane(deformed(node)), u0);
      Tensor<1, dim> n;
      n[0] = n2[0];
      n[1] = n2[1];
      return n;
    }

    void
    SliceBody::assemble()
    {
      system_matrix = 0;
      system_rhs    = 0;
      if (iterative)
        preconditioner_matrix = 0;
      TrilinosWrappers::MPI::Vector raw(owned, communicator),
        condensed(owned, communicator);
      const QGauss<dim>                    quadrature(degree + 1);
      FEValues<dim>                        fv(*mapping,
                       fe,
                       quadrature,
                       update_gradients | update_values | update_JxW_values);
      const unsigned int                   n = fe.n_dofs_per_cell();
      const FEValuesExtractors::Vector     u_ex(0);
      const FEValuesExtractors::Scalar     q_ex(dim);
      FullMatrix<double>                   K(n, n), K_amg;
      Vector<double>                       R(n), R_u(n);
      std::vector<types::global_dof_index> dofs(n);
      std::vector<Tensor<2, dim>>          grad_u(quadrature.size());
      std::vector<double>                  q(quadrature.size());
      double                               constraint_error = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            K = 0;
            R = 0;
            fv[u_ex].get_function_gradients(solution, grad_u);
            fv[q_ex].get_function_values(solution, q);
            const double cell_constraint = add_cell_terms(
              fv, *layer_laws[cell->material_id()], grad_u, q, K, R);
            constraint_error += std::abs(cell_constraint);
            cell->get_dof_indices(dofs);
            // The displacement rows only: reactions and their norm.
            for (unsigned int i = 0; i < n; ++i)
              R_u(i) = fe.system_to_component_index(i).first < dim ? R(i) : 0.;
            raw.add(dofs, R_u);
            homogeneous_constraints.distribute_local_to_global(R_u,
                                                               dofs,
                                                               condensed);
            FullMatrix<double>     mass, inverse_mass;
            const CellAugmentation cell_aug =
              iterative ? augmentation[cell->material_id()]
                        : CellAugmentation{0., 0.};
            if (iterative)
              {
                mass = cell_pressure_mass(fv);
                inverse_mass.reinit(mass.m(), mass.n());
                inverse_mass.invert(mass);
                augment_cell_system(fe, inverse_mass, cell_aug.gamma, K, R);
              }
            R *= -1.;
            constraints.distribute_local_to_global(
              K, R, dofs, system_matrix, system_rhs, true);
            if (iterative)
              {
                make_augmented_cell_matrix(
                  fe, K, mass, cell_aug.schur_modulus, K_amg);
                constraints.distribute_local_to_global(K_amg,
                                                       dofs,
                                                       preconditioner_matrix);
              }
          }
      system_matrix.compress(VectorOperation::add);
      if (iterative)
        preconditioner_matrix.compress(VectorOperation::add);
      system_rhs.compress(VectorOperation::add);
      raw.compress(VectorOperation::add);
      condensed.compress(VectorOperation::add);
      reactions = raw;
      residual_u =
        condensed.l2_norm() /
        std::max(raw.l2_norm(),
                 1e-8 * law->shear_modulus() *
                   parameters.geometry.outer_radius * three_d.slice_thickness);
      residual_q = Utilities::MPI::sum(constraint_error, communicator) /
                   GridTools::volume(triangulation);
    }

    int
    validate_slice_body(const Parameters::AllParameters &parameters,
                        const Parameters::ThreeD        &three_d,
                        const std::string               &file,
                        const MPI_Comm                   communicator)
    {
      // The mesh and its DoFs, not the matrix: cheap at any size.
      parallel::distributed::Triangulation<dim> triangulation(communicator);
      make_body_mesh(parameters,
                     three_d,
                     parameters.mesh.global_refinements,
                     triangulation);
      const unsigned int degree =
        parameters.discretization.displacement_degree();
      const FESystem<dim> fe(*displacement_element(degree),
                             dim,
                             *pressure_element(degree),
                             1);
      DoFHandler<dim>     dofs(triangulation);
      dofs.distribute_dofs(fe);
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        std::cout << "3D body: " << triangulation.n_global_active_cells()
                  << " cells, " << dofs.n_dofs() << " DoFs (" << fe.get_name()
                  << "), " << Utilities::MPI::n_mpi_processes(communicator)
                  << " MPI process(es)" << std::endl
                  << "rollnip: '" << file << "' is valid" << std::endl;
      return 0;
    }
  } // namespace three_d
} // namespace rollnip
