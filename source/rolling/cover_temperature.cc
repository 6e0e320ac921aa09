#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/rolling/cover_temperature.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace rollnip
{
  namespace
  {
    /// SI to the mm of the mesh: W/(m K) -> W/(mm K), W/(m^2 K) ->
    /// W/(mm^2 K), W/m^3 -> W/mm^3.
    constexpr double per_mm = 1e-3, per_mm2 = 1e-6, per_mm3 = 1e-9;

    /// The thermal data of one run, in mm units.
    struct ThermalData
    {
      const std::function<double(double)> &source; ///< [W/m^3] of r [mm]
      const Parameters::Rolling           &rolling;

      double
      k(const unsigned int layer) const
      {
        return per_mm * rolling.layer_conductivity(
                          rolling.conductivity.size() == 1 ? 0 : layer);
      }
      /// The source [W/mm^3] at the unit point @p xi of @p cell, at the
      /// radius the vertices' radii give there (bilinearly): the circle
      /// the point belongs to, not |x|, which a straight-edged cell
      /// brings inside its ring by up to r (1 - cos(dtheta / 2)).
      double
      s(const Triangulation<dim>::cell_iterator &cell,
        const Point<dim>                        &xi) const
      {
        const double r = (1 - xi[0]) * (1 - xi[1]) * cell->vertex(0).norm() +
                         xi[0] * (1 - xi[1]) * cell->vertex(1).norm() +
                         (1 - xi[0]) * xi[1] * cell->vertex(2).norm() +
                         xi[0] * xi[1] * cell->vertex(3).norm();
        return per_mm3 * source(r);
      }
      double
      h() const
      {
        return per_mm2 * rolling.heat_transfer;
      }
    };

    /// The cell matrix and right-hand side of the conduction problem on
    /// @p cell; with @p T (ghosted, not null) the cell's residual
    /// K T - f instead, in @p rhs.
    void
    cell_system(const DoFHandler<dim>::active_cell_iterator &cell,
                FEValues<dim>                               &fv,
                FEFaceValues<dim>                           &ffv,
                const ThermalData                           &data,
                FullMatrix<double>                          &A,
                Vector<double>                              &rhs)
    {
      const unsigned int n = fv.get_fe().n_dofs_per_cell();
      A                    = 0;
      rhs                  = 0;
      fv.reinit(cell);
      const double k = data.k(cell->material_id());
      for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
        {
          const double s = data.s(cell, fv.get_quadrature().point(q));
          for (unsigned int i = 0; i < n; ++i)
            {
              for (unsigned int j = 0; j < n; ++j)
                A(i, j) +=
                  k * fv.shape_grad(i, q) * fv.shape_grad(j, q) * fv.JxW(q);
              rhs(i) += s * fv.shape_value(i, q) * fv.JxW(q);
            }
        }
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == BoundaryIds::outer_arc)
          {
            ffv.reinit(cell, f);
            for (unsigned int q = 0; q < ffv.n_quadrature_points; ++q)
              for (unsigned int i = 0; i < n; ++i)
                {
                  for (unsigned int j = 0; j < n; ++j)
                    A(i, j) += data.h() * ffv.shape_value(i, q) *
                               ffv.shape_value(j, q) * ffv.JxW(q);
                  rhs(i) += data.h() * data.rolling.ambient *
                            ffv.shape_value(i, q) * ffv.JxW(q);
                }
          }
    }

    /// The cell values and the cell system of the conduction problem, one
    /// per loop over the cells (the solve and the core's flux use the same).
    struct ThermalScratch
    {
      ThermalScratch(const Mapping<dim> &mapping, const FiniteElement<dim> &fe)
          : quadrature(fe.degree + 2)
          , fv(mapping,
               fe,
               quadrature,
               update_values | update_gradients | update_quadrature_points |
                 update_JxW_values)
          , ffv(mapping,
                fe,
                QGauss<dim - 1>(fe.degree + 2),
                update_values | update_JxW_values)
          , A(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
          , f(fe.n_dofs_per_cell())
          , indices(fe.n_dofs_per_cell())
      {}

      /// The cell matrix and right-hand side of @p cell, and its DoFs.
      void
      assemble(const DoFHandler<dim>::active_cell_iterator &cell,
               const ThermalData                           &data)
      {
        cell_system(cell, fv, ffv, data, A, f);
        cell->get_dof_indices(indices);
      }

      const QGauss<dim>                    quadrature;
      FEValues<dim>                        fv;
      FEFaceValues<dim>                    ffv;
      FullMatrix<double>                   A;
      Vector<double>                       f;
      std::vector<types::global_dof_index> indices;
    };
  } // namespace

  CoverTemperature::CoverTemperature(
    const parallel::distributed::Triangulation<dim> &mesh,
    const Mapping<dim>                              &mapping,
    const unsigned int                               degree,
    const double                                     sector_angle)
      : mesh(mesh)
      , mapping(mapping)
      , fe(degree)
      , dofs(mesh)
      , sector_angle(sector_angle)
  {
    dofs.distribute_dofs(fe);
  }

  namespace
  {
    /// The mean of the field @p T over the boundary @p id [degC] and the
    /// integral of h (T - T_air) over it [W/mm] (collective).
    std::pair<double, double>
    boundary_values(const DoFHandler<dim>               &dofs,
                    const Mapping<dim>                  &mapping,
                    const TrilinosWrappers::MPI::Vector &T,
                    const types::boundary_id             id,
                    const ThermalData                   &data)
    {
      const QGauss<dim - 1> quadrature(dofs.get_fe().degree + 2);
      FEFaceValues<dim>     ffv(mapping,
                            dofs.get_fe(),
                            quadrature,
                            update_values | update_JxW_values);
      std::vector<double>   values(quadrature.size());
      double                integral = 0, length = 0, flux = 0;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                ffv.reinit(cell, f);
                ffv.get_function_values(T, values);
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  {
                    integral += values[q] * ffv.JxW(q);
                    length += ffv.JxW(q);
                    flux += data.h() * (values[q] - data.rolling.ambient) *
                            ffv.JxW(q);
                  }
              }
      const MPI_Comm comm = dofs.get_communicator();
      return {Utilities::MPI::sum(integral, comm) /
                Utilities::MPI::sum(length, comm),
              Utilities::MPI::sum(flux, comm)};
    }

    /// (r, T) at the nodes on the line of centres, on every process.
    std::vector<std::pair<double, double>>
    centre_line_profile(const DoFHandler<dim>               &dofs,
                        const Mapping<dim>                  &mapping,
                        const TrilinosWrappers::MPI::Vector &T)
    {
      std::map<types::global_dof_index, Point<dim>> points;
      DoFTools::map_dofs_to_support_points(mapping, dofs, points);
      std::vector<double> flat;
      for (const auto &[i, x] : points)
        if (dofs.locally_owned_dofs().is_element(i) &&
            std::abs(x[1]) < 1e-9 * x.norm() && x[0] > 0)
          flat.insert(flat.end(), {x[0], T[i]});
      std::vector<std::pair<double, double>> profile;
      for (const auto &part :
           Utilities::MPI::all_gather(dofs.get_communicator(), flat))
        for (std::size_t k = 0; k + 1 < part.size(); k += 2)
          profile.emplace_back(part[k], part[k + 1]);
      std::sort(profile.begin(), profile.end());
      return profile;
    }

    /// The heat into the core [W/mm]: minus the residual K T - f of the
    /// unconstrained system summed over the core's nodes (the consistent
    /// flux through the bond, collective).
    double
    core_flux(const DoFHandler<dim>               &dofs,
              const Mapping<dim>                  &mapping,
              const TrilinosWrappers::MPI::Vector &T,
              const ThermalData                   &data,
              const AffineConstraints<double>     &core)
    {
      ThermalScratch                scratch(mapping, dofs.get_fe());
      const unsigned int            n = scratch.f.size();
      Vector<double>                Tc(n), r(n);
      TrilinosWrappers::MPI::Vector residual(dofs.locally_owned_dofs(),
                                             dofs.get_communicator());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            scratch.assemble(cell, data);
            for (unsigned int i = 0; i < n; ++i)
              Tc(i) = T[scratch.indices[i]];
            scratch.A.vmult(r, Tc);
            r -= scratch.f;
            residual.add(scratch.indices, r);
          }
      residual.compress(VectorOperation::add);
      double flux = 0;
      for (const auto i : dofs.locally_owned_dofs())
        if (core.is_constrained(i))
          flux -= residual[i];
      return Utilities::MPI::sum(flux, dofs.get_communicator());
    }
  } // namespace

  CoverTemperatureResult
  CoverTemperature::solve(const std::function<double(double)> &source,
                          const Parameters::Rolling           &rolling)
  {
    const MPI_Comm  comm  = mesh.get_communicator();
    const IndexSet &owned = dofs.locally_owned_dofs();
    IndexSet        relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    AffineConstraints<double> constraints(relevant);
    const bool                fixed_core = rolling.core_condition ==
                            Parameters::CoreThermalCondition::fixed_temperature;
    if (fixed_core)
      VectorTools::interpolate_boundary_values(mapping,
                                               dofs,
                                               BoundaryIds::inner_arc,
                                               Functions::ConstantFunction<dim>(
                                                 rolling.core),
                                               constraints);
    constraints.close();
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned, owned, dsp, comm);
    TrilinosWrappers::MPI::Vector rhs(owned, comm), x(owned, comm);

    const ThermalData data{source, rolling};
    ThermalScratch    scratch(mapping, fe);
    double            generated = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          scratch.assemble(cell, data);
          for (unsigned int q = 0; q < scratch.quadrature.size(); ++q)
            generated +=
              data.s(cell, scratch.quadrature.point(q)) * scratch.fv.JxW(q);
          constraints.distribute_local_to_global(
            scratch.A, scratch.f, scratch.indices, matrix, rhs);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);

    SolverControl                  control(1, 0);
    TrilinosWrappers::SolverDirect solver(control);
    solver.solve(matrix, x, rhs);
    constraints.distribute(x);
    temperature.reinit(owned, relevant, comm);
    temperature = x;

    CoverTemperatureResult r;
    const double whole = 2. * numbers::PI / sector_angle * 1e3; // W/mm->W/m
    r.generated        = whole * Utilities::MPI::sum(generated, comm);
    const auto bond =
      boundary_values(dofs, mapping, temperature, BoundaryIds::inner_arc, data);
    const auto surface =
      boundary_values(dofs, mapping, temperature, BoundaryIds::outer_arc, data);
    r.bond    = bond.first;
    r.surface = surface.first;
    r.to_air  = whole * surface.second;
    r.to_core =
      fixed_core
        ? whole * core_flux(dofs, mapping, temperature, data, constraints)
        : 0.;
    r.max     = x.max();
    r.profile = centre_line_profile(dofs, mapping, temperature);
    return r;
  }

  void
  CoverTemperature::write_vtu(const std::string &directory,
                              const std::string &name) const
  {
    DataOut<dim> out;
    out.attach_dof_handler(dofs);
    out.add_data_vector(temperature, "temperature_degC");
    out.build_patches(mapping, fe.degree);
    const MPI_Comm     comm  = mesh.get_communicator();
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    auto               piece = [&](const unsigned int r) {
      return name + "." + Utilities::int_to_string(r, 4) + ".vtu";
    };
    write_atomically(directory + "/" + piece(rank),
                     [&](std::ostream &o) { out.write_vtu(o); });
    MPI_Barrier(comm);
    if (rank != 0)
      return;
    std::vector<std::string> pieces;
    for (unsigned int r = 0; r < Utilities::MPI::n_mpi_processes(comm); ++r)
      pieces.push_back(piece(r));
    write_atomically(directory + "/" + name + ".pvtu", [&](std::ostream &o) {
      out.write_pvtu_record(o, pieces);
    });
  }
  double
  profile_temperature(const std::vector<std::pair<double, double>> &profile,
                      const double                                  r)
  {
    if (profile.empty())
      return std::nan("");
    auto it = std::lower_bound(profile.begin(),
                               profile.end(),
                               std::make_pair(r, -1e300));
    if (it == profile.begin())
      return it->second;
    if (it == profile.end())
      return profile.back().second;
    const auto &a = *(it - 1), &b = *it;
    return a.second +
           (b.second - a.second) * (r - a.first) / (b.first - a.first);
  }
} // namespace rollnip
