#ifndef rollnip_tests_three_d_test_tools_h
#define rollnip_tests_three_d_test_tools_h

#include <rollnip/three_d/three_d_parameters.h>

#include <string>

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
  } // namespace testing
} // namespace rollnip

#endif
