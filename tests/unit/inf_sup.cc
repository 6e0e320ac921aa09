// Is the element inf-sup stable? The discrete inf-sup constant beta_h of
// the incompressible problem satisfies
//   beta_h^2 = G lambda_min(S, M_p),  S = B A^-1 B^T,
// with A the displacement block of linear theory (2 G eps : eps), B the
// constraint block and M_p the pressure mass matrix (doc/intro.md,
// section 3). A stable pair keeps beta_h bounded below as h -> 0; Q1-P0 is
// known not to (beta_h ~ h, the checkerboard family). Measured on the
// default roll section (quarter roll, uniform cells, fixed core, free
// outer arc), refined three times (Q1-P0) and twice (Q2-P1).
// The Schur complement is formed densely, so the meshes stay small.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <functional>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <rollnip/fe_fields.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  /// +1/-1 on the cells of a mesh whose cell graph is two-coloured (the
  /// structured roll meshes): neighbours across a face get opposite signs.
  std::vector<int>
  checkerboard_signs(const DoFHandler<dim> &dof_handler)
  {
    std::vector<int> sign(dof_handler.get_triangulation().n_active_cells(), 0);
    std::vector<DoFHandler<dim>::active_cell_iterator> queue = {
      dof_handler.begin_active()};
    sign[queue[0]->active_cell_index()] = 1;
    for (unsigned int k = 0; k < queue.size(); ++k)
      for (const auto f : queue[k]->face_indices())
        if (!queue[k]->at_boundary(f))
          {
            const auto n = queue[k]->neighbor(f);
            if (sign[n->active_cell_index()] == 0)
              {
                sign[n->active_cell_index()] =
                  -sign[queue[k]->active_cell_index()];
                queue.push_back(n);
              }
            else
              AssertThrow(sign[n->active_cell_index()] ==
                            -sign[queue[k]->active_cell_index()],
                          ExcMessage("mesh is not two-colourable"));
          }
    return sign;
  }

  /// sum s_K v_K |K| / sum |v_K| |K| for a cellwise field v: 1 for a pure
  /// checkerboard, O(h) for a smooth field.
  double
  checkerboard_fraction(const DoFHandler<dim>     &dof_handler,
                        const std::vector<double> &cell_values,
                        const std::function<bool(const Point<dim> &)> &in)
  {
    const auto sign        = checkerboard_signs(dof_handler);
    double     alternating = 0, total = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (in(cell->center()))
        {
          const double v = cell_values[cell->active_cell_index()];
          alternating += sign[cell->active_cell_index()] * v * cell->measure();
          total += std::abs(v) * cell->measure();
        }
    return std::abs(alternating) / total;
  }

  /// The displacement and pressure DoFs of a problem, each numbered in
  /// its own block.
  struct Blocks
  {
    IndexSet                  is_pressure;
    std::vector<int>          block_index; ///< of each DoF in its block
    std::vector<unsigned int> u_dofs, p_dofs;
  };

  /// The blocks of the DoFs of @p dof_handler.
  Blocks
  split_blocks(const DoFHandler<dim> &dof_handler)
  {
    Blocks b;
    b.is_pressure =
      DoFTools::extract_dofs(dof_handler, ComponentMask({false, false, true}));
    const unsigned int n = dof_handler.n_dofs();
    b.block_index.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      if (b.is_pressure.is_element(i))
        {
          b.block_index[i] = b.p_dofs.size();
          b.p_dofs.push_back(i);
        }
      else
        {
          b.block_index[i] = b.u_dofs.size();
          b.u_dofs.push_back(i);
        }
    return b;
  }

  /// S = B A^-1 B^T (symmetrised) from the assembled tangent @p K.
  Eigen::MatrixXd
  schur_complement(const TrilinosWrappers::SparseMatrix &K,
                   const Blocks                         &blocks)
  {
    // A and B from the assembled tangent (constrained rows of A carry only
    // their diagonal, so they decouple).
    using Triplet = Eigen::Triplet<double>;
    std::vector<Triplet> a_entries, b_entries;
    for (unsigned int row = 0; row < blocks.block_index.size(); ++row)
      for (auto entry = K.begin(row); entry != K.end(row); ++entry)
        {
          const unsigned int col = entry->column();
          if (entry->value() == 0)
            continue;
          const bool p_row = blocks.is_pressure.is_element(row);
          const bool p_col = blocks.is_pressure.is_element(col);
          if (!p_row && !p_col)
            a_entries.emplace_back(blocks.block_index[row],
                                   blocks.block_index[col],
                                   entry->value());
          else if (p_row && !p_col)
            b_entries.emplace_back(blocks.block_index[row],
                                   blocks.block_index[col],
                                   entry->value());
        }
    const auto                  n_u = blocks.u_dofs.size();
    const auto                  n_p = blocks.p_dofs.size();
    Eigen::SparseMatrix<double> A(n_u, n_u);
    Eigen::SparseMatrix<double> B(n_p, n_u);
    A.setFromTriplets(a_entries.begin(), a_entries.end());
    B.setFromTriplets(b_entries.begin(), b_entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
    const Eigen::MatrixXd X = lu.solve(Eigen::MatrixXd(B.transpose()));
    Eigen::MatrixXd       S = B * X;
    S                       = 0.5 * (S + S.transpose());
    return S;
  }

  /// The pressure mass matrix, cell by cell.
  Eigen::MatrixXd
  pressure_mass_matrix(const DoFHandler<dim> &dof_handler, const Blocks &blocks)
  {
    const auto                          &fe = dof_handler.get_fe();
    MappingQ<dim>                        mapping(2);
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            FEFields::cell_quadrature(fe),
                            update_values | update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    const auto                           n_p = blocks.p_dofs.size();
    Eigen::MatrixXd                      M   = Eigen::MatrixXd::Zero(n_p, n_p);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          for (unsigned int j = 0; j < dofs.size(); ++j)
            if (fe.system_to_component_index(i).first == dim &&
                fe.system_to_component_index(j).first == dim)
              for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
                M(blocks.block_index[dofs[i]], blocks.block_index[dofs[j]]) +=
                  fe_values[FEFields::pressure].value(i, q) *
                  fe_values[FEFields::pressure].value(j, q) * fe_values.JxW(q);
      }
    return M;
  }

  /// The pressure mode @p mode (one value per cell, Q1-P0) as cell values.
  std::vector<double>
  cell_values(const DoFHandler<dim> &dof_handler,
              const Blocks          &blocks,
              const Eigen::VectorXd &mode)
  {
    const auto                          &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<double> v(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (fe.system_to_component_index(i).first == dim)
            v[cell->active_cell_index()] = mode(blocks.block_index[dofs[i]]);
      }
    return v;
  }

  /// G lambda_min(S, M_p) for the scene at @p refinements.
  double
  inf_sup_squared(const std::string &element,
                  const unsigned int refinements,
                  double            *checkerboard = nullptr)
  {
    const auto parameters = testing::parameters_from_string(
      "subsection Mesh\n set Radial cells = 2\n set Circumferential cells = 6\n"
      " set Circumferential grading = 1\n set Global refinements = " +
      std::to_string(refinements) +
      "\nend\n"
      "subsection Material\n set Theory = linear\nend\n"
      // Assembled at load 0, so the load does not enter S; the default
      // zone (10 deg) is narrower than two 15 deg cells at level 0, which
      // the setup refuses: load the whole arc.
      "subsection Load\n set Pressure function = p0\nend\n"
      "subsection Discretization\n set Element = " +
      element + "\nend\n");
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    problem.assemble(0., true);

    const auto           &dof_handler = problem.dofs();
    const Blocks          blocks      = split_blocks(dof_handler);
    const Eigen::MatrixXd S = schur_complement(problem.tangent(), blocks);
    const Eigen::MatrixXd M = pressure_mass_matrix(dof_handler, blocks);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(S, M);
    const double G     = 2. * (parameters.material.layer_C1.back() +
                           parameters.material.layer_C2.back());
    const double beta2 = G * eigen.eigenvalues().minCoeff();
    if (checkerboard && element == "Q1-P0")
      {
        // The weakest pressure mode, one value per cell.
        Eigen::Index k;
        eigen.eigenvalues().minCoeff(&k);
        const std::vector<double> v =
          cell_values(dof_handler, blocks, eigen.eigenvectors().col(k));
        *checkerboard = checkerboard_fraction(dof_handler, v, [](const auto &) {
          return true;
        });
      }
    std::cout << "  " << element << ", refinement " << refinements << ": "
              << blocks.p_dofs.size()
              << " pressure DoFs, beta_h^2 = " << testing::num(beta2)
              << ", largest G lambda = "
              << testing::num(G * eigen.eigenvalues().maxCoeff()) << std::endl;
    return beta2;
  }

  /// Checkerboard fraction of the cell-mean pressure q in the nip (outer
  /// half of the cover, theta < 1.5 theta0) of the parabolic-pressure scene.
  double
  nip_pressure_checkerboard(const std::string &element,
                            const unsigned int refinements)
  {
    const auto parameters = testing::parameters_from_string(
      "subsection Mesh\n set Global refinements = " +
      std::to_string(refinements) +
      "\nend\n"
      "subsection Load\n set p0 = 0.5\nend\n"
      "subsection Discretization\n set Element = " +
      element + "\nend\n");
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    problem.set_step_log(false);
    AssertThrow(problem.run().converged, ExcMessage("scene did not converge"));

    const auto         &dof_handler = problem.dofs();
    const auto         &fe          = dof_handler.get_fe();
    MappingQ<dim>       mapping(2);
    FEValues<dim>       fe_values(mapping,
                            fe,
                            FEFields::cell_quadrature(fe),
                            update_values | update_JxW_values);
    std::vector<double> q(fe_values.n_quadrature_points);
    std::vector<double> mean(dof_handler.get_triangulation().n_active_cells());
    double              q_max  = 0;
    const double        R0     = parameters.geometry.outer_radius;
    const double        R1     = parameters.geometry.inner_radius;
    const double        theta0 = parameters.load.theta0;
    auto                in_nip = [&](const Point<dim> &X) {
      return X.norm() > 0.5 * (R0 + R1) &&
             std::abs(std::atan2(X[1], X[0])) < 1.5 * theta0;
    };
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[FEFields::pressure].get_function_values(
          problem.current_solution(), q);
        double integral = 0;
        for (unsigned int k = 0; k < q.size(); ++k)
          integral += q[k] * fe_values.JxW(k);
        mean[cell->active_cell_index()] = integral / cell->measure();
        if (in_nip(cell->center()))
          q_max = std::max(q_max, std::abs(mean[cell->active_cell_index()]));
      }
    const double fraction = checkerboard_fraction(dof_handler, mean, in_nip);
    std::cout << "  " << element << ", refinement " << refinements
              << ": nip pressure checkerboard fraction "
              << testing::num(fraction) << " (max |q| in the nip "
              << testing::num(q_max) << " MPa)" << std::endl;
    return fraction;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;

  std::vector<double> q1, q2;
  double              mode_checkerboard = 0;
  for (unsigned int r = 0; r <= 3; ++r)
    q1.push_back(inf_sup_squared("Q1-P0", r, &mode_checkerboard));
  for (unsigned int r = 0; r <= 2; ++r)
    q2.push_back(inf_sup_squared("Q2-P1", r));
  std::vector<double> nip_q1, nip_q2;
  for (unsigned int r = 0; r <= 2; ++r)
    nip_q1.push_back(nip_pressure_checkerboard("Q1-P0", r));
  for (unsigned int r = 0; r <= 1; ++r)
    nip_q2.push_back(nip_pressure_checkerboard("Q2-P1", r));
  std::cout << "  weakest Q1-P0 mode (refinement 3): checkerboard fraction "
            << testing::num(mode_checkerboard) << std::endl;

  // Q2-P1: beta_h bounded below, converging.
  for (unsigned int r = 0; r + 1 < q2.size(); ++r)
    checker.check(q2[r + 1] > 0.9 * q2[r] && q2[r + 1] < 1.1 * q2[r] &&
                    q2[r + 1] > 0.2,
                  "Q2-P1 stable: beta_h^2 " + testing::num(q2[r]) + " -> " +
                    testing::num(q2[r + 1]) +
                    " changes by < 10 % and stays > 0.2");
  // Q1-P0: beta_h ~ h (order of beta_h itself approaches 1).
  for (unsigned int r = 0; r + 1 < q1.size(); ++r)
    {
      const double order = 0.5 * testing::order(q1[r], q1[r + 1]);
      checker.check(order > 0.7 && order < 1.2,
                    "Q1-P0 not stable: beta_h falls at order " +
                      testing::num(order) + " in [0.7, 1.2] (theory: 1)");
    }
  checker.check(mode_checkerboard > 0.9,
                "the weakest Q1-P0 pressure mode is a checkerboard: "
                "fraction " +
                  testing::num(mode_checkerboard) + " > 0.9");
  // ... which the nip loading does not excite: the checkerboard part of
  // the pressure falls with h, as in the stable element.
  for (unsigned int r = 0; r + 1 < nip_q1.size(); ++r)
    checker.check(nip_q1[r + 1] < 0.5 * nip_q1[r],
                  "Q1-P0 nip pressure checkerboard falls with h: " +
                    testing::num(nip_q1[r]) + " -> " +
                    testing::num(nip_q1[r + 1]));
  for (unsigned int r = 0; r < nip_q2.size(); ++r)
    checker.check(nip_q1[r] < 2 * nip_q2[r] + 1e-3,
                  "Q1-P0 nip checkerboard " + testing::num(nip_q1[r]) +
                    " within 2x of Q2-P1's " + testing::num(nip_q2[r]) +
                    " at refinement " + std::to_string(r));

  return checker.result();
}
