#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <rollnip/body/nested_transfer.h>

#include <vector>

namespace rollnip
{
  namespace
  {
    using CellIterator = Triangulation<dim>::cell_iterator;

    /// The children of @p cell's ancestors down to it, from the coarse
    /// cell; returns the coarse cell.
    CellIterator
    path_from_coarse(CellIterator cell, std::vector<unsigned int> &path)
    {
      path.clear();
      while (cell->level() > 0)
        {
          const CellIterator parent = cell->parent();
          unsigned int       c      = 0;
          while (parent->child(c) != cell)
            ++c;
          path.push_back(c);
          cell = parent;
        }
      return cell;
    }

    /// The active descendant of @p cell that holds the point of unit
    /// coordinates @p p, which becomes the point's unit coordinates in it.
    CellIterator
    active_cell_around(CellIterator cell, Point<dim> &p)
    {
      while (cell->has_children())
        {
          unsigned int child = 0;
          for (unsigned int d = 0; d < dim; ++d)
            if (p[d] >= 0.5)
              child += 1u << d;
          p    = GeometryInfo<dim>::cell_to_child_coordinates(p, child);
          cell = cell->child(child);
        }
      return cell;
    }
  } // namespace

  bool
  transfer_nested_displacement(const RollBody &from, RollBody &to)
  {
    const auto &tria_from = from.mesh();
    const auto &tria_to   = to.mesh();
    if (Utilities::MPI::n_mpi_processes(to.communicator()) > 1 ||
        tria_from.n_cells(0) != tria_to.n_cells(0))
      return false;
    const FESystem<dim> &fe_from = from.fe();
    const FESystem<dim> &fe_to   = to.fe();
    const auto          &u_from  = from.solution();
    const auto          &q_to    = fe_to.base_element(0);

    TrilinosWrappers::MPI::Vector        u_to(to.owned_solution());
    std::vector<types::global_dof_index> dofs_to(fe_to.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs_from(fe_from.n_dofs_per_cell());
    std::vector<unsigned int>            path;
    u_to = 0;
    for (const auto &cell : to.dofs().active_cell_iterators())
      {
        cell->get_dof_indices(dofs_to);
        const CellIterator coarse =
          path_from_coarse(CellIterator(&tria_to, cell->level(), cell->index()),
                           path);
        for (unsigned int i = 0; i < fe_to.n_dofs_per_cell(); ++i)
          {
            // Displacement nodes only (base element 0, FE_Q).
            const auto base = fe_to.system_to_base_index(i);
            if (base.first.first != 0)
              continue;
            const unsigned int component =
              fe_to.system_to_component_index(i).first;
            // The node in the coarse cell's unit coordinates, then in the
            // active cell of @p from that holds it.
            Point<dim> p = q_to.unit_support_point(base.second);
            for (const unsigned int c : path)
              p = GeometryInfo<dim>::child_to_cell_coordinates(p, c);
            const CellIterator found =
              active_cell_around(CellIterator(&tria_from, 0, coarse->index()),
                                 p);
            const DoFHandler<dim>::active_cell_iterator source(&tria_from,
                                                               found->level(),
                                                               found->index(),
                                                               &from.dofs());
            source->get_dof_indices(dofs_from);
            double value = 0;
            for (unsigned int j = 0; j < fe_from.n_dofs_per_cell(); ++j)
              if (fe_from.system_to_base_index(j).first.first == 0 &&
                  fe_from.system_to_component_index(j).first == component)
                value += u_from[dofs_from[j]] *
                         fe_from.shape_value_component(j, p, component);
            u_to[dofs_to[i]] = value;
          }
      }
    u_to.compress(VectorOperation::insert);
    to.constraints().distribute(u_to);
    to.set_solution(u_to);
    return true;
  }
} // namespace rollnip
