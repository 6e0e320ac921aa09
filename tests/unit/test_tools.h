#ifndef rollnip_tests_test_tools_h
#define rollnip_tests_test_tools_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/parameters.h>
#include <rollnip/problem.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

/**
 * Small helpers shared by the test programs: scenes are written as .prm
 * text in the test itself, and every check prints what it compared.
 */
namespace rollnip
{
  namespace testing
  {
    /// Parameters from .prm text on top of the defaults; output is off
    /// unless the text turns it on.
    inline Parameters::AllParameters
    parameters_from_string(const std::string &text)
    {
      ParameterHandler prm;
      Parameters::AllParameters::declare(prm);
      prm.parse_input_from_string("subsection Output\n"
                                  "  set Write VTU = false\n"
                                  "  set Write CSV = false\n"
                                  "  set Print timing = false\n"
                                  "  set Directory = test_output\n"
                                  "end\n" +
                                  text);
      Parameters::AllParameters p;
      p.parse(prm);
      p.validate();
      return p;
    }

    /// The default pressure scene (the parabolic pressure, p0 = 0.5 MPa)
    /// at mesh level 1 with @p element and Linear solver/Method @p method
    /// (GMRES allowed 2000 iterations), then the .prm text @p more.
    inline Parameters::AllParameters
    parabolic_pressure_scene(const std::string &element,
                             const std::string &method,
                             const std::string &more = "")
    {
      return parameters_from_string(
        "subsection Mesh\n set Global refinements = 1\nend\n"
        "subsection Load\n set p0 = 0.5\nend\n"
        "subsection Discretization\n set Element = " +
        element +
        "\nend\n"
        "subsection Linear solver\n set Method = " +
        method + "\n set Max iterations = 2000\nend\n" + more);
    }

    /// Counts failed checks; the test's exit code.
    struct Checker
    {
      unsigned int n_failed = 0;

      void
      check(const bool ok, const std::string &what)
      {
        std::cout << (ok ? "  ok:     " : "  FAILED: ") << what << std::endl;
        if (!ok)
          ++n_failed;
      }

      int
      result() const
      {
        std::cout << (n_failed == 0
                        ? "all checks passed"
                        : std::to_string(n_failed) + " check(s) failed")
                  << std::endl;
        return n_failed == 0 ? 0 : 1;
      }
    };

    /// A number as text with 4 significant digits.
    inline std::string
    num(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(4) << x;
      return s.str();
    }

    /// The c >= 0 with f(c) = target for an increasing f with f(0) <= target,
    /// by bisection to round-off (the exact solutions given implicitly).
    template <typename Function>
    double
    increasing_root(const Function &f, const double target)
    {
      double lo = 0, hi = 1;
      while (f(hi) < target)
        hi *= 2;
      for (int i = 0; i < 200; ++i)
        {
          const double mid            = 0.5 * (lo + hi);
          (f(mid) < target ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    }

    /// Observed order of convergence from errors at mesh sizes h and h/2.
    inline double
    order(const double e_coarse, const double e_fine)
    {
      return std::log(e_coarse / e_fine) / std::log(2.);
    }
    /// Batra's run-30 cover as .prm text: radii 47.2 and 60.7 mm (13.5 mm
    /// of rubber) on a @p sector_deg sector, C1 = C2 = 0.25 MPa.
    inline std::string
    run30_cover(const double sector_deg = 90)
    {
      return "subsection Geometry\n set Inner radius = 47.2\n"
             " set Outer radius = 60.7\n set Sector angle = " +
             num(sector_deg) +
             "\nend\n"
             "subsection Material\n set C1 = 0.25\n set C2 = 0.25\nend\n";
    }

    /// The builtin mesh graded towards the nip (grading 10): @p radial x
    /// @p circumferential coarse cells, @p level global refinements.
    inline std::string
    graded_mesh(const unsigned int radial,
                const unsigned int circumferential,
                const unsigned int level)
    {
      return "subsection Mesh\n set Radial cells = " + std::to_string(radial) +
             "\n set Circumferential cells = " +
             std::to_string(circumferential) +
             "\n set Circumferential grading = 10\n"
             " set Global refinements = " +
             std::to_string(level) + "\nend\n";
    }

    /// The scene of the 3D tests: the run-30 cover on the 8 x 18 graded
    /// mesh at level 1, far edge free, pressed to the @p approaches [mm] by a
    /// cylinder of radius @p indenter_radius [mm] ("inf": a flat).
    inline std::string
    run30_indentation_scene(const std::string &approaches,
                            const std::string &indenter_radius = "76.2")
    {
      return run30_cover() + graded_mesh(8, 18, 1) +
             "subsection Boundary conditions\n set Far edge (id 3) = free\n"
             "end\n"
             "subsection Contact\n set Mode = indentation\n set Values = " +
             approaches + "\n set Indenter radius = " + indenter_radius +
             "\nend\n";
    }
  } // namespace testing
} // namespace rollnip

#endif
