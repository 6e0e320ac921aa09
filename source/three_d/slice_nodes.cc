#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <rollnip/three_d/slice_body.h>

namespace rollnip
{
  namespace three_d
  {
    std::map<types::global_dof_index, SliceBody::SurfaceNode>
    SliceBody::boundary_nodes(const types::boundary_id id) const
    {
      // The displacement's support points through the mapping: with Q2 the
      // edge and face nodes lie on the curved (manifold) surface, where
      // the dofs live, not on the straight chords between the vertices.
      const Quadrature<dim> support(
        fe.base_element(0).get_unit_support_points());
      FEValues<dim> fv(*mapping, fe, support, update_quadrature_points);
      std::vector<types::global_dof_index>           dofs(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, SurfaceNode> nodes;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                fv.reinit(cell);
                cell->get_dof_indices(dofs);
                std::map<unsigned int, SurfaceNode> by_support_point;
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  {
                    const auto [c, k] = fe.system_to_component_index(i);
                    if (c >= dim || !fe.has_support_on_face(i, f))
                      continue;
                    by_support_point[k].dofs[c] = dofs[i];
                    by_support_point[k].X       = fv.quadrature_point(k);
                  }
                for (const auto &[k, node] : by_support_point)
                  nodes[node.dofs[0]] = node;
              }
      return nodes;
    }

    TrilinosWrappers::MPI::Vector
    SliceBody::lumped_areas(const types::boundary_id id,
                            const bool               deformed) const
    {
      // int phi_i dA: the row sums of the face mass matrix, positive for
      // tensor-product Q1 and Q2 (1D weights 1/2, 1/2 and 1/6, 2/3, 1/6).
      // The current area element is J |F^-T N| dA_0 (Nanson).
      FEFaceValues<dim>                    fv(*mapping,
                           fe,
                           QGauss<dim - 1>(degree + 1),
                           update_values | update_gradients |
                             update_normal_vectors | update_JxW_values);
      const FEValuesExtractors::Vector     u_ex(0);
      std::vector<Tensor<2, dim>>          grad_u(fv.n_quadrature_points);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      TrilinosWrappers::MPI::Vector        area(owned, communicator);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                fv.reinit(cell, f);
                cell->get_dof_indices(dofs);
                fv[u_ex].get_function_gradients(solution, grad_u);
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  {
                    if (fe.system_to_component_index(i).first != 0 ||
                        !fe.has_support_on_face(i, f))
                      continue;
                    double a = 0;
                    for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                      {
                        double stretch = 1;
                        if (deformed)
                          {
                            const Tensor<2, dim> F =
                              unit_symmetric_tensor<dim>() + grad_u[q];
                            stretch = determinant(F) * (invert(transpose(F)) *
                                                        fv.normal_vector(q))
                                                         .norm();
                          }
                        a += fv.shape_value_component(i, q, 0) * stretch *
                             fv.JxW(q);
                      }
                    area.add(std::vector<types::global_dof_index>{dofs[i]},
                             std::vector<double>{a});
                  }
              }
      area.compress(VectorOperation::add);
      TrilinosWrappers::MPI::Vector ghosted(owned, relevant, communicator);
      ghosted = area;
      return ghosted;
    }
  } // namespace three_d
} // namespace rollnip
