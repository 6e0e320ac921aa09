// The compressible cover (Material/Poisson ratio < 0.5) in the 2D body,
// against independent truth:
// (a) a quarter tube under the same follower pressure p on both arcs, both
//     edges symmetric, deforms homogeneously, F = lambda I in plane, with
//     (2 C2 + kappa)(lambda^2 - 1) = -p, kappa = K - 2 G/3 + 2 C1 (the
//     closed form of the law, material/mooney_rivlin_law.h): exact on any
//     mesh and with either element;
// (b) the Lame tube in linear theory: inner pressure p, outer arc free,
//     plane strain, u = A r + B/r with B = p / (2 G (R1^-2 - R0^-2)) and
//     A = G B / ((lambda + G) R0^2): second-order convergence of the
//     radius changes; and the finite-strain law at small loads tends to
//     it, with a difference first order in the load (C1 = 0, where the
//     discrete linearisations coincide: small_load_limit.cc);
// (c) run 30 in indentation control: P(u0) at nu -> 0.5 tends to the
//     incompressible P, the difference linear in 1 - 2 nu (the same
//     mesh, element and contact method: only the constraint differs).

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/problem.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  constexpr double R1 = 47.2, R0 = 60.7;

  std::string
  material(const double C1, const double C2, const double nu)
  {
    return "subsection Material\n set C1 = " + testing::num(C1) +
           "\n set C2 = " + testing::num(C2) +
           "\n set Poisson ratio = " + testing::num(nu) + "\nend\n";
  }

  std::string
  tube(const unsigned int level, const std::string &outer)
  {
    return "subsection Mesh\n set Radial cells = 2\n set Circumferential "
           "cells = 4\n set Circumferential grading = 1\n"
           " set Global refinements = " +
           std::to_string(level) +
           "\nend\n"
           "subsection Boundary conditions\n set Inner arc (id 0) = pressure\n"
           " set Outer arc (id 1) = " +
           outer +
           "\n set Symmetry edge (id 2) = symmetry\n"
           " set Far edge (id 3) = symmetry\nend\n";
  }

  /// u_r at the inner and the outer radius on the line of centres [mm].
  std::pair<double, double>
  radius_changes(const Parameters::AllParameters &parameters)
  {
    RollProblem problem(parameters, MPI_COMM_WORLD);
    problem.setup();
    AssertThrow(problem.run().converged, ExcMessage("no convergence"));
    return {problem.radial_displacement_at(Point<dim>(R1, 0)),
            problem.radial_displacement_at(Point<dim>(R0, 0))};
  }

  void
  check_homogeneous(testing::Checker &check)
  {
    const double C1 = 0.25, C2 = 0.25, nu = 0.3, p = 0.2, G = 1;
    const double K      = 2 * G * (1 + nu) / (3 * (1 - 2 * nu));
    const double kappa  = K - 2 * G / 3 + 2 * C1;
    const double lambda = std::sqrt(1 - p / (2 * C2 + kappa));
    for (const std::string element : {"Q1-P0", "Q2-P1"})
      {
        const auto [a, b]  = radius_changes(testing::parameters_from_string(
          tube(1, "pressure") + material(C1, C2, nu) +
          "subsection Discretization\n set Element = " + element +
          "\nend\nsubsection Load\n set Pressure function = p0\n set p0 = " +
          testing::num(p) + "\nend\n"));
        const double error = std::max(std::abs(a / ((lambda - 1) * R1) - 1),
                                      std::abs(b / ((lambda - 1) * R0) - 1));
        check.check(error < 1e-6,
                    element + ", nu = 0.3, p = 0.2 MPa on both arcs: u_r(R1) " +
                      testing::num(a) + ", u_r(R0) " + testing::num(b) +
                      " mm, exact " + testing::num((lambda - 1) * R1) + ", " +
                      testing::num((lambda - 1) * R0) +
                      " mm (lambda = " + testing::num(lambda) +
                      "), relative error " + testing::num(error));
      }
  }

  std::string
  inner_pressure(const double p)
  {
    return "subsection Load\n set Pressure function = p0\n set p0 = " +
           testing::num(p) + "\nend\n";
  }

  void
  check_lame(testing::Checker &check, const double nu)
  {
    const double        G = 1, p = 0.1;
    const double        lambda_lame = 2 * G * nu / (1 - 2 * nu);
    const double        B       = p / (2 * G * (1 / (R1 * R1) - 1 / (R0 * R0)));
    const double        A       = G * B / ((lambda_lame + G) * R0 * R0);
    const double        exact_a = A * R1 + B / R1, exact_b = A * R0 + B / R0;
    std::vector<double> errors;
    for (const unsigned int level : {1u, 2u, 3u})
      {
        const auto [a, b] = radius_changes(testing::parameters_from_string(
          tube(level, "free") + material(0.3, 0.2, nu) + inner_pressure(p) +
          "subsection Material\n set Theory = linear\nend\n"));
        errors.push_back(
          std::max(std::abs(a / exact_a - 1), std::abs(b / exact_b - 1)));
        std::cout << "  Lame, nu = " << nu << ", level " << level
                  << ": u_r(R1) " << a << " (exact " << exact_a << "), u_r(R0) "
                  << b << " (exact " << exact_b << ") mm" << std::endl;
      }
    const double order = testing::order(errors[1], errors[2]);
    check.check(order > 1.7 && order < 2.5 && errors[2] < 1e-3,
                "Lame, nu = " + testing::num(nu) +
                  ": relative error at level 3 " + testing::num(errors[2]) +
                  ", observed order " + testing::num(order));
  }

  /// Finite strain at small loads against the linear theory, same mesh.
  void
  check_small_load(testing::Checker &check)
  {
    const double        nu     = 0.45;
    const auto          linear = radius_changes(testing::parameters_from_string(
      tube(2, "free") + material(0, 0.5, nu) + inner_pressure(1) +
      "subsection Material\n set Theory = linear\nend\n"));
    std::vector<double> differences;
    for (const double p : {1e-3, 1e-4})
      {
        const auto nonlinear = radius_changes(testing::parameters_from_string(
          tube(2, "free") + material(0, 0.5, nu) + inner_pressure(p) +
          "subsection Load stepping\n set Initial steps = 1\nend\n"));
        differences.push_back(
          std::max(std::abs(nonlinear.first / p / linear.first - 1),
                   std::abs(nonlinear.second / p / linear.second - 1)));
      }
    const double ratio = differences[0] / differences[1];
    check.check(differences[1] < 1e-3 && ratio > 8 && ratio < 12,
                "nu = 0.45, finite strain / p against linear theory: relative "
                "difference " +
                  testing::num(differences[0]) + " at p = 0.001, " +
                  testing::num(differences[1]) +
                  " at p = 0.0001 MPa (first order: ratio " +
                  testing::num(ratio) + ")");
  }

  /// P(u0 = 1 mm) of run 30 [N/mm].
  double
  run30_load(const double nu)
  {
    const auto p = testing::parameters_from_string(
      "subsection Mesh\n set Radial cells = 8\n set Circumferential cells = "
      "18\n set Circumferential grading = 10\n set Global refinements = 1\n"
      "end\n" +
      material(0.25, 0.25, nu) +
      "subsection Boundary conditions\n set Far edge (id 3) = free\nend\n"
      "subsection Contact\n set Mode = indentation\n set Values = 1\n"
      " set Indenter radius = 76.2\n set Conformity tolerance = 1e-8\n"
      " set Control tolerance = 1e-9\nend\n");
    RollProblem problem(p, MPI_COMM_WORLD);
    problem.setup();
    InverseContact contact(problem, p);
    return solve_controlled_nip(contact, p, 1.).nip_load;
  }

  void
  check_incompressible_limit(testing::Checker &check)
  {
    const double P    = run30_load(0.5);
    const double d4   = run30_load(0.4999) / P - 1;
    const double d3   = run30_load(0.499) / P - 1;
    const double rate = d3 / d4;
    // The difference is about 3.2 (1 - 2 nu): 6.4e-4 at nu = 0.4999.
    check.check(std::abs(d4) < 1e-3 && rate > 9 && rate < 11,
                "run 30, u0 = 1 mm: P = " + testing::num(P) +
                  " N/mm incompressible; nu = 0.4999: relative difference " +
                  testing::num(d4) + ", nu = 0.499: " + testing::num(d3) +
                  " (linear in 1 - 2 nu: ratio " + testing::num(rate) + ")");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 check;
  check_homogeneous(check);
  for (const double nu : {0.3, 0.45})
    check_lame(check, nu);
  check_small_load(check);
  check_incompressible_limit(check);
  return check.result();
}
