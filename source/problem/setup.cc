#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_dgp_nonparametric.h>
#include <deal.II/fe/fe_q.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/loading/pressure_load.h>
#include <rollnip/problem.h>
#include <rollnip/run_errors.h>

#include <cmath>

namespace rollnip
{
  RollProblem::RollProblem(const Parameters::AllParameters &parameters,
                           const MPI_Comm                   mpi_communicator)
      : parameters(parameters)
      , mpi_communicator(mpi_communicator)
      , pcout(std::cout,
              Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      , timer(mpi_communicator,
              pcout,
              parameters.output.print_timing ? TimerOutput::summary
                                             : TimerOutput::never,
              TimerOutput::wall_times)
      , triangulation(mpi_communicator)
      , material(parameters.material)
      , dof_handler(triangulation)
      , direct_solver(parameters.linear_solver.direct_solver)
      , iterative_solver(parameters.linear_solver.iterative_tolerance,
                         parameters.linear_solver.max_iterations)
      , output_directory(parameters.output.directory)
  {
    auto load =
      std::make_shared<PressureLoad>(parameters.load, parameters.geometry);
    pressure = [load](const double theta, const double lambda) {
      return lambda * load->value(theta);
    };
  }

  RollProblem::~RollProblem()
  {
    dof_handler.clear();
  }

  void
  RollProblem::set_pressure(std::function<double(double, double)> new_pressure)
  {
    pressure = std::move(new_pressure);
  }

  void
  RollProblem::set_solution(const TrilinosWrappers::MPI::Vector &owned)
  {
    solution                  = owned;
    locally_relevant_solution = solution;
  }

  void
  RollProblem::setup()
  {
    TimerOutput::Scope t(timer, "setup");
    if (parameters.nip_fitted_mesh())
      {
        // Fitted to the first nip angle, or provisionally (load and
        // indentation control fit it to every theta0 they try).
        const bool by_angle =
          parameters.contact.mode == Parameters::ContactMode::nip_angle;
        nip_mesh = std::make_unique<NipFittedMesh>(parameters);
        nip_mesh->build(triangulation,
                        by_angle ? parameters.contact.values[0]
                                 : 0.1 * parameters.geometry.sector_angle);
      }
    else
      make_roll_mesh(parameters, triangulation);

    const unsigned int degree = parameters.discretization.displacement_degree();
    mapping                   = std::make_unique<MappingQ<dim>>(degree);
    // On curved (non-affine) cells a mapped P1 cannot represent linear
    // functions; FE_DGPNonparametric can (doc/intro.md, section 3).
    if (degree == 1)
      fe =
        std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim, FE_DGP<dim>(0), 1);
    else
      fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(2),
                                           dim,
                                           FE_DGPNonparametric<dim>(1),
                                           1);
    dof_handler.distribute_dofs(*fe);

    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    pressure_dofs =
      DoFTools::extract_dofs(dof_handler, ComponentMask({false, false, true}));

    make_constraints();

    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    direct_solver.forget_pattern();
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    if (use_iterative_solver())
      {
        preconditioner_matrix.reinit(locally_owned_dofs,
                                     locally_owned_dofs,
                                     dsp,
                                     mpi_communicator);
        DoFTools::extract_constant_modes(dof_handler,
                                         fe->component_mask(
                                           FEValuesExtractors::Vector(0)),
                                         constant_modes);
        set_up_schur_blocks();
      }

    solution.reinit(locally_owned_dofs, mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    external_force.reinit(locally_owned_dofs, mpi_communicator);
    locally_relevant_solution.reinit(locally_owned_dofs,
                                     locally_relevant_dofs,
                                     mpi_communicator);

    domain_area = measure_area();

    pcout << "Mesh: " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " DoFs (" << fe->get_name() << "), "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI process(es)" << std::endl;
    if (parameters.contact.mode == Parameters::ContactMode::none &&
        parameters.boundary_conditions.condition[BoundaryIds::outer_arc] ==
          Parameters::BoundaryCondition::pressure)
      pcout << PressureLoad(parameters.load, parameters.geometry).describe()
            << std::endl;
  }

  double
  RollProblem::measure_area() const
  {
    double area = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        area += cell->measure();
    return Utilities::MPI::sum(area, mpi_communicator);
  }

  void
  RollProblem::fit_mesh_to_nip(const double theta0)
  {
    Assert(nip_mesh, ExcInternalError());
    TimerOutput::Scope t(timer, "setup");
    nip_mesh->fit(triangulation, theta0);
    domain_area = measure_area();
    if (use_iterative_solver())
      set_up_schur_blocks();
  }

  /**
   * G times the inverse of each cell's pressure mass matrix, for the Schur
   * complement of the gmres-amg solver (block_amg.h). The pressure is
   * discontinuous, so M_p is block diagonal; the reference volume is the
   * current one of an incompressible body.
   */
  void
  RollProblem::set_up_schur_blocks()
  {
    const unsigned int degree = parameters.discretization.displacement_degree();
    FEValues<dim>      fe_values(*mapping,
                            *fe,
                            QGauss<dim>(degree + 1),
                            update_values | update_JxW_values);
    const FEValuesExtractors::Scalar pressure_unknown(dim);
    std::vector<unsigned int>        local_p;
    for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
      if (fe->system_to_component_index(i).first == dim)
        local_p.push_back(i);
    const unsigned int n_p = local_p.size();

    std::vector<std::vector<types::global_dof_index>> blocks;
    std::vector<FullMatrix<double>>                   inverses;
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());
    FullMatrix<double>                   mass(n_p, n_p);
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
          inverse *= material.shear_modulus();
          blocks.push_back(std::move(block));
          inverses.push_back(std::move(inverse));
        }
    iterative_solver.set_schur_blocks(std::move(blocks), std::move(inverses));
  }

  /**
   * Homogeneous constraints only: fixed boundaries get u = 0, symmetry
   * boundaries u . n = 0 with n the edge normal known from the geometry
   * (the X2 = 0 line for id 2, the line at the sector angle for id 3).
   * Fixed wins where the two meet.
   */
  void
  RollProblem::make_constraints()
  {
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);

    const auto &bc = parameters.boundary_conditions.condition;
    const FEValuesExtractors::Vector displacement(0);
    for (types::boundary_id b = 0; b < BoundaryIds::n_boundaries; ++b)
      if (bc[b] == Parameters::BoundaryCondition::fixed)
        VectorTools::interpolate_boundary_values(
          *mapping,
          dof_handler,
          b,
          Functions::ZeroFunction<dim>(dim + 1),
          constraints,
          fe->component_mask(displacement));

    const double   alpha = parameters.geometry.sector_angle;
    Tensor<1, dim> normal[BoundaryIds::n_boundaries];
    normal[BoundaryIds::symmetry_edge] = Tensor<1, dim>({0., 1.});
    normal[BoundaryIds::far_edge] =
      Tensor<1, dim>({-std::sin(alpha), std::cos(alpha)});

    std::vector<types::global_dof_index> face_dofs(fe->n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const types::boundary_id b = cell->face(f)->boundary_id();
              if ((b != BoundaryIds::symmetry_edge &&
                   b != BoundaryIds::far_edge) ||
                  bc[b] != Parameters::BoundaryCondition::symmetry)
                continue;
              cell->face(f)->get_dof_indices(face_dofs);
              const Tensor<1, dim> &n = normal[b];
              // The dominant component is eliminated.
              const unsigned int c = std::abs(n[1]) >= std::abs(n[0]) ? 1 : 0;
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const auto ci = fe->face_system_to_component_index(i);
                  if (ci.first != c)
                    continue;
                  // The partner DoF of the other component at the same node.
                  for (unsigned int j = 0; j < face_dofs.size(); ++j)
                    {
                      const auto cj = fe->face_system_to_component_index(j);
                      if (cj.first != 1 - c || cj.second != ci.second)
                        continue;
                      const auto d = face_dofs[i];
                      if (constraints.is_constrained(d) ||
                          !locally_relevant_dofs.is_element(d))
                        break;
                      constraints.add_line(d);
                      const double ratio = -n[1 - c] / n[c];
                      if (std::abs(ratio) > 1e-14 &&
                          !constraints.is_constrained(face_dofs[j]))
                        constraints.add_entry(d, face_dofs[j], ratio);
                      break;
                    }
                }
            }
    constraints.close();
  }
} // namespace rollnip
