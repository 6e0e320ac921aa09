#ifndef rollnip_tests_three_d_test_tools_h
#define rollnip_tests_three_d_test_tools_h

#include <rollnip/contact/inverse_contact.h>
#include <rollnip/contact/nip_control.h>
#include <rollnip/problem.h>
#include <rollnip/three_d/three_d_parameters.h>

#include <string>

#include "test_tools.h"

/**
 * The scenes the 3D tests share, so that each test states only what it
 * varies.
 */
namespace rollnip
{
  namespace testing
  {
    /// A 3D segment of the face @p length [mm] long with @p layers cells
    /// along it, graded @p grading times towards the far face (z = length);
    /// that face is held at u_z = 0 (a plane-strain slice) unless
    /// @p free_end. Approach steps of at most @p step [mm], Newton up to 40
    /// iterations, the rigid straight core.
    inline Parameters::ThreeD
    slice_parameters(const double       length,
                     const unsigned int layers,
                     const bool         free_end = false,
                     const double       step     = 0.5,
                     const double       grading  = 1.)
    {
      Parameters::ThreeD t;
      t.enabled               = true;
      t.slice_thickness       = length;
      t.layers                = layers;
      t.fix_far_face          = !free_end;
      t.approach_step         = step;
      t.max_newton_iterations = 40;
      t.axial_grading         = grading;
      return t;
    }

    /// A 2 mm cover on the run-30 roll (R0 = 60.7 mm, indenter 76.2 mm), a
    /// 20 deg sector at level 0, pressed 0.2 mm: the free-end scene, thin
    /// enough that its end zone is a few cover thicknesses long.
    inline std::string
    thin_end_cover_scene()
    {
      return "subsection Geometry\n set Inner radius = 58.7\n"
             " set Outer radius = 60.7\n set Sector angle = 20\nend\n"
             "subsection Mesh\n set Radial cells = 4\n"
             " set Circumferential cells = 18\n"
             " set Circumferential grading = 10\nend\n"
             "subsection Material\n set C1 = 0.25\n set C2 = 0.25\nend\n"
             "subsection Boundary conditions\n"
             " set Far edge (id 3) = free\nend\n"
             "subsection Contact\n set Mode = indentation\n set Values = 0.2\n"
             " set Indenter radius = 76.2\nend\n";
    }

    /// The plane-strain truth of the slice tests: P(u0) [N/mm] of the 2D
    /// @p scene (indentation control), Q2-P1 at level 3.
    inline double
    plane_strain_reference_load(const std::string &scene, const double u0)
    {
      const auto p = parameters_from_string(
        scene + "subsection Mesh\n set Global refinements = 3\nend\n"
                "subsection Discretization\n set Element = Q2-P1\nend\n");
      RollProblem problem(p, MPI_COMM_WORLD);
      problem.setup();
      InverseContact contact(problem, p);
      return solve_controlled_nip(contact, p, u0).nip_load;
    }

    /// The half roll of the elastic-core tests: the run-30 cover (R1 =
    /// 47.2 mm, R2 = 60.7 mm, C1 = C2 = 0.25 MPa) over 180 deg on 6 radial
    /// and @p circumferential_cells cells, pressed 1 mm by a 76.2 mm
    /// cylinder.
    inline std::string
    half_roll_core_scene(const unsigned int circumferential_cells)
    {
      return "subsection Geometry\n set Inner radius = 47.2\n set Outer "
             "radius = 60.7\n set Sector angle = 180\nend\n"
             "subsection Mesh\n set Radial cells = 6\n set Circumferential "
             "cells = " +
             std::to_string(circumferential_cells) +
             "\n set Circumferential grading = 10\nend\n"
             "subsection Material\n set C1 = 0.25\n set C2 = 0.25\nend\n"
             "subsection Boundary conditions\n set Far edge (id 3) = "
             "symmetry\nend\n"
             "subsection Contact\n set Mode = indentation\n set Values = 1\n"
             " set Indenter radius = 76.2\nend\n";
    }

    /// The quarter roll of the compressible-cover tests: the run-30 cover
    /// of Poisson ratio @p nu over 90 deg on 8 x 18 cells, its far edge
    /// free, pressed 1 mm by a 76.2 mm cylinder.
    inline std::string
    compressible_quarter_scene(const double nu)
    {
      return "subsection Geometry\n set Inner radius = 47.2\n set Outer "
             "radius = 60.7\n set Sector angle = 90\nend\n"
             "subsection Mesh\n set Radial cells = 8\n set Circumferential "
             "cells = 18\n set Circumferential grading = 10\nend\n"
             "subsection Material\n set C1 = 0.25\n set C2 = 0.25\n"
             " set Poisson ratio = " +
             num(nu) +
             "\nend\n"
             "subsection Boundary conditions\n set Far edge (id 3) = "
             "free\nend\n"
             "subsection Contact\n set Mode = indentation\n set Values = 1\n"
             " set Indenter radius = 76.2\nend\n";
    }

    /// The 1000 mm face of the half-roll core tests (half of it modelled,
    /// free end, 3 times graded) on a steel tube of bore 35 mm (E = 210
    /// GPa, nu = 0.3) between journals 600 mm from the middle; rigid
    /// unless the caller sets elastic_core.
    inline Parameters::ThreeD
    half_roll_core_face(const unsigned int layers)
    {
      auto t                = slice_parameters(500, layers, true, 0.5, 3);
      t.core_inner_radius   = 35;
      t.core_youngs_modulus = 210000;
      t.core_poisson_ratio  = 0.3;
      t.bearing_distance    = 600;
      return t;
    }
  } // namespace testing
} // namespace rollnip

#endif
