#ifndef rollnip_contact_surface_nodes_h
#define rollnip_contact_surface_nodes_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/global.h>

#include <vector>

namespace rollnip
{
  /// A vertex of the outer arc: its reference angle and position and the
  /// dofs of its displacement.
  struct SurfaceNode
  {
    double                  theta;
    Point<dim>              X;
    types::global_dof_index dof[dim];
  };

  /// The vertices of the outer arc (boundary id 1), ordered by reference
  /// angle, identical on all ranks.
  std::vector<SurfaceNode>
  outer_surface_nodes(const DoFHandler<dim> &dofs);

  /// The displacement part of @p v at @p nodes, on all ranks (@p owned:
  /// the locally owned dofs of @p v).
  std::vector<Tensor<1, dim>>
  surface_values(const std::vector<SurfaceNode>      &nodes,
                 const TrilinosWrappers::MPI::Vector &v,
                 const IndexSet                      &owned);
} // namespace rollnip

#endif
