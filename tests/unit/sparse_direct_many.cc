// SparseDirectSolver::solve with several right-hand sides (the contact
// iteration's sensitivities: one per pressure parameter) against its
// one-vector solves and against the system itself: on a nonsymmetric
// saddle-point matrix (zero diagonal block, as the Q1-P0 and Q2-P1 Newton
// matrices), each column of the batched solve leaves a residual of
// round-off and equals the one-vector solve to round-off, for MUMPS (one
// solve phase for all columns) and KLU (one solve per column).

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <rollnip/solvers/sparse_direct.h>

#include <random>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr unsigned int n_a = 300, n_b = 40, n = n_a + n_b;

  /// [A B; B^T 0]: A diagonally dominant and nonsymmetric, B of full
  /// column rank (two entries per column in rows of their own).
  void
  make_matrix(TrilinosWrappers::SparseMatrix &matrix)
  {
    std::vector<std::tuple<unsigned int, unsigned int, double>> entries;
    for (unsigned int i = 0; i < n_a; ++i)
      {
        entries.emplace_back(i, i, 4. + 0.01 * i);
        if (i + 1 < n_a)
          entries.emplace_back(i, i + 1, -1.3);
        if (i > 0)
          entries.emplace_back(i, i - 1, -0.7);
        entries.emplace_back(i, (7 * i + 3) % n_a, 0.2);
      }
    for (unsigned int j = 0; j < n_b; ++j)
      for (const auto &[row, value] : {std::pair{6 * j, 1.}, {6 * j + 1, 0.5}})
        {
          entries.emplace_back(row, n_a + j, value);
          entries.emplace_back(n_a + j, row, value);
        }
    DynamicSparsityPattern pattern(n, n);
    for (const auto &[i, j, v] : entries)
      pattern.add(i, j);
    IndexSet all = complete_index_set(n);
    matrix.reinit(all, all, pattern, MPI_COMM_WORLD);
    for (const auto &[i, j, v] : entries)
      matrix.add(i, j, v);
    matrix.compress(VectorOperation::add);
  }

  void
  check_solver(const std::string                    &name,
               const TrilinosWrappers::SparseMatrix &matrix,
               testing::Checker                     &checker)
  {
    const unsigned int                         m = 12;
    std::mt19937                               random(42);
    std::uniform_real_distribution<double>     value(-1., 1.);
    const IndexSet                             all = complete_index_set(n);
    std::vector<TrilinosWrappers::MPI::Vector> b(m), batched(m), single(m);
    for (unsigned int k = 0; k < m; ++k)
      {
        b[k].reinit(all, MPI_COMM_WORLD);
        for (unsigned int i = 0; i < n; ++i)
          b[k][i] = value(random);
        batched[k].reinit(all, MPI_COMM_WORLD);
        single[k].reinit(all, MPI_COMM_WORLD);
      }
    SparseDirectSolver solver(name);
    solver.factorize(matrix);
    solver.solve(b, batched);
    for (unsigned int k = 0; k < m; ++k)
      solver.solve(b[k], single[k]);

    double residual = 0, difference = 0;
    for (unsigned int k = 0; k < m; ++k)
      {
        TrilinosWrappers::MPI::Vector r(all, MPI_COMM_WORLD);
        matrix.vmult(r, batched[k]);
        r -= b[k];
        residual = std::max(residual, r.l2_norm() / b[k].l2_norm());
        r        = batched[k];
        r -= single[k];
        difference = std::max(difference, r.l2_norm() / single[k].l2_norm());
      }
    checker.check(residual < 1e-12,
                  name + ": " + std::to_string(m) +
                    " right-hand sides at once, largest |A x - b| / |b| = " +
                    testing::num(residual) + " (< 1e-12)");
    checker.check(difference < 1e-12,
                  name + ": each the one-vector solve's to " +
                    testing::num(difference) + " (< 1e-12)");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  TrilinosWrappers::SparseMatrix   matrix;
  make_matrix(matrix);
  for (const std::string name : {"Amesos_Mumps", "Amesos_Klu"})
    check_solver(name, matrix, checker);
  return checker.result();
}
