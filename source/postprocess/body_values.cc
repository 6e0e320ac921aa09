#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/fe_fields.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/postprocess/body_values.h>
#include <rollnip/postprocess/line_traction.h>
#include <rollnip/postprocess/stress_state.h>

#include <cmath>
#include <limits>
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

    /// Whether two reference angles name the same node.
    bool
    same_angle(const double a, const double b)
    {
      return std::abs(a - b) < 1e-8;
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
      NodeSums merged;
      for (const auto &part : Utilities::MPI::gather(comm, flat, 0))
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

    /// The fields of one surface face, at its two vertices.
    struct FaceVertexValues
    {
      explicit FaceVertexValues(const RollBody &body)
          : fv(body.mapping(),
               body.fe(),
               QTrapezoid<dim - 1>(),
               update_values | update_gradients | update_normal_vectors |
                 update_quadrature_points)
      {}

      FEFaceValues<dim>           fv;
      std::vector<Tensor<1, dim>> u      = std::vector<Tensor<1, dim>>(2);
      std::vector<Tensor<2, dim>> grad_u = std::vector<Tensor<2, dim>>(2);
      std::vector<double>         q      = std::vector<double>(2);
      Tensor<1, dim>              n; ///< outward normal of the deformed face

      void
      read(const typename DoFHandler<dim>::active_cell_iterator &cell,
           const unsigned int                                    f,
           const TrilinosWrappers::MPI::Vector                  &solution)
      {
        fv.reinit(cell, f);
        using FEFields::displacement;
        const auto &pressure_unknown = FEFields::pressure;
        fv[displacement].get_function_values(solution, u);
        fv[displacement].get_function_gradients(solution, grad_u);
        fv[pressure_unknown].get_function_values(solution, q);
        const Point<dim> x0 = fv.quadrature_point(0) + u[0];
        const Point<dim> x1 = fv.quadrature_point(1) + u[1];
        n                   = Tensor<1, dim>({x1[1] - x0[1], x0[0] - x1[0]});
        n /= n.norm();
        if (n * fv.normal_vector(0) < 0)
          n = -n;
      }
    };

    /// The row of one outer-surface vertex (see OuterSurfacePoint).
    std::vector<double>
    outer_row(const Point<dim>     &X,
              const Tensor<1, dim> &u,
              const Tensor<1, dim> &n,
              const StressState    &s,
              const double          applied)
    {
      const double         theta = reference_angle(X);
      const double         c = std::cos(theta), sn = std::sin(theta);
      const Tensor<1, dim> t({-n[1], n[0]});
      const Tensor<1, dim> traction = s.sigma * n;
      return {theta,
              X[0],
              X[1],
              X[0] + u[0],
              X[1] + u[1],
              c * u[0] + sn * u[1],
              -sn * u[0] + c * u[1],
              applied,
              -(n * traction),
              t * traction};
    }

    /// The interface nodes of a layered cover, gathered on rank 0: the
    /// traction from the nodal forces, and each side's hoop stress from its
    /// own cells, averaged per node and side.
    std::vector<std::vector<InterfacePoint>>
    interface_data(const RollBody &body)
    {
      const unsigned int n_interfaces = body.materials().n_layers() - 1;
      if (n_interfaces == 0)
        return {};
      FaceVertexValues      values(body);
      const auto           &fv = values.fv;
      std::vector<NodeSums> inner(n_interfaces), outer(n_interfaces);
      for (const auto &cell : body.dofs().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            {
              if (cell->face(f)->at_boundary())
                continue;
              const unsigned int own   = cell->material_id();
              const unsigned int other = cell->neighbor(f)->material_id();
              if (own == other)
                continue;
              values.read(cell, f, body.solution());
              NodeSums &sums = own < other ? inner[own] : outer[other];
              for (unsigned int v = 0; v < 2; ++v)
                {
                  const Point<dim> &X = fv.quadrature_point(v);
                  const StressState s = evaluate_stress_state(body.materials(),
                                                              *cell,
                                                              values.grad_u[v],
                                                              values.q[v],
                                                              X,
                                                              values.u[v]);
                  accumulate(sums,
                             reference_angle(X),
                             {reference_angle(X), s.sigma_tt});
                }
            }
      std::vector<std::vector<InterfacePoint>> interfaces(n_interfaces);
      const MPI_Comm                           comm = body.communicator();
      for (unsigned int j = 0; j < n_interfaces; ++j)
        {
          const auto in  = gather_rows(inner[j], 2, comm);
          const auto out = gather_rows(outer[j], 2, comm);
          const auto t   = interface_traction(body, j);
          AssertThrow(in.size() == t.size() && out.size() == t.size(),
                      ExcInternalError());
          for (unsigned int k = 0; k < t.size(); ++k)
            {
              AssertThrow(same_angle(in[k][0], t[k].theta) &&
                            same_angle(out[k][0], t[k].theta),
                          ExcInternalError());
              interfaces[j].push_back({t[k].theta,
                                       t[k].sigma_nn,
                                       t[k].sigma_nt,
                                       in[k][1],
                                       out[k][1]});
            }
        }
      return interfaces;
    }
  } // namespace

  double
  radial_displacement_at(const RollBody &body, const Point<dim> &X)
  {
    const double tolerance = 1e-8 * X.norm();
    const auto  &u         = body.solution();
    double       sum = 0, count = 0;
    for (const auto &cell : body.dofs().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto v : cell->vertex_indices())
          if (cell->vertex(v).distance(X) < tolerance)
            {
              // Vertex DoFs of the FESystem come as (u_x, u_y, ...).
              const double ux = u[cell->vertex_dof_index(v, 0)];
              const double uy = u[cell->vertex_dof_index(v, 1)];
              sum += (ux * X[0] + uy * X[1]) / X.norm();
              count += 1;
            }
    sum   = Utilities::MPI::sum(sum, body.communicator());
    count = Utilities::MPI::sum(count, body.communicator());
    return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
  }

  double
  radial_displacement_on_line_of_centres(const RollBody &body)
  {
    return radial_displacement_at(body,
                                  Point<dim>(body.scene().geometry.outer_radius,
                                             0.));
  }

  Tensor<1, dim>
  load_resultant(const RollBody &body, const double load_fraction)
  {
    const FollowerLoad &load = body.load();
    const auto face_values   = load.make_face_values(body.mapping(), body.fe());
    std::vector<Tensor<2, dim>> grad_u;
    Tensor<1, dim>              resultant;
    for (const auto &cell : body.dofs().active_cell_iterators())
      if (cell->is_locally_owned())
        load.for_each_point(cell,
                            *face_values,
                            body.solution(),
                            grad_u,
                            [&](const unsigned int,
                                const double          theta,
                                const Tensor<2, dim> &grad_u_q,
                                const Tensor<1, dim> &N,
                                const double          JxW) {
                              resultant -=
                                load.value(theta, load_fraction) *
                                load.current_area_normal(grad_u_q, N) * JxW;
                            });
    for (unsigned int d = 0; d < dim; ++d)
      resultant[d] = Utilities::MPI::sum(resultant[d], body.communicator());
    return resultant;
  }

  /**
   * Stresses come from the cells' own fields evaluated at the face
   * vertices and are averaged over the (two) faces meeting at a node: with
   * Q1-P0 they are discontinuous, and the average is what a user reads off
   * a plot. The tractions on the bond and the interfaces come from the
   * consistent nodal forces instead (line_traction.h), which converge
   * faster than the cells' stresses at a node.
   */
  SurfaceData
  surface_data(const RollBody &body, const double load_fraction)
  {
    const auto &bc = body.scene().boundary_conditions.condition;
    const bool  pressure_on_outer =
      bc[BoundaryIds::outer_arc] == Parameters::BoundaryCondition::pressure;
    FaceVertexValues values(body);
    const auto      &fv = values.fv;
    NodeSums         outer, bond;
    for (const auto &cell : body.dofs().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const types::boundary_id b = cell->face(f)->boundary_id();
            if (b != BoundaryIds::outer_arc && b != BoundaryIds::inner_arc)
              continue;
            values.read(cell, f, body.solution());
            for (unsigned int v = 0; v < 2; ++v)
              {
                const Point<dim> &X     = fv.quadrature_point(v);
                const double      theta = reference_angle(X);
                const StressState s = evaluate_stress_state(body.materials(),
                                                            *cell,
                                                            values.grad_u[v],
                                                            values.q[v],
                                                            X,
                                                            values.u[v]);
                if (b == BoundaryIds::outer_arc)
                  accumulate(outer,
                             theta,
                             outer_row(X,
                                       values.u[v],
                                       values.n,
                                       s,
                                       pressure_on_outer
                                         ? body.load().value(theta,
                                                             load_fraction)
                                         : 0.));
                else
                  accumulate(
                    bond,
                    theta,
                    {theta, s.sigma_rr, s.sigma_rt, s.sigma_tt, s.sigma_zz});
              }
          }

    SurfaceData    data;
    const MPI_Comm comm = body.communicator();
    for (const auto &r : gather_rows(outer, 10, comm))
      data.outer.push_back(
        {r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], r[9]});
    const auto bond_rows = gather_rows(bond, 5, comm);
    const auto traction  = bond_traction(body);
    AssertThrow(traction.size() == bond_rows.size(), ExcInternalError());
    for (unsigned int k = 0; k < bond_rows.size(); ++k)
      {
        const auto &r = bond_rows[k];
        AssertThrow(same_angle(r[0], traction[k].theta), ExcInternalError());
        data.bond.push_back(
          {r[0], traction[k].sigma_nn, traction[k].sigma_nt, r[3], r[4]});
      }
    data.interfaces = interface_data(body);
    data.extremes   = field_extremes(body);
    return data;
  }

  FieldExtremes
  field_extremes(const RollBody &body)
  {
    const QGauss<dim> quadrature = FEFields::cell_quadrature(body.fe());
    FEValues<dim>     fe_values(body.mapping(),
                            body.fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points);
    using FEFields::displacement;
    const auto                 &pressure_unknown = FEFields::pressure;
    std::vector<Tensor<1, dim>> uq(quadrature.size());
    std::vector<Tensor<2, dim>> gq(quadrature.size());
    std::vector<double>         qq(quadrature.size());
    constexpr double            big = std::numeric_limits<double>::max();
    FieldExtremes               e;
    e.min_J = e.min_principal_stretch = e.min_sigma_rr = big;
    e.max_sigma_rr                                     = -big;
    for (const auto &cell : body.dofs().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(body.solution(), uq);
          fe_values[displacement].get_function_gradients(body.solution(), gq);
          fe_values[pressure_unknown].get_function_values(body.solution(), qq);
          for (unsigned int k = 0; k < quadrature.size(); ++k)
            {
              const StressState s =
                evaluate_stress_state(body.materials(),
                                      *cell,
                                      gq[k],
                                      qq[k],
                                      fe_values.quadrature_point(k),
                                      uq[k]);
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
    const MPI_Comm c        = body.communicator();
    e.min_J                 = Utilities::MPI::min(e.min_J, c);
    e.max_abs_J_minus_1     = Utilities::MPI::max(e.max_abs_J_minus_1, c);
    e.max_principal_stretch = Utilities::MPI::max(e.max_principal_stretch, c);
    e.min_principal_stretch = Utilities::MPI::min(e.min_principal_stretch, c);
    e.max_von_mises         = Utilities::MPI::max(e.max_von_mises, c);
    e.min_sigma_rr          = Utilities::MPI::min(e.min_sigma_rr, c);
    e.max_sigma_rr          = Utilities::MPI::max(e.max_sigma_rr, c);
    e.max_abs_sigma_rtheta  = Utilities::MPI::max(e.max_abs_sigma_rtheta, c);
    return e;
  }
} // namespace rollnip
