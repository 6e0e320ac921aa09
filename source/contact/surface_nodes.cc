#include <deal.II/base/mpi.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/contact/surface_nodes.h>
#include <rollnip/geometry/angles.h>

#include <cmath>
#include <map>

namespace rollnip
{
  std::vector<SurfaceNode>
  outer_surface_nodes(const DoFHandler<dim> &dofs)
  {
    std::vector<double> flat;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == BoundaryIds::outer_arc)
            for (unsigned int v = 0; v < 2; ++v)
              {
                const Point<dim> X = cell->face(f)->vertex(v);
                flat.insert(flat.end(),
                            {reference_angle(X),
                             X[0],
                             X[1],
                             double(cell->face(f)->vertex_dof_index(v, 0)),
                             double(cell->face(f)->vertex_dof_index(v, 1))});
              }
    // Keyed by the angle: a vertex shared by two faces or two ranks once.
    std::map<long long, SurfaceNode> unique;
    for (const auto &part :
         Utilities::MPI::all_gather(dofs.get_communicator(), flat))
      for (std::size_t i = 0; i < part.size(); i += 5)
        unique[std::llround(part[i] * 1e9)] =
          SurfaceNode{part[i],
                      Point<dim>(part[i + 1], part[i + 2]),
                      {types::global_dof_index(part[i + 3]),
                       types::global_dof_index(part[i + 4])}};
    std::vector<SurfaceNode> nodes;
    for (const auto &entry : unique)
      nodes.push_back(entry.second);
    return nodes;
  }

  std::vector<Tensor<1, dim>>
  surface_values(const std::vector<SurfaceNode>      &nodes,
                 const TrilinosWrappers::MPI::Vector &v,
                 const IndexSet                      &owned)
  {
    std::vector<double> values(dim * nodes.size(), 0.);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        if (owned.is_element(nodes[i].dof[d]))
          values[dim * i + d] = v[nodes[i].dof[d]];
    Utilities::MPI::sum(values, v.get_mpi_communicator(), values);
    std::vector<Tensor<1, dim>> u(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        u[i][d] = values[dim * i + d];
    return u;
  }
} // namespace rollnip
