// The engineering forms of the inputs (doc/engineering_inputs.md) give the
// same nip as the program's own: a 250 mm roll with a 13.5 mm cover of
// 60 Shore A against a 300 mm roll at 40 N/mm, level 1 of a 16 x 4 mesh.
//  - Roll diameter, Cover thickness and Indenter diameter against the radii
//    R0 = 125, R1 = 111.5, Rbar = 150 mm: the same numbers (1e-12).
//  - Hardness = 60 Shore A against C1 = E/6, C2 = 0 with Gent's E written
//    out in 17 digits: the same (1e-12).
//  - The load as 40 N/mm, 40 kN/m, 228.4 pli and a total force of 200 kN
//    on a 5000 mm face: the same target, so the same nip; kN/m and the
//    total force exactly, pli to the control tolerance (P within 1e-6, u0
//    and b within 1e-5).
//  - A two-layer cover given as Hardness = 90, 60 Shore A: each layer's
//    C1 + C2 is its own E/6 from Gent's relation (1e-15), and the nip
//    report's modulus is the top layer's.

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/material/hardness.h>
#include <rollnip/problem.h>

#include "test_tools.h"

using namespace rollnip;

namespace
{
  const std::string mesh =
    "subsection Mesh\n set Radial cells = 4\n set Global refinements = 1\n"
    "end\n";
  const std::string radii = "subsection Geometry\n set Inner radius = 111.5\n"
                            " set Outer radius = 125\nend\n";
  const std::string diameters =
    "subsection Geometry\n set Roll diameter = 250\n set Cover thickness = "
    "13.5\nend\n";
  const std::string hardness =
    "subsection Material\n set Hardness = 60\n set Hardness scale = Shore "
    "A\nend\n";

  std::string
  contact(const std::string &indenter,
          const std::string &unit,
          const std::string &value)
  {
    return "subsection Contact\n set Mode = load\n " + indenter +
           "\n set Load unit = " + unit + "\n set Values = " + value +
           "\nend\n";
  }

  ContactResult
  solve(const std::string &text)
  {
    const auto  p = testing::parameters_from_string(mesh + text);
    RollProblem problem(p, MPI_COMM_WORLD);
    problem.setup();
    InverseContact contact(problem, p);
    return solve_controlled_nip(contact, p, p.contact.values[0]);
  }

  std::string
  full_precision(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(17) << x;
    return s.str();
  }

  double
  rel(const double a, const double b)
  {
    return std::abs(a / b - 1);
  }

  /// The largest relative difference of P, u0 and b of two nips.
  double
  difference(const ContactResult &a, const ContactResult &b)
  {
    return std::max({rel(a.nip_load, b.nip_load),
                     rel(a.indentation, b.indentation),
                     rel(a.half_chord, b.half_chord)});
  }

  /// Hardness per layer: each layer's Mooney-Rivlin constants from its own
  /// reading.
  void
  check_layer_hardness(testing::Checker &checker)
  {
    const auto p = testing::parameters_from_string(
      "subsection Material\n set Layer thicknesses = 3, 10.5\n"
      " set Hardness = 90, 60\n set C2/C1 ratio = 0.25\nend\n");
    const auto  &m      = p.material;
    const double E_base = Hardness::youngs_modulus_from_shore_a(90);
    const double E_top  = Hardness::youngs_modulus_from_shore_a(60);
    auto         close  = [](const double a, const double b) {
      return std::abs(a - b) <= 1e-15 * std::abs(b);
    };
    checker.check(m.n_layers() == 2 && m.layer_C2.size() == 2 &&
                    close(m.layer_C1[0] + m.layer_C2[0], E_base / 6) &&
                    close(m.layer_C1[1] + m.layer_C2[1], E_top / 6) &&
                    close(m.layer_C2[1], 0.25 * m.layer_C1[1]) &&
                    m.hardness_modulus == E_top,
                  "Hardness = 90, 60 Shore A: C1 + C2 = " +
                    testing::num(m.layer_C1[0] + m.layer_C2[0]) + ", " +
                    testing::num(m.layer_C1[1] + m.layer_C2[1]) +
                    " MPa (E/6 = " + testing::num(E_base / 6) + ", " +
                    testing::num(E_top / 6) +
                    "), C2 = C1/4, the report's E = " +
                    testing::num(m.hardness_modulus) + " MPa (top layer)");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const std::string                radius = "set Indenter radius = 150";
  const ContactResult              base =
    solve(radii + hardness + contact(radius, "N/mm", "40"));
  checker.check(base.converged,
                "radii, 60 Shore A, 40 N/mm: P = " +
                  testing::num(base.nip_load) +
                  " N/mm, u0 = " + testing::num(base.indentation) +
                  " mm, 2b = " + testing::num(2 * base.half_chord) + " mm");

  const ContactResult by_diameter =
    solve(diameters + hardness +
          contact("set Indenter diameter = 300", "N/mm", "40"));
  checker.check(by_diameter.converged && difference(by_diameter, base) < 1e-12,
                "diameters: the same nip (difference " +
                  testing::num(difference(by_diameter, base)) + ")");

  const double        E = Hardness::youngs_modulus_from_shore_a(60);
  const ContactResult by_constants =
    solve(radii + "subsection Material\n set C1 = " + full_precision(E / 6) +
          "\n set C2 = 0\nend\n" + contact(radius, "N/mm", "40"));
  checker.check(by_constants.converged && difference(by_constants, base) < 1e-5,
                "C1 = E/6 = " + testing::num(E / 6) +
                  " MPa, C2 = 0: the same nip (difference " +
                  testing::num(difference(by_constants, base)) + ")");

  const ContactResult by_kn =
    solve(radii + hardness + contact(radius, "kN/m", "40"));
  checker.check(by_kn.converged && difference(by_kn, base) < 1e-12,
                "40 kN/m: the same nip (difference " +
                  testing::num(difference(by_kn, base)) + ")");

  const std::string   pli = std::to_string(40 / pli_in_n_per_mm);
  const ContactResult by_pli =
    solve(radii + hardness + contact(radius, "pli", pli));
  checker.check(by_pli.converged && rel(by_pli.nip_load, 40) < 1e-6 &&
                  difference(by_pli, base) < 1e-5,
                pli + " pli: P = " + testing::num(by_pli.nip_load) +
                  " N/mm, the same nip (difference " +
                  testing::num(difference(by_pli, base)) + " < 1e-5)");
  const ContactResult by_force = solve(
    radii + hardness + "subsection Contact\n set Mode = load\n " + radius +
    "\n set Load unit = kN\n set Face length = 5000\n"
    " set Values = 200\nend\n");
  checker.check(by_force.converged && difference(by_force, base) < 1e-12,
                "200 kN on a 5000 mm face: the same nip (difference " +
                  testing::num(difference(by_force, base)) + ")");

  check_layer_hardness(checker);
  return checker.result();
}
