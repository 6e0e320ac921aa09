#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_dgp_nonparametric.h>
#include <deal.II/fe/fe_q.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <rollnip/body/roll_body.h>
#include <rollnip/boundary_ids.h>
#include <rollnip/fe_fields.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/loading/applied_load.h>

#include <cmath>

namespace rollnip
{
  RollBody::RollBody(const Parameters::AllParameters &parameters,
                     const MPI_Comm                   mpi_communicator,
                     TimerOutput                     &timer)
      : parameters(parameters)
      , mpi_communicator(mpi_communicator)
      , timer(timer)
      , with_preconditioner(parameters.linear_solver.method == "gmres-amg")
      , triangulation(mpi_communicator)
      , material_table(parameters.material)
      , follower_load(parameters, material_table.is_linear())
      , dof_handler(triangulation)
  {}

  RollBody::~RollBody()
  {
    dof_handler.clear();
  }

  void
  RollBody::set_solution(const TrilinosWrappers::MPI::Vector &owned)
  {
    solution_owned            = owned;
    locally_relevant_solution = solution_owned;
  }

  void
  RollBody::setup()
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
    cell_mapping              = std::make_unique<MappingQ<dim>>(degree);
    // On curved (non-affine) cells a mapped P1 cannot represent linear
    // functions; FE_DGPNonparametric can (doc/intro.md, section 3).
    if (degree == 1)
      element =
        std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim, FE_DGP<dim>(0), 1);
    else
      element = std::make_unique<FESystem<dim>>(FE_Q<dim>(2),
                                                dim,
                                                FE_DGPNonparametric<dim>(1),
                                                1);
    dof_handler.distribute_dofs(*element);

    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    owned_pressure_dofs =
      DoFTools::extract_dofs(dof_handler, FEFields::pressure_mask(*element));

    make_constraints();
    make_sparsity_and_vectors();
    domain_area = measure_area();

    ConditionalOStream pcout(
      std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0);
    pcout << "Mesh: " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " DoFs (" << element->get_name() << "), "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI process(es)" << std::endl;
    if (parameters.contact.mode == Parameters::ContactMode::none &&
        parameters.boundary_conditions.condition[BoundaryIds::outer_arc] ==
          Parameters::BoundaryCondition::pressure)
      pcout << check_applied_load(*this) << std::endl;
  }

  void
  RollBody::make_sparsity_and_vectors()
  {
    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    boundary_constraints,
                                    /*keep_constrained_dofs=*/false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    if (with_preconditioner)
      {
        preconditioner_matrix.reinit(locally_owned_dofs,
                                     locally_owned_dofs,
                                     dsp,
                                     mpi_communicator);
        DoFTools::extract_constant_modes(dof_handler,
                                         FEFields::displacement_mask(*element),
                                         constant_modes);
      }

    solution_owned.reinit(locally_owned_dofs, mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    load_vector.reinit(locally_owned_dofs, mpi_communicator);
    locally_relevant_solution.reinit(locally_owned_dofs,
                                     locally_relevant_dofs,
                                     mpi_communicator);
  }

  double
  RollBody::measure_area() const
  {
    double area = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        area += cell->measure();
    return Utilities::MPI::sum(area, mpi_communicator);
  }

  void
  RollBody::fit_mesh_to_nip(const double theta0)
  {
    Assert(nip_mesh, ExcInternalError());
    TimerOutput::Scope t(timer, "setup");
    nip_mesh->fit(triangulation, theta0);
    domain_area = measure_area();
  }

  /**
   * Homogeneous constraints only: fixed boundaries get u = 0, symmetry
   * boundaries u . n = 0 (add_symmetry_constraints). Fixed wins where the
   * two meet.
   */
  void
  RollBody::make_constraints()
  {
    boundary_constraints.clear();
    boundary_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, boundary_constraints);

    const auto &bc = parameters.boundary_conditions.condition;
    for (types::boundary_id b = 0; b < BoundaryIds::n_boundaries; ++b)
      if (bc[b] == Parameters::BoundaryCondition::fixed)
        VectorTools::interpolate_boundary_values(
          *cell_mapping,
          dof_handler,
          b,
          Functions::ZeroFunction<dim>(dim + 1),
          boundary_constraints,
          FEFields::displacement_mask(*element));
    add_symmetry_constraints();
    boundary_constraints.close();
  }

  /**
   * u . n = 0 with n the edge normal known from the geometry (the X2 = 0
   * line for id 2, the line at the sector angle for id 3): the dominant
   * component of each node is eliminated in favour of the other.
   */
  void
  RollBody::add_symmetry_constraints()
  {
    const auto    &bc    = parameters.boundary_conditions.condition;
    const double   alpha = parameters.geometry.sector_angle;
    Tensor<1, dim> normal[BoundaryIds::n_boundaries];
    normal[BoundaryIds::symmetry_edge] = Tensor<1, dim>({0., 1.});
    normal[BoundaryIds::far_edge] =
      Tensor<1, dim>({-std::sin(alpha), std::cos(alpha)});

    auto                                &constraints = boundary_constraints;
    std::vector<types::global_dof_index> face_dofs(element->n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const types::boundary_id b = cell->face(f)->boundary_id();
            if ((b != BoundaryIds::symmetry_edge &&
                 b != BoundaryIds::far_edge) ||
                bc[b] != Parameters::BoundaryCondition::symmetry)
              continue;
            cell->face(f)->get_dof_indices(face_dofs);
            const Tensor<1, dim> &n = normal[b];
            const unsigned int    c = std::abs(n[1]) >= std::abs(n[0]) ? 1 : 0;
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              {
                const auto ci = element->face_system_to_component_index(i);
                if (ci.first != c)
                  continue;
                // The partner DoF of the other component at the same node.
                for (unsigned int j = 0; j < face_dofs.size(); ++j)
                  {
                    const auto cj = element->face_system_to_component_index(j);
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
  }
} // namespace rollnip
