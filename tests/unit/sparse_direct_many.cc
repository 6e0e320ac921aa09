// SparseDirectSolver::solve with several right-hand sides (the contact
// iteration's sensitivities: one per pressure parameter) against its
// one-vector solves and against the system itself: on a nonsymmetric
// saddle-point matrix (zero diagonal block, as the Q1-P0 and Q2-P1 Newton
// matrices), each column of the batched solve leaves a residual of
// round-off and equals the one-vector solve to round-off, for MUMPS (one
// solve phase for all columns) and KLU (one solve per column); after it,
// a numeric refactorisation of the matrix times 2 and a one-vector solve
// give half the first answer (the solver's state for one vector intact).
// Run on one process and, by cli_mpi_unit_sparse_direct_many, on two: the
// rows split between them, MUMPS on process 0 alone for a matrix this
// small (the other outside its communicator).

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

  /// The rows this process owns: a contiguous share.
  IndexSet
  owned_rows()
  {
    const unsigned int p = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int r = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    IndexSet           owned(n);
    owned.add_range(r * n / p, (r + 1) * n / p);
    return owned;
  }

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
    const IndexSet         owned = owned_rows();
    DynamicSparsityPattern pattern(n, n);
    for (const auto &[i, j, v] : entries)
      pattern.add(i, j);
    matrix.reinit(owned, owned, pattern, MPI_COMM_WORLD);
    for (const auto &[i, j, v] : entries)
      if (owned.is_element(i))
        matrix.add(i, j, v);
    matrix.compress(VectorOperation::add);
  }

  double
  relative_difference(const TrilinosWrappers::MPI::Vector &x,
                      const TrilinosWrappers::MPI::Vector &y)
  {
    TrilinosWrappers::MPI::Vector d = x;
    d -= y;
    return d.l2_norm() / y.l2_norm();
  }

  void
  check_solver(const std::string                    &name,
               const TrilinosWrappers::SparseMatrix &original,
               testing::Checker                     &checker)
  {
    TrilinosWrappers::SparseMatrix matrix;
    matrix.copy_from(original);
    const unsigned int                         m = 12;
    std::mt19937                               random(42);
    std::uniform_real_distribution<double>     value(-1., 1.);
    const IndexSet                             owned = owned_rows();
    std::vector<TrilinosWrappers::MPI::Vector> b(m), batched(m), single(m);
    for (unsigned int k = 0; k < m; ++k)
      {
        b[k].reinit(owned, MPI_COMM_WORLD);
        // The same vector on any number of processes.
        for (unsigned int i = 0; i < n; ++i)
          if (const double v = value(random); owned.is_element(i))
            b[k][i] = v;
        b[k].compress(VectorOperation::insert);
        batched[k].reinit(owned, MPI_COMM_WORLD);
        single[k].reinit(owned, MPI_COMM_WORLD);
      }
    SparseDirectSolver solver(name);
    solver.factorize(matrix);
    solver.solve(b, batched);
    for (unsigned int k = 0; k < m; ++k)
      solver.solve(b[k], single[k]);

    double residual = 0, difference = 0;
    for (unsigned int k = 0; k < m; ++k)
      {
        TrilinosWrappers::MPI::Vector r(owned, MPI_COMM_WORLD);
        matrix.vmult(r, batched[k]);
        residual = std::max(residual, relative_difference(r, b[k]));
        difference =
          std::max(difference, relative_difference(batched[k], single[k]));
      }
    checker.check(residual < 1e-12,
                  name + ": " + std::to_string(m) +
                    " right-hand sides at once, largest |A x - b| / |b| = " +
                    testing::num(residual) + " (< 1e-12)");
    checker.check(difference < 1e-12,
                  name + ": each the one-vector solve's to " +
                    testing::num(difference) + " (< 1e-12)");

    // The same pattern refactorised numerically, then one vector.
    matrix *= 2.;
    solver.factorize(matrix);
    TrilinosWrappers::MPI::Vector half(owned, MPI_COMM_WORLD);
    solver.solve(b[0], half);
    half *= 2.;
    const double refactorised = relative_difference(half, single[0]);
    checker.check(refactorised < 1e-12,
                  name +
                    ": then 2 A refactorised, one vector: half the "
                    "answer to " +
                    testing::num(refactorised) + " (< 1e-12)");
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
