#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/fe_fields.h>
#include <rollnip/geometry/angles.h>
#include <rollnip/kinematics.h>
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
    };

    /// This rank's sums at one node of the line.
    struct NodeSums
    {
      double         theta_sum = 0, count = 0;
      Tensor<1, dim> force; ///< sum of the region's int P : Grad phi_a
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

    /// Per face of the line: its nodes' keys, then per Gauss point the
    /// nodes' shape values and n da (the deformed outward normal times the
    /// deformed length element), flattened for the gather.
    using FaceRecords = std::vector<double>;

    /**
     * The angle of every node and the line's face records (FaceRecords),
     * from the owned region cells' faces; da = |cof F N| dA.
     */
    void
    add_line_geometry(const RollBody              &body,
                      const LineChoice            &line,
                      std::map<NodeKey, NodeSums> &nodes,
                      FaceRecords                 &faces)
    {
      const auto &fe = body.fe();
      using FEFields::displacement;
      const unsigned int degree = fe.base_element(0).degree;
      FEFaceValues<dim>  at_nodes(
        body.mapping(),
        fe,
        Quadrature<dim - 1>(FE_Q<dim - 1>(degree).get_unit_support_points()),
        update_values | update_quadrature_points);
      FEFaceValues<dim>                    gauss(body.mapping(),
                              fe,
                              FEFields::face_quadrature(fe),
                              update_values | update_gradients |
                                update_normal_vectors | update_JxW_values);
      std::vector<Tensor<2, dim>>          grad_u(gauss.n_quadrature_points);
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
              for (const unsigned int ci : nodes_of_face)
                for (unsigned int q = 0; q < at_nodes.n_quadrature_points; ++q)
                  if (at_nodes.shape_value(ci, q) > 0.5)
                    {
                      NodeSums &s = nodes[dofs[ci]];
                      s.theta_sum +=
                        reference_angle(at_nodes.quadrature_point(q));
                      s.count += 1;
                      s.vertex = fe.system_to_component_index(ci).second <
                                     cell->n_vertices()
                                   ? 1.
                                   : 0.;
                    }
              for (const unsigned int a : nodes_of_face)
                faces.push_back(static_cast<double>(dofs[a]));
              gauss.reinit(cell, f);
              gauss[displacement].get_function_gradients(body.solution(),
                                                         grad_u);
              for (unsigned int q = 0; q < gauss.n_quadrature_points; ++q)
                {
                  for (const unsigned int a : nodes_of_face)
                    faces.push_back(gauss.shape_value(a, q));
                  const Tensor<1, dim> n_da = cofactor(I + grad_u[q]) *
                                              gauss.normal_vector(q) *
                                              gauss.JxW(q);
                  faces.push_back(n_da[0]);
                  faces.push_back(n_da[1]);
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
      const auto &fe = body.fe();
      using FEFields::displacement;
      const auto                 &pressure_unknown = FEFields::pressure;
      const QGauss<dim>           quadrature = FEFields::cell_quadrature(fe);
      FEValues<dim>               fe_values(body.mapping(),
                              fe,
                              quadrature,
                              update_values | update_gradients |
                                update_JxW_values);
      const auto                  x_dof = x_dof_of_node(fe);
      std::vector<Tensor<2, dim>> grad_u(quadrature.size());
      std::vector<double>         q_values(quadrature.size());
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
              if (c.first != FEFields::pressure_component &&
                  keys.count(dofs[x_dof[c.second]]) > 0)
                touched.emplace_back(i, dofs[x_dof[c.second]]);
            }
          if (touched.empty())
            continue;
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(body.solution(),
                                                         grad_u);
          fe_values[pressure_unknown].get_function_values(body.solution(),
                                                          q_values);
          const ScaledLaw<dim> material = body.materials().law(*cell);
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

    /// Everything of all ranks on rank 0: the node sums and the face
    /// records (empty on the other ranks).
    void
    gather_on_root(std::map<NodeKey, NodeSums> &nodes,
                   FaceRecords                 &faces,
                   const MPI_Comm               comm)
    {
      std::vector<double> flat_nodes;
      for (const auto &[key, s] : nodes)
        flat_nodes.insert(flat_nodes.end(),
                          {static_cast<double>(key),
                           s.theta_sum,
                           s.count,
                           s.force[0],
                           s.force[1],
                           s.vertex});
      const auto all_nodes = Utilities::MPI::gather(comm, flat_nodes, 0);
      const auto all_faces = Utilities::MPI::gather(comm, faces, 0);
      nodes.clear();
      faces.clear();
      for (const auto &part : all_nodes)
        for (std::size_t i = 0; i < part.size(); i += 6)
          {
            NodeSums &s = nodes[static_cast<NodeKey>(part[i])];
            s.theta_sum += part[i + 1];
            s.count += part[i + 2];
            s.force += Tensor<1, dim>({part[i + 3], part[i + 4]});
            s.vertex = std::max(s.vertex, part[i + 5]);
          }
      for (const auto &part : all_faces)
        faces.insert(faces.end(), part.begin(), part.end());
    }

    /// A band matrix, A(i, j) = band[i][j - i + w] for |i - j| <= w,
    /// diagonally dominant (a mass matrix), so no pivoting is needed.
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

      /// Solves A x = b by elimination without pivoting; A is copied, so
      /// it can be reused.
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
     * Rank 0: the nodal normals n_a (int phi_a n da over the line,
     * normalised; on a symmetry edge the mirror image's is added, which
     * leaves the radial direction) and the matrix
     * M_ab = int phi_a phi_b (n . n_a) da, rows and columns in @p index.
     * Projected on n_a and its tangent s_a, f_a = int t phi_a da becomes
     * M tau_n = f . n_a and M tau_s = f . s_a for t = tau_n n + tau_s s:
     * exact for a hydrostatic state (tau_n = -p) on a polygonal line too.
     */
    BandMatrix
    line_matrix(const RollBody                        &body,
                const FaceRecords                     &faces,
                const std::map<NodeKey, unsigned int> &index,
                const std::vector<double>             &theta,
                std::vector<Tensor<1, dim>>           &normal)
    {
      const unsigned int nf     = body.fe().base_element(0).degree + 1;
      const unsigned int record = nf + nf * (nf + 2);
      normal.assign(theta.size(), Tensor<1, dim>());
      unsigned int w = 0;
      for (std::size_t r = 0; r < faces.size(); r += record)
        for (unsigned int a = 0; a < nf; ++a)
          {
            const unsigned int i = index.at(static_cast<NodeKey>(faces[r + a]));
            for (unsigned int b = 0; b < nf; ++b)
              {
                const unsigned int j =
                  index.at(static_cast<NodeKey>(faces[r + b]));
                w = std::max(w, i > j ? i - j : j - i);
              }
            for (unsigned int q = 0; q < nf; ++q)
              {
                const double *p = &faces[r + nf + q * (nf + 2)];
                normal[i] += p[a] * Tensor<1, dim>({p[nf], p[nf + 1]});
              }
          }
      for (unsigned int i = 0; i < theta.size(); ++i)
        {
          if (on_symmetry_edge(body.scene(), theta[i]))
            {
              const Tensor<1, dim> e_r(
                {std::cos(theta[i]), std::sin(theta[i])});
              normal[i] = (normal[i] * e_r) * e_r;
            }
          normal[i] /= normal[i].norm();
        }
      BandMatrix M(theta.size(), w);
      for (std::size_t r = 0; r < faces.size(); r += record)
        for (unsigned int q = 0; q < nf; ++q)
          {
            const double        *p = &faces[r + nf + q * (nf + 2)];
            const Tensor<1, dim> n_da({p[nf], p[nf + 1]});
            for (unsigned int a = 0; a < nf; ++a)
              {
                const unsigned int i =
                  index.at(static_cast<NodeKey>(faces[r + a]));
                for (unsigned int b = 0; b < nf; ++b)
                  M(i, index.at(static_cast<NodeKey>(faces[r + b]))) +=
                    p[a] * p[b] * (n_da * normal[i]);
              }
          }
      return M;
    }

    /**
     * Rank 0: solves for the normal and shear traction of the nodes (zero
     * shear on a symmetry edge), filters them and returns the vertices'.
     * n_a points out of the region: away from the axis on an interface
     * seen from inside, towards it on the bond; sigma_nn and sigma_nt (n
     * away from the axis, s its counter-clockwise tangent) are tau_n and
     * tau_s either way.
     */
    std::vector<LineTraction>
    solve_on_root(const RollBody                    &body,
                  const std::map<NodeKey, NodeSums> &nodes,
                  const FaceRecords                 &faces)
    {
      std::vector<std::pair<double, NodeKey>> order;
      for (const auto &[key, s] : nodes)
        if (s.count > 0)
          order.emplace_back(s.theta_sum / s.count, key);
      std::sort(order.begin(), order.end());
      const unsigned int              n = order.size();
      std::map<NodeKey, unsigned int> index;
      std::vector<double>             theta(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          index[order[i].second] = i;
          theta[i]               = order[i].first;
        }
      std::vector<Tensor<1, dim>> normal;
      BandMatrix          M = line_matrix(body, faces, index, theta, normal);
      std::vector<double> f_n(n), f_s(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const Tensor<1, dim> &f = nodes.at(order[i].second).force;
          f_n[i]                  = f * normal[i];
          f_s[i] = f * Tensor<1, dim>({-normal[i][1], normal[i][0]});
        }
      const auto tau_n = smooth(M.solve(f_n), theta, false, body.scene());
      for (unsigned int i = 0; i < n; ++i)
        if (on_symmetry_edge(body.scene(), theta[i]))
          {
            M.make_identity_row(i);
            f_s[i] = 0;
          }
      const auto tau_s = smooth(M.solve(f_s), theta, true, body.scene());
      std::vector<LineTraction> result;
      for (unsigned int i = 0; i < n; ++i)
        if (nodes.at(order[i].second).vertex != 0)
          result.push_back({theta[i], tau_n[i], tau_s[i]});
      return result;
    }

    std::vector<LineTraction>
    recover(const RollBody &body, const LineChoice &line)
    {
      std::map<NodeKey, NodeSums> nodes;
      FaceRecords                 faces;
      add_line_geometry(body, line, nodes, faces);
      add_nodal_forces(body, line, line_keys(body, line), nodes);
      gather_on_root(nodes, faces, body.communicator());
      if (Utilities::MPI::this_mpi_process(body.communicator()) != 0 ||
          nodes.empty())
        return {};
      return solve_on_root(body, nodes, faces);
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
    return recover(body, line);
  }
} // namespace rollnip
