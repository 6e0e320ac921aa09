// The nonlinear face model on a power-law foundation (doc/face.md,
// "Validation"):
// 1. q(y) converges in the 1D mesh (centre and end, observed order);
// 2. a symmetric press gives a symmetric q(y), and the bearings carry the
//    nip force;
// 3. two identical rolls bend alike, and as one roll of half the
//    stiffnesses against a rigid mate;
// 4. the ideal crown at the design load makes q uniform to 0.1 %, less
//    load leaves the centre heavy (over-crowned), more makes it light;
// 5. a strongly crowned roll at a low load lifts off at the ends: q = 0
//    there, and the bearings still carry the nip force;
// 6. the non-local foundation q - l^2 q'' = k delta on a stiff straight
//    core: with delta = a uniform and q = 0 at the ends, q = k a (1 -
//    cosh(y / l) / cosh(L / 2 l)), and int q = F gives a = F / (k (L -
//    2 l tanh(L / 2 l))); q(0) and a converge to it at second order.
#include <rollnip/face/beam.h>
#include <rollnip/face/crown.h>
#include <rollnip/face/face_solver.h>
#include <rollnip/face/foundation_law.h>

#include "test_tools.h"

#include <cmath>

using namespace rollnip;
using namespace rollnip::Face;
using testing::num;

namespace
{
  /// q = 2.5 delta^1.5 [N/mm], b = sqrt(2 R delta) with R = 34 mm: the
  /// shape of a nip law, sampled on the approaches a sweep would take.
  SampledLaw
  power_law()
  {
    std::vector<double> u, P, b, peak;
    for (unsigned int i = 0; i < 12; ++i)
      {
        u.push_back(0.1 * std::pow(1.45, i));
        P.push_back(2.5 * std::pow(u.back(), 1.5));
        b.push_back(std::sqrt(68 * u.back()));
        peak.push_back(P.back() / b.back());
      }
    return SampledLaw(u, P, b, peak);
  }

  FaceModel
  press(const FoundationLaw &law)
  {
    Parameters::FaceCore core{94.4, 60, 210000, 0.3, 7850};
    FaceModel            m;
    m.face_length      = 1000;
    m.bearing_distance = 1200;
    m.elements         = 100;
    m.roll             = tube_section(core, true);
    m.mate             = m.roll;
    m.total_force      = 20 * m.face_length;
    m.law              = &law;
    return m;
  }

  void
  check_mesh_convergence(testing::Checker &checker, const FoundationLaw &law)
  {
    std::cout << "1. Convergence of q(y) in the 1D mesh" << std::endl;
    FaceModel           m = press(law);
    std::vector<double> centre, end;
    for (const unsigned int n : {20u, 40u, 80u, 160u, 320u})
      {
        m.elements           = n;
        const FaceSolution s = solve_face(m);
        centre.push_back(s.line_load(0));
        end.push_back(s.line_load(m.face_length / 2));
        std::cout << "  " << n << " elements: q(0) = " << std::setprecision(10)
                  << centre.back() << " N/mm, q(L/2) = " << end.back()
                  << " N/mm, " << s.iterations << " Newton iterations"
                  << std::endl;
      }
    const unsigned int k = centre.size() - 1;
    const double order   = std::log2(std::abs(centre[k - 2] - centre[k - 1]) /
                                   std::abs(centre[k - 1] - centre[k]));
    // Second order: the exact element's deflection shapes tend to linear
    // ones as phi = 12 EI / (kGA h^2) grows on finer meshes (without
    // shear they are the Hermite cubics and the order is 4, face_beam).
    checker.check(order > 1.9,
                  "q(0) converges at order " + num(order) +
                    " (Timoshenko beams)");
    checker.check(std::abs(centre[k - 1] / centre[k] - 1) < 1e-6 &&
                    std::abs(end[k - 1] / end[k] - 1) < 1e-6,
                  "160 elements agree with 320 to 1e-6 at the centre and "
                  "the end");
  }

  void
  check_symmetry(testing::Checker &checker, const FoundationLaw &law)
  {
    std::cout << "2. Symmetry and equilibrium" << std::endl;
    FaceModel m              = press(law);
    m.elements               = 101; // odd: the centre is not a node
    const FaceSolution s     = solve_face(m);
    double             worst = 0;
    for (double y = 0; y <= 500; y += 12.5)
      worst = std::max(worst, std::abs(s.line_load(y) / s.line_load(-y) - 1));
    checker.check(worst < 1e-10,
                  "q(y) = q(-y) to " + num(worst) + " (101 elements)");
    const double bearings = s.roll_bearings[0] + s.roll_bearings[1];
    checker.check(std::abs(bearings / m.total_force - 1) < 1e-9 &&
                    std::abs(s.roll_bearings[0] / s.roll_bearings[1] - 1) <
                      1e-9,
                  "the roll's bearings carry " + num(bearings) +
                    " N of the nip force " + num(m.total_force) +
                    " N, half each");
  }

  void
  check_identical_rolls(testing::Checker &checker, const FoundationLaw &law)
  {
    std::cout << "3. Two identical rolls" << std::endl;
    FaceModel two     = press(law);
    two.mate_is_beam  = true;
    FaceSolution both = solve_face(two);
    double       diff = 0;
    for (double y = -500; y <= 500; y += 50)
      diff =
        std::max(diff,
                 std::abs(both.roll_deflection(y) - both.mate_deflection(y)));
    checker.check(diff < 1e-12 * std::abs(both.roll_deflection(0)) + 1e-15,
                  "the rolls' deflections agree to " + num(diff) +
                    " mm (centre " + num(both.roll_deflection(0)) + " mm)");
    // One roll with half of both stiffnesses against a rigid mate bends
    // by w_roll + w_mate under the same q.
    FaceModel one = press(law);
    one.roll.bending_stiffness /= 2;
    one.roll.shear_stiffness /= 2;
    const FaceSolution single = solve_face(one);
    double             worst  = 0;
    for (double y = -500; y <= 500; y += 50)
      worst =
        std::max(worst, std::abs(single.line_load(y) / both.line_load(y) - 1));
    checker.check(worst < 1e-9 && std::abs(single.roll_deflection(0) /
                                             (2 * both.roll_deflection(0)) -
                                           1) < 1e-9,
                  "as one roll of half EI and kGA: q agrees to " + num(worst) +
                    ", its deflection is the sum of both");
  }

  void
  check_ideal_crown(testing::Checker &checker, const FoundationLaw &law)
  {
    std::cout << "4. The ideal crown" << std::endl;
    FaceModel m    = press(law);
    m.mate_is_beam = true;
    m.mate.bending_stiffness *= 3;
    m.roll_beam_load = -m.roll.weight;
    m.mate_beam_load = m.mate.weight;
    const FaceMesh mesh(m.face_length, m.bearing_distance, m.elements);
    const double   design = m.total_force / m.face_length;
    const Crown    a      = ideal_crown(
      mesh,
      m.roll,
      simply_supported_deflection(mesh, m.roll, design, m.roll_beam_load),
      m.face_length);
    const Crown b = ideal_crown(
      mesh,
      m.mate,
      simply_supported_deflection(mesh, m.mate, design, m.mate_beam_load),
      m.face_length);
    m.crown      = [a, b](const double y) { return a(y) + b(y); };
    double worst = 0;
    for (const double factor : {1., 0.5, 1.5})
      {
        FaceModel f          = m;
        f.total_force        = factor * m.total_force;
        const FaceSolution s = solve_face(f);
        const double       r = s.line_load(0) / s.line_load(500);
        std::cout << "  " << factor << " x design: q(0) / q(L/2) = " << r
                  << std::endl;
        if (factor == 1.)
          for (double y = -500; y <= 500; y += 10)
            worst = std::max(worst, std::abs(s.line_load(y) / design - 1));
        else
          checker.check(factor < 1 ? r > 1.01 : r < 0.99,
                        "off design (" + num(factor) +
                          " x): the centre carries " +
                          (factor < 1 ? "more" : "less") + " than the ends");
      }
    checker.check(worst < 1e-3,
                  "at the design load q is uniform to " + num(worst) +
                    " (own weight on, mating roll 3 times as stiff)");
  }

  void
  check_lift_off(testing::Checker &checker, const FoundationLaw &law)
  {
    std::cout << "5. Lift-off at the ends" << std::endl;
    FaceModel m   = press(law);
    m.total_force = 2 * m.face_length;
    m.crown       = [](const double y) { return 3.0 * (1 - y * y / 250000); };
    const FaceSolution s         = solve_face(m);
    double             open_from = 500;
    for (double y = 0; y <= 500; y += 0.5)
      if (s.approach_at(y) <= 0)
        {
          open_from = y;
          break;
        }
    std::cout << "  " << s.iterations << " Newton iterations; the nip opens "
              << "at |y| = " << open_from << " mm" << std::endl;
    checker.check(open_from < 450 && s.line_load(500) == 0 &&
                    s.line_load(-500) == 0,
                  "3 mm crown at 2 N/mm: the nip is open beyond |y| = " +
                    num(open_from) + " mm");
    const double bearings = s.roll_bearings[0] + s.roll_bearings[1];
    checker.check(std::abs(bearings / m.total_force - 1) < 1e-9,
                  "the bearings carry the nip force (" + num(bearings) + " N)");
  }

  void
  check_nonlocal(testing::Checker &checker)
  {
    std::cout << "6. The non-local foundation on a straight core" << std::endl;
    const double           k = 100, l = 20;
    const LinearFoundation law(k);
    FaceModel              m = press(law);
    // A core 1e8 times stiffer: it bends by 1e-9 mm, the foundation's
    // approach is 0.2 mm.
    m.roll.bending_stiffness *= 1e8;
    m.roll.shear_stiffness *= 1e8;
    m.nonlocal_length     = l;
    const double        L = m.face_length, F = m.total_force;
    const double        a  = F / (k * (L - 2 * l * std::tanh(L / (2 * l))));
    const double        q0 = k * a * (1 - 1 / std::cosh(L / (2 * l)));
    std::vector<double> errors;
    for (const unsigned int n : {100u, 200u, 400u})
      {
        m.elements           = n;
        const FaceSolution s = solve_face(m);
        errors.push_back(std::max(std::abs(s.line_load(0) / q0 - 1),
                                  std::abs(s.approach / a - 1)));
        std::cout << "  " << n << " elements: q(0) = " << s.line_load(0)
                  << " N/mm (closed form " << q0 << "), a = " << s.approach
                  << " mm (" << a << "), q(L/2) = " << s.line_load(L / 2)
                  << std::endl;
        if (n == 400)
          checker.check(s.line_load(L / 2) == 0 &&
                          std::abs(
                            (s.roll_bearings[0] + s.roll_bearings[1]) / F - 1) <
                            1e-9,
                        "q = 0 at the cover ends, and the bearings carry "
                        "the nip force");
      }
    const double order = std::log2(errors[1] / errors[2]);
    checker.check(errors.back() < 1e-4 && order > 1.8,
                  "400 elements: within " + num(errors.back()) +
                    " of the closed form, observed order " + num(order));
  }
} // namespace

int
main()
{
  testing::Checker checker;
  const SampledLaw law = power_law();
  check_mesh_convergence(checker, law);
  check_symmetry(checker, law);
  check_identical_rolls(checker, law);
  check_ideal_crown(checker, law);
  check_lift_off(checker, law);
  check_nonlocal(checker);
  return checker.result();
}
