#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/mapping_q.h>

#include <deal.II/numerics/error_estimator.h>

#include <rollnip/fe_fields.h>
#include <rollnip/geometry/adaptive_grading.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/problem.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <numeric>

namespace rollnip
{
  std::vector<double>
  adapted_circumferential_steps(const RollProblem         &problem,
                                const std::vector<double> &steps,
                                const double               sector_angle)
  {
    const auto        &dof_handler = problem.dofs();
    const unsigned int p           = dof_handler.get_fe().degree;
    const unsigned int n           = steps.size();

    Vector<float> eta(dof_handler.get_triangulation().n_active_cells());
    KellyErrorEstimator<dim>::estimate(
      MappingQ<dim>(p + 1),
      dof_handler,
      FEFields::face_quadrature(dof_handler.get_fe()),
      {},
      problem.current_solution(),
      eta,
      FEFields::displacement_mask(dof_handler.get_fe()));

    // E_j: the squared indicators of the cells of coarse column j.
    std::vector<double> edges(n + 1, 0.);
    std::partial_sum(steps.begin(), steps.end(), edges.begin() + 1);
    std::vector<double> E(n, 0.);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Point<dim> c     = cell->center();
          const double     theta = std::atan2(c[1], c[0]);
          const auto       j     = std::min<std::ptrdiff_t>(
            n - 1,
            std::upper_bound(edges.begin() + 1, edges.end(), theta) -
              (edges.begin() + 1));
          E[j] += double(eta[cell->active_cell_index()]) *
                  eta[cell->active_cell_index()];
        }
    std::vector<double> E_local(E);
    MPI_Allreduce(E_local.data(),
                  E.data(),
                  n,
                  MPI_DOUBLE,
                  MPI_SUM,
                  dof_handler.get_communicator());

    // Cell density per unit angle, E^(1/(2p+1)) / w, limited to a factor
    // 1.5 between neighbours (forward and backward sweeps).
    const double tiny = 1e-30 + 1e-12 * *std::max_element(E.begin(), E.end());
    std::vector<double> density(n);
    for (unsigned int j = 0; j < n; ++j)
      density[j] = std::pow(E[j] + tiny, 1. / (2 * p + 1)) / steps[j];
    for (unsigned int j = 1; j < n; ++j)
      density[j] = std::max(density[j], density[j - 1] / 1.5);
    for (unsigned int j = n - 1; j-- > 0;)
      density[j] = std::max(density[j], density[j + 1] / 1.5);

    // Equidistribute: n cells with equal integrals of the density.
    std::vector<double> cumulative(n + 1, 0.);
    for (unsigned int j = 0; j < n; ++j)
      cumulative[j + 1] = cumulative[j] + density[j] * steps[j];
    std::vector<double> vertices = {0.};
    unsigned int        j        = 0;
    for (unsigned int k = 1; k < n; ++k)
      {
        const double target = cumulative[n] * k / n;
        while (cumulative[j + 1] < target)
          ++j;
        vertices.push_back(edges[j] + (target - cumulative[j]) / density[j]);
      }
    vertices.push_back(sector_angle);
    std::vector<double> result(n);
    for (unsigned int k = 0; k < n; ++k)
      result[k] = vertices[k + 1] - vertices[k];
    return result;
  }
} // namespace rollnip
