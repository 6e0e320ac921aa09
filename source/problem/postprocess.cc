#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/postprocess/stress_state.h>
#include <rollnip/problem.h>

#include <cmath>
#include <map>

namespace rollnip
{
  namespace
  {
    /// Key of a surface node: its reference angle, rounded so that the
    /// copies of one node seen from two cells (or two ranks) coincide.
    long long
    angle_key(const double theta)
    {
      return std::llround(theta * 1e9);
    }

    /// Per-node sums, so that values seen from several faces average.
    using NodeSums = std::map<long long, std::vector<double>>;

    void
    accumulate(NodeSums &sums, const double theta, std::vector<double> values)
    {
      values.push_back(1.); // the count
      auto it = sums.find(angle_key(theta));
      if (it == sums.end())
        sums.emplace(angle_key(theta), std::move(values));
      else
        for (unsigned int k = 0; k < values.size(); ++k)
          it->second[k] += values[k];
    }

    /// Gathers the sums of all ranks on rank 0 and returns averaged rows.
    std::vector<std::vector<double>>
    gather_rows(const NodeSums &sums, const unsigned int width, MPI_Comm comm)
    {
      std::vector<double> flat;
      for (const auto &entry : sums)
        {
          flat.push_back(static_cast<double>(entry.first));
          flat.insert(flat.end(), entry.second.begin(), entry.second.end());
        }
      const auto all = Utilities::MPI::gather(comm, flat, 0);
      NodeSums   merged;
      for (const auto &part : all)
        for (std::size_t i = 0; i < part.size(); i += width + 2)
          {
            const long long     key = static_cast<long long>(part[i]);
            std::vector<double> v(part.begin() + i + 1,
                                  part.begin() + i + width + 2);
            auto                it = merged.find(key);
            if (it == merged.end())
              merged.emplace(key, v);
            else
              for (unsigned int k = 0; k < v.size(); ++k)
                it->second[k] += v[k];
          }
      std::vector<std::vector<double>> rows;
      for (auto &entry : merged)
        {
          std::vector<double> row(width);
          for (unsigned int k = 0; k < width; ++k)
            row[k] = entry.second[k] / entry.second[width];
          rows.push_back(row);
        }
      return rows;
    }
  } // namespace

  double
  RollProblem::radial_displacement_on_line_of_centres() const
  {
    return radial_displacement_at(
      Point<dim>(parameters.geometry.outer_radius, 0.));
  }

  double
  RollProblem::radial_displacement_at(const Point<dim> &X) const
  {
    const double tolerance = 1e-8 * X.norm();
    double       sum = 0, count = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto v : cell->vertex_indices())
          if (cell->vertex(v).distance(X) < tolerance)
            {
              // Vertex DoFs of the FESystem come as (u_x, u_y, ...).
              const double ux =
                locally_relevant_solution[cell->vertex_dof_index(v, 0)];
              const double uy =
                locally_relevant_solution[cell->vertex_dof_index(v, 1)];
              sum += (ux * X[0] + uy * X[1]) / X.norm();
              count += 1;
            }
    sum   = Utilities::MPI::sum(sum, mpi_communicator);
    count = Utilities::MPI::sum(count, mpi_communicator);
    return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
  }

  Tensor<1, dim>
  RollProblem::load_resultant(const double load_fraction) const
  {
    const unsigned int degree = parameters.discretization.displacement_degree();
    const QGauss<dim - 1>            face_quadrature(degree + 1);
    const auto                       face_values = make_pressure_face_values();
    FEFaceValues<dim>               &fe_face_values = *face_values;
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u(face_quadrature.size());
    Tensor<1, dim>                   resultant;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (is_pressure_face(cell, f))
            {
              fe_face_values.reinit(cell, f);
              fe_face_values[displacement].get_function_gradients(
                locally_relevant_solution, grad_u);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                {
                  const Point<dim> &X = fe_face_values.quadrature_point(q);
                  const double      f =
                    pressure(std::atan2(X[1], X[0]), load_fraction);
                  const Tensor<1, dim> &N   = fe_face_values.normal_vector(q);
                  const Tensor<1, dim>  nda = current_area_normal(grad_u[q], N);
                  resultant -= f * nda * fe_face_values.JxW(q);
                }
            }
    for (unsigned int d = 0; d < dim; ++d)
      resultant[d] = Utilities::MPI::sum(resultant[d], mpi_communicator);
    return resultant;
  }

  /**
   * Surface values at the nodes of the outer and bond arcs. Stresses come
   * from the cells' own fields evaluated at the face vertices and are
   * averaged over the (two) faces meeting at a node: with Q1-P0 they are
   * discontinuous, and the average is what a user reads off a plot.
   */
  SurfaceData
  RollProblem::surface_data(const double load_fraction) const
  {
    const bool pressure_on_outer =
      parameters.boundary_conditions.condition[BoundaryIds::outer_arc] ==
      Parameters::BoundaryCondition::pressure;
    const QTrapezoid<dim - 1>        vertex_quadrature;
    FEFaceValues<dim>                fe_face_values(*mapping,
                                     *fe,
                                     vertex_quadrature,
                                     update_values | update_gradients |
                                       update_normal_vectors |
                                       update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    const FEValuesExtractors::Scalar pressure_unknown(dim);
    std::vector<Tensor<1, dim>>      u(2);
    std::vector<Tensor<2, dim>>      grad_u(2);
    std::vector<double>              q(2);

    NodeSums outer, bond;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const types::boundary_id b = cell->face(f)->boundary_id();
            if (b != BoundaryIds::outer_arc && b != BoundaryIds::inner_arc)
              continue;
            fe_face_values.reinit(cell, f);
            fe_face_values[displacement].get_function_values(
              locally_relevant_solution, u);
            fe_face_values[displacement].get_function_gradients(
              locally_relevant_solution, grad_u);
            fe_face_values[pressure_unknown].get_function_values(
              locally_relevant_solution, q);
            // Outward unit normal of the deformed (straight) face.
            const Point<dim> x0 = fe_face_values.quadrature_point(0) + u[0];
            const Point<dim> x1 = fe_face_values.quadrature_point(1) + u[1];
            Tensor<1, dim>   n({x1[1] - x0[1], x0[0] - x1[0]});
            n /= n.norm();
            if (n * fe_face_values.normal_vector(0) < 0)
              n = -n;
            const Tensor<1, dim> t({-n[1], n[0]});
            for (unsigned int v = 0; v < 2; ++v)
              {
                const Point<dim> &X     = fe_face_values.quadrature_point(v);
                const double      theta = std::atan2(X[1], X[0]);
                const StressState s =
                  evaluate_stress_state(material, grad_u[v], q[v], X, u[v]);
                if (b == BoundaryIds::outer_arc)
                  {
                    const double c = std::cos(theta), sn = std::sin(theta);
                    const double applied =
                      pressure_on_outer ? pressure(theta, load_fraction) : 0.;
                    const Tensor<1, dim> sn_vec = s.sigma * n;
                    accumulate(outer,
                               theta,
                               {theta,
                                X[0],
                                X[1],
                                X[0] + u[v][0],
                                X[1] + u[v][1],
                                c * u[v][0] + sn * u[v][1],
                                -sn * u[v][0] + c * u[v][1],
                                applied,
                                -(n * sn_vec),
                                t * sn_vec});
                  }
                else
                  accumulate(
                    bond,
                    theta,
                    {theta, s.sigma_rr, s.sigma_rt, s.sigma_tt, s.sigma_zz});
              }
          }

    SurfaceData data;
    for (const auto &r : gather_rows(outer, 10, mpi_communicator))
      data.outer.push_back(
        {r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], r[9]});
    for (const auto &r : gather_rows(bond, 5, mpi_communicator))
      data.bond.push_back({r[0], r[1], r[2], r[3], r[4]});

    // Extremes over the Gauss points of the whole cover.
    const unsigned int degree = parameters.discretization.displacement_degree();
    const QGauss<dim>  quadrature(degree + 1);
    FEValues<dim>      fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points);
    std::vector<Tensor<1, dim>> uq(quadrature.size());
    std::vector<Tensor<2, dim>> gq(quadrature.size());
    std::vector<double>         qq(quadrature.size());
    FieldExtremes               e;
    e.min_J = e.min_principal_stretch = std::numeric_limits<double>::max();
    e.min_sigma_rr                    = std::numeric_limits<double>::max();
    e.max_sigma_rr                    = -std::numeric_limits<double>::max();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(locally_relevant_solution,
                                                      uq);
          fe_values[displacement].get_function_gradients(
            locally_relevant_solution, gq);
          fe_values[pressure_unknown].get_function_values(
            locally_relevant_solution, qq);
          for (unsigned int k = 0; k < quadrature.size(); ++k)
            {
              const StressState s = evaluate_stress_state(
                material, gq[k], qq[k], fe_values.quadrature_point(k), uq[k]);
              e.min_J = std::min(e.min_J, s.J);
              e.max_abs_J_minus_1 =
                std::max(e.max_abs_J_minus_1, std::abs(s.J - 1.));
              e.max_principal_stretch =
                std::max(e.max_principal_stretch, s.max_stretch);
              e.min_principal_stretch =
                std::min(e.min_principal_stretch, s.min_stretch);
              e.max_von_mises = std::max(e.max_von_mises, s.von_mises);
              e.min_sigma_rr  = std::min(e.min_sigma_rr, s.sigma_rr);
              e.max_sigma_rr  = std::max(e.max_sigma_rr, s.sigma_rr);
              e.max_abs_sigma_rtheta =
                std::max(e.max_abs_sigma_rtheta, std::abs(s.sigma_rt));
            }
        }
    const MPI_Comm c        = mpi_communicator;
    e.min_J                 = Utilities::MPI::min(e.min_J, c);
    e.max_abs_J_minus_1     = Utilities::MPI::max(e.max_abs_J_minus_1, c);
    e.max_principal_stretch = Utilities::MPI::max(e.max_principal_stretch, c);
    e.min_principal_stretch = Utilities::MPI::min(e.min_principal_stretch, c);
    e.max_von_mises         = Utilities::MPI::max(e.max_von_mises, c);
    e.min_sigma_rr          = Utilities::MPI::min(e.min_sigma_rr, c);
    e.max_sigma_rr          = Utilities::MPI::max(e.max_sigma_rr, c);
    e.max_abs_sigma_rtheta  = Utilities::MPI::max(e.max_abs_sigma_rtheta, c);
    data.extremes           = e;
    return data;
  }
} // namespace rollnip
