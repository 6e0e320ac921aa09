// Exact solution 1 of doc/intro.md section 8: a uniform follower pressure q
// on the outer arc, inner arc bonded, both edges symmetric. Incompressibility
// with a fixed inner boundary forbids any motion, so u = 0 and the stress is
// sigma = -q I (in-plane and zz), exactly, on any mesh and with any element.

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <rollnip/postprocess/stress_state.h>

#include <rollnip/fe_fields.h>

#include "test_tools.h"

using namespace rollnip;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     q = 0.3; // MPa

  for (const std::string element : {"Q1-P0", "Q2-P1"})
    for (const unsigned int refinements : {0u, 2u})
      {
        const auto parameters = testing::parameters_from_string(
          "subsection Mesh\n set Global refinements = " +
          std::to_string(refinements) +
          "\nend\n"
          "subsection Discretization\n set Element = " +
          element +
          "\nend\n"
          "subsection Boundary conditions\n"
          " set Far edge (id 3) = symmetry\n"
          "end\n"
          "subsection Load\n set Pressure function = p0\n set p0 = 0.3\n"
          "end\n");
        RollProblem problem(parameters, MPI_COMM_WORLD);
        problem.setup();
        const RunStatus status = problem.run();
        checker.check(status.converged, element + " run converged");

        // Every Gauss point: u = 0 and sigma = -q I.
        const MaterialTable materials(parameters.material);
        const unsigned int  degree =
          parameters.discretization.displacement_degree();
        const QGauss<dim> quadrature =
          FEFields::cell_quadrature(problem.dofs().get_fe());
        MappingQ<dim>               mapping(degree);
        FEValues<dim>               fe_values(mapping,
                                problem.dofs().get_fe(),
                                quadrature,
                                update_values | update_gradients |
                                  update_quadrature_points);
        std::vector<Tensor<1, dim>> u(quadrature.size());
        std::vector<Tensor<2, dim>> grad_u(quadrature.size());
        std::vector<double>         qv(quadrature.size());
        double                      max_u = 0, max_stress_error = 0;
        for (const auto &cell : problem.dofs().active_cell_iterators())
          {
            fe_values.reinit(cell);
            fe_values[FEFields::displacement].get_function_values(
              problem.current_solution(), u);
            fe_values[FEFields::displacement].get_function_gradients(
              problem.current_solution(), grad_u);
            fe_values[FEFields::pressure].get_function_values(
              problem.current_solution(), qv);
            for (unsigned int k = 0; k < quadrature.size(); ++k)
              {
                const StressState s =
                  evaluate_stress_state(materials,
                                        cell->material_id(),
                                        grad_u[k],
                                        qv[k],
                                        fe_values.quadrature_point(k),
                                        u[k]);
                max_u            = std::max(max_u, u[k].norm());
                max_stress_error = std::max({max_stress_error,
                                             std::abs(s.sigma[0][0] + q),
                                             std::abs(s.sigma[1][1] + q),
                                             std::abs(s.sigma[0][1]),
                                             std::abs(s.sigma_zz + q)});
              }
          }
        const std::string scene =
          element + ", " + std::to_string(problem.n_cells()) + " cells";
        checker.check(max_u < 1e-10,
                      scene + ": max |u| = " + testing::num(max_u) +
                        " mm < 1e-10 mm");
        std::ostringstream s;
        s << scene << ": max |sigma + q I| = " << max_stress_error
          << " MPa < 1e-10 MPa";
        checker.check(max_stress_error < 1e-10, s.str());
      }
  return checker.result();
}
