#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/postprocess/line_traction.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace rollnip
{
  namespace
  {
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    /// A node is named by the global index of its x-displacement DoF.
    using NodeKey = types::global_dof_index;

    /**
     * Which line and from which side: the nodal forces of the cells in
     * the region balance the traction the rest of the body (or the core)
     * exerts on the region across the line.
     */
    struct LineChoice
    {
      std::function<bool(const CellIterator &)>                     in_region;
      std::function<bool(const CellIterator &, const unsigned int)> on_line;
      /// +1 if the region's outward normal points away from the axis (an
      /// interface seen from the inner layer), -1 if towards it (the bond).
      double side;
    };

    /// This rank's sums at one node of the line.
    struct NodeSums
    {
      double         theta_sum = 0, count = 0;
      Tensor<1, dim> force;  ///< sum of the region's int P : Grad phi_a
      Tensor<1, dim> normal; ///< sum of the faces' deformed outward normals
      double         vertex = 0;
    };

    /// For each node k of the scalar Lagrange element, the cell index of
    /// its x-displacement DoF.
    std::vector<unsigned int>
    x_dof_of_node(const FiniteElement<dim> &fe)
    {
      std::vector<unsigned int> table(fe.base_element(0).n_dofs_per_cell());
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (fe.system_to_component_index(i).first == 0)
          table[fe.system_to_component_index(i).second] = i;
      return table;
    }

    /// The cell indices of the x-displacement DoFs on face @p f.
    std::vector<unsigned int>
    face_nodes(const FiniteElement<dim> &fe, const unsigned int f)
    {
      std::vector<unsigned int> nodes;
      for (unsigned int i = 0; i < fe.n_dofs_per_face(f); ++i)
        {
          const unsigned int ci = fe.face_to_cell_index(i, f);
          if (fe.system_to_component_index(ci).first == 0)
            nodes.push_back(ci);
        }
      return nodes;
    }

    /// The keys of all nodes on the line that this rank can see (owned
    /// and ghost cells), so that cells touching the line at a vertex only
    /// add their forces too.
    std::set<NodeKey>
    line_keys(const RollBody &body, const LineChoice &line)
    {
      std::set<NodeKey>                    keys;
      std::vector<types::global_dof_index> dofs(body.fe().n_dofs_per_cell());
      for (const auto &cell : body.dofs().active_cell_iterators())
        if (!cell->is_artificial() && line.in_region(cell))
          for (const auto f : cell->face_indices())
            if (line.on_line(cell, f))
              {
                cell->get_dof_indices(dofs);
                for (const unsigned int ci : face_nodes(body.fe(), f))
                  keys.insert(dofs[ci]);
              }
      return keys;
    }

    using MassSums = std::map<std::pair<NodeKey, NodeKey>, double>;

    /**
     * Angle, deformed normal and the mass matrix int phi_a phi_b da of the
     * deformed line (da = |cof F N| dA), from the owned region cells' faces.
     */
    void
    add_line_geometry(const RollBody              &body,
                      const LineChoice            &line,
                      std::map<NodeKey, NodeSums> &nodes,
                      MassSums                    &mass)
    {
      const auto                      &fe = body.fe();
      const FEValuesExtractors::Vector displacement(0);
      const unsigned int               degree = fe.base_element(0).degree;
      FEFaceValues<dim>                at_nodes(
        body.mapping(),
        fe,
        Quadrature<dim - 1>(FE_Q<dim - 1>(degree).get_unit_support_points()),
        update_values | update_gradients | update_normal_vectors |
          update_quadrature_points);
      FEFaceValues<dim>           gauss(body.mapping(),
                              fe,
                              QGauss<dim - 1>(degree + 1),
                              update_values | update_gradients |
                                update_normal_vectors | update_JxW_values);
      std::vector<Tensor<2, dim>> grad_u(
        std::max(at_nodes.n_quadrature_points, gauss.n_quadrature_points));
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      const Tensor<2, dim>                 I = unit_symmetric_tensor<dim>();
      for (const auto &cell : body.dofs().active_cell_iterators())
        if (cell->is_locally_owned() && line.in_region(cell))
          for (const auto f : cell->face_indices())
            {
              if (!line.on_line(cell, f))
                continue;
              cell->get_dof_indices(dofs);
              const auto nodes_of_face = face_nodes(fe, f);
              at_nodes.reinit(cell, f);
              at_nodes[displacement].get_function_gradients(body.solution(),
                                                            grad_u);
              for (const unsigned int ci : nodes_of_face)
                for (unsigned int q = 0; q < at_nodes.n_quadrature_points; ++q)
                  if (at_nodes.shape_value(ci, q) > 0.5)
                    {
                      NodeSums &s = nodes[dofs[ci]];
                      s.theta_sum +=
                        reference_angle(at_nodes.quadrature_point(q));
                      s.count += 1;
                      const Tensor<1, dim> n =
                        cofactor(I + grad_u[q]) * at_nodes.normal_vector(q);
                      s.normal += n / n.norm();
                      s.vertex = fe.system_to_component_index(ci).second <
                                     cell->n_vertices()
                                   ? 1.
                                   : 0.;
                    }
              gauss.reinit(cell, f);
              gauss[displacement].get_function_gradients(body.solution(),
                                                         grad_u);
              for (unsigned int q = 0; q < gauss.n_quadrature_points; ++q)
                {
                  const double da =
                    (cofactor(I + grad_u[q]) * gauss.normal_vector(q)).norm() *
                    gauss.JxW(q);
                  for (const unsigned int a : nodes_of_face)
                    for (const unsigned int b : nodes_of_face)
                      mass[{dofs[a], dofs[b]}] +=
                        gauss.shape_value(a, q) * gauss.shape_value(b, q) * da;
                }
            }
    }

    /// The consistent nodal forces int P : Grad phi_a dV of the owned
    /// region cells at the line's nodes (the residual's volume part before
    /// constraints, as RollBody::assemble() integrates it).
    void
    add_nodal_forces(const RollBody              &body,
                     const LineChoice            &line,
                     const std::set<NodeKey>     &keys,
                     std::map<NodeKey, NodeSums> &nodes)
    {
      const auto                          &fe = body.fe();
      const FEValuesExtractors::Vector     displacement(0);
      const FEValuesExtractors::Scalar     pressure_unknown(dim);
      const QGauss<dim>                    quadrature(fe.degree + 1);
      FEValues<dim>                        fe_values(body.mapping(),
                              fe,
                              quadrature,
                              update_values | update_gradients |
                                update_JxW_values);
      const auto                           x_dof = x_dof_of_node(fe);
      std::vector<Tensor<2, dim>>          grad_u(quadrature.size());
      std::vector<double>                  q_values(quadrature.size());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      const Tensor<2, dim>                 I = unit_symmetric_tensor<dim>();
      for (const auto &cell : body.dofs().active_cell_iterators())
        {
          if (!cell->is_locally_owned() || !line.in_region(cell))
            continue;
          cell->get_dof_indices(dofs);
          std::vector<std::pair<unsigned int, NodeKey>> touched;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto c = fe.system_to_component_index(i);
              if (c.first < dim && keys.count(dofs[x_dof[c.second]]) > 0)
                touched.emplace_back(i, dofs[x_dof[c.second]]);
            }
          if (touched.empty())
            continue;
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(body.solution(),
                                                         grad_u);
          fe_values[pressure_unknown].get_function_values(body.solution(),
                                                          q_values);
          const MooneyRivlin &material = body.materials()[cell->material_id()];
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<2, dim> P =
                material.piola(I + grad_u[q], q_values[q]) * fe_values.JxW(q);
              for (const auto &[i, key] : touched)
                nodes[key].force[fe.system_to_component_index(i).first] +=
                  scalar_product(P, fe_values[displacement].gradient(i, q));
            }
        }
    }

    /// Everything of all ranks on rank 0: the node sums and the mass
    /// matrix entries (empty on the other ranks).
    void
    gather_on_root(std::map<NodeKey, NodeSums> &nodes,
                   MassSums                    &mass,
                   const MPI_Comm               comm)
    {
      std::vector<double> flat_nodes, flat_mass;
      for (const auto &[key, s] : nodes)
        flat_nodes.insert(flat_nodes.end(),
                          {static_cast<double>(key),
                           s.theta_sum,
                           s.count,
                           s.force[0],
                           s.force[1],
                           s.normal[0],
                           s.normal[1],
                           s.vertex});
      for (const auto &[keys, m] : mass)
        flat_mass.insert(flat_mass.end(),
                         {static_cast<double>(keys.first),
                          static_cast<double>(keys.second),
                          m});
      const auto all_nodes = Utilities::MPI::gather(comm, flat_nodes, 0);
      const auto all_mass  = Utilities::MPI::gather(comm, flat_mass, 0);
      nodes.clear();
      mass.clear();
      for (const auto &part : all_nodes)
        for (std::size_t i = 0; i < part.size(); i += 8)
          {
            NodeSums &s = nodes[static_cast<NodeKey>(part[i])];
            s.theta_sum += part[i + 1];
            s.count += part[i + 2];
            s.force += Tensor<1, dim>({part[i + 3], part[i + 4]});
            s.normal += Tensor<1, dim>({part[i + 5], part[i + 6]});
            s.vertex = std::max(s.vertex, part[i + 7]);
          }
      for (const auto &part : all_mass)
        for (std::size_t i = 0; i < part.size(); i += 3)
          mass[{static_cast<NodeKey>(part[i]),
                static_cast<NodeKey>(part[i + 1])}] += part[i + 2];
    }

    /// A symmetric positive definite band matrix, A(i, j) = band[i][j - i + w]
    /// for |i - j| <= w.
    struct BandMatrix
    {
      BandMatrix(const unsigned int n, const unsigned int w)
          : w(w)
          , band(n, std::vector<double>(2 * w + 1, 0.))
      {}

      double &
      operator()(const unsigned int i, const unsigned int j)
      {
        return band[i][j + w - i];
      }

      /// Replaces row and column @p i by those of the identity.
      void
      make_identity_row(const unsigned int i)
      {
        const unsigned int n = band.size();
        for (unsigned int j = (i > w ? i - w : 0); j < std::min(n, i + w + 1);
             ++j)
          (*this)(i, j) = (*this)(j, i) = 0.;
        (*this)(i, i) = 1.;
      }

      /// Solves A x = b in place by elimination without pivoting (A is
      /// positive definite); A is copied, so it can be reused.
      std::vector<double>
      solve(std::vector<double> b) const
      {
        BandMatrix         a = *this;
        const unsigned int n = b.size();
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int i = k + 1; i < std::min(n, k + w + 1); ++i)
            {
              const double factor = a(i, k) / a(k, k);
              if (factor == 0)
                continue;
              for (unsigned int j = k; j < std::min(n, k + w + 1); ++j)
                a(i, j) -= factor * a(k, j);
              b[i] -= factor * b[k];
            }
        for (unsigned int i = n; i-- > 0;)
          {
            for (unsigned int j = i + 1; j < std::min(n, i + w + 1); ++j)
              b[i] -= a(i, j) * b[j];
            b[i] /= a(i, i);
          }
        return b;
      }

      unsigned int                     w;
      std::vector<std::vector<double>> band;
    };

    /// Whether the node at @p theta lies on a side edge with a symmetry
    /// condition, where the shear traction vanishes by symmetry (the
    /// edge's own reaction shares that node's force).
    bool
    on_symmetry_edge(const Parameters::AllParameters &p, const double theta)
    {
      const auto &bc       = p.boundary_conditions.condition;
      const auto  symmetry = Parameters::BoundaryCondition::symmetry;
      return (std::abs(theta) < 1e-9 &&
              bc[BoundaryIds::symmetry_edge] == symmetry) ||
             (std::abs(theta - p.geometry.sector_angle) < 1e-9 &&
              bc[BoundaryIds::far_edge] == symmetry);
    }

    /**
     * The three-point filter t_i/2 + (h2 t_{i-1} + h1 t_{i+1}) / 2(h1 + h2)
     * (h1, h2 the node spacings), exact for linear t: it removes the
     * node-to-node oscillation of the nodal forces (Q1-P0's pressure modes
     * next to the line, Q2's vertex and mid-side nodes), which decays only
     * at first order. Measured on a smooth pressure scene against Q2-P1:
     * second order with it, 0.8 to 1.2 without it. A symmetry edge's node
     * takes its mirror image (@p odd: the shear, zero there).
     */
    std::vector<double>
    smooth(const std::vector<double>       &t,
           const std::vector<double>       &theta,
           const bool                       odd,
           const Parameters::AllParameters &p)
    {
      const unsigned int  n   = t.size();
      std::vector<double> out = t;
      for (unsigned int i = 0; i < n; ++i)
        {
          if (i == 0 || i == n - 1)
            {
              if (n > 1 && on_symmetry_edge(p, theta[i]))
                out[i] = odd ? 0. : 0.5 * (t[i] + t[i == 0 ? 1 : n - 2]);
              continue;
            }
          const double h1 = theta[i] - theta[i - 1],
                       h2 = theta[i + 1] - theta[i];
          out[i] =
            0.5 * t[i] + (h2 * t[i - 1] + h1 * t[i + 1]) / (2 * (h1 + h2));
        }
      return out;
    }

    /**
     * Rank 0: solves M t = f for the traction's polar components (at each
     * node's reference angle, so that a symmetry edge's zero shear is one
     * row) and reads sigma n at the vertices in the deformed line's frame.
     */
    std::vector<LineTraction>
    solve_on_root(const RollBody                    &body,
                  const std::map<NodeKey, NodeSums> &nodes,
                  const MassSums                    &mass,
                  const double                       side)
    {
      std::vector<std::pair<double, NodeKey>> order;
      for (const auto &[key, s] : nodes)
        if (s.count > 0)
          order.emplace_back(s.theta_sum / s.count, key);
      std::sort(order.begin(), order.end());
      const unsigned int              n = order.size();
      std::map<NodeKey, unsigned int> index;
      for (unsigned int i = 0; i < n; ++i)
        index[order[i].second] = i;
      unsigned int w = 0;
      for (const auto &[keys, m] : mass)
        w = std::max(w,
                     static_cast<unsigned int>(
                       std::abs(static_cast<int>(index.at(keys.first)) -
                                static_cast<int>(index.at(keys.second)))));
      BandMatrix M(n, w);
      for (const auto &[keys, m] : mass)
        M(index.at(keys.first), index.at(keys.second)) += m;
      std::vector<double> f_r(n), f_t(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const double          theta = order[i].first;
          const Tensor<1, dim> &f     = nodes.at(order[i].second).force;
          f_r[i] = std::cos(theta) * f[0] + std::sin(theta) * f[1];
          f_t[i] = -std::sin(theta) * f[0] + std::cos(theta) * f[1];
        }
      auto t_r = M.solve(f_r);
      for (unsigned int i = 0; i < n; ++i)
        if (on_symmetry_edge(body.scene(), order[i].first))
          {
            M.make_identity_row(i);
            f_t[i] = 0;
          }
      auto                t_t = M.solve(f_t);
      std::vector<double> theta(n);
      for (unsigned int i = 0; i < n; ++i)
        theta[i] = order[i].first;
      t_r = smooth(t_r, theta, false, body.scene());
      t_t = smooth(t_t, theta, true, body.scene());

      std::vector<LineTraction> result;
      for (unsigned int i = 0; i < n; ++i)
        {
          const NodeSums &s = nodes.at(order[i].second);
          if (s.vertex == 0)
            continue;
          const double   c     = std::cos(order[i].first);
          const double   sn    = std::sin(order[i].first);
          Tensor<1, dim> n_out = s.normal;
          // On a symmetry edge only one side's faces are meshed: the
          // mirror image's normal is added, which leaves the edge's own
          // direction e_r (the edges are radial).
          if (on_symmetry_edge(body.scene(), order[i].first))
            n_out = (n_out * Tensor<1, dim>({c, sn})) * Tensor<1, dim>({c, sn});
          // sigma n with n pointing away from the axis.
          const Tensor<1, dim> t =
            side * Tensor<1, dim>(
                     {c * t_r[i] - sn * t_t[i], sn * t_r[i] + c * t_t[i]});
          const Tensor<1, dim> normal = side * n_out / n_out.norm();
          const Tensor<1, dim> tangent({-normal[1], normal[0]});
          result.push_back({order[i].first, normal * t, tangent * t});
        }
      return result;
    }

    std::vector<LineTraction>
    recover(const RollBody &body, const LineChoice &line)
    {
      std::map<NodeKey, NodeSums> nodes;
      MassSums                    mass;
      add_line_geometry(body, line, nodes, mass);
      add_nodal_forces(body, line, line_keys(body, line), nodes);
      gather_on_root(nodes, mass, body.communicator());
      if (Utilities::MPI::this_mpi_process(body.communicator()) != 0 ||
          nodes.empty())
        return {};
      return solve_on_root(body, nodes, mass, line.side);
    }
  } // namespace

  std::vector<LineTraction>
  bond_traction(const RollBody &body)
  {
    LineChoice line;
    line.in_region = [](const CellIterator &) { return true; };
    line.on_line   = [](const CellIterator &cell, const unsigned int f) {
      return cell->face(f)->at_boundary() &&
             cell->face(f)->boundary_id() == BoundaryIds::inner_arc;
    };
    line.side = -1;
    return recover(body, line);
  }

  std::vector<LineTraction>
  interface_traction(const RollBody    &body,
                     const unsigned int j,
                     const bool         from_outer_layer)
  {
    const types::material_id own   = from_outer_layer ? j + 1 : j;
    const types::material_id other = from_outer_layer ? j : j + 1;
    LineChoice               line;
    line.in_region = [own](const CellIterator &cell) {
      return cell->material_id() == own;
    };
    line.on_line = [other](const CellIterator &cell, const unsigned int f) {
      return !cell->face(f)->at_boundary() &&
             cell->neighbor(f)->material_id() == other;
    };
    line.side = from_outer_layer ? -1 : 1;
    return recover(body, line);
  }
} // namespace rollnip
