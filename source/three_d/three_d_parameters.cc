#include <rollnip/parameter_entries.h>
#include <rollnip/parameters.h>
#include <rollnip/three_d/core_deflection.h>
#include <rollnip/three_d/three_d_parameters.h>

namespace rollnip
{
  namespace Parameters
  {
    namespace
    {
      /// The elastic core's entries (three_d/core_tube.h).
      void
      declare_core_tube(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Core",
                           "rigid",
                           Patterns::Selection("rigid|elastic"),
                           "'rigid': the bonded nodes at R1 are held (or "
                           "follow Core deflection); 'elastic': a steel tube "
                           "from Core inner radius to R1 meshed with the "
                           "cover, running on to the journal at Bearing "
                           "distance, where u_x = u_y = 0 on its end "
                           "section (a simple support); needs a 180 deg "
                           "sector with Far edge = symmetry");
        declare_documented(prm,
                           "Core inner radius",
                           "0",
                           Patterns::Double(0.),
                           "The elastic core tube's bore radius [mm], "
                           "between 0 and Geometry/Inner radius");
        declare_documented(prm,
                           "Core Young's modulus",
                           "210000",
                           Patterns::Double(0.),
                           "The elastic core's Young's modulus [MPa] "
                           "(steel: 210000)");
        declare_documented(prm,
                           "Core Poisson ratio",
                           "0.3",
                           Patterns::Double(0., 0.5),
                           "The elastic core's Poisson ratio (steel: 0.3)");
        declare_documented(prm,
                           "Bearing distance",
                           "0",
                           Patterns::Double(0.),
                           "The journal's distance from the middle of the "
                           "face along the axis [mm], beyond the cover end "
                           "(> Slice thickness)");
      }
    } // namespace

    void
    ThreeD::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Three d");
      declare_documented(prm,
                         "Enabled",
                         "false",
                         Patterns::Bool(),
                         "Run the 3D body instead of the 2D cross-section: "
                         "the builtin or gmsh cross-section of Geometry and "
                         "Mesh extruded along the roll axis (or a 3D "
                         "hexahedral gmsh mesh as drawn), pressed by the "
                         "indenter of Contact at the approaches u0 of "
                         "Contact/Values (Mode = indentation), Q1-P0 or "
                         "Q2-P1 as Discretization/Element (Q2-P1 with the "
                         "direct linear solver)");
      declare_documented(prm,
                         "Slice thickness",
                         "1",
                         Patterns::Double(0.),
                         "Length of the modelled piece of the face along "
                         "the roll axis [mm]");
      declare_documented(prm,
                         "Layers",
                         "1",
                         Patterns::Integer(1, 1000),
                         "Cells through the slice thickness");
      declare_documented(prm,
                         "Far face",
                         "fixed axial",
                         Patterns::Selection("fixed axial|free"),
                         "The face z = Slice thickness: 'fixed axial' "
                         "(u_z = 0, the plane-strain slice) or 'free' (a "
                         "free cover end); z = 0 always has u_z = 0 (the "
                         "symmetry plane through the middle of the face)");
      declare_documented(prm,
                         "Approach step",
                         "0.25",
                         Patterns::Double(0.),
                         "Largest increment of u0 per load step [mm]");
      declare_documented(prm,
                         "Max Newton iterations",
                         "40",
                         Patterns::Integer(1, 1000),
                         "Semismooth Newton iterations per load step (the "
                         "active set and the displacements together)");

      declare_documented(prm,
                         "Core deflection",
                         "0",
                         Patterns::Anything(),
                         "The rigid core's bending line v(z) [mm], positive "
                         "away from the nip (the face model's deflection): "
                         "a muparser expression in z [mm] with the constant "
                         "pi. The bonded nodes at R1 move by -v(z) along "
                         "x1, so the local approach at z is u0 - v(z)");
      declare_documented(prm,
                         "Axial grading",
                         "1",
                         Patterns::Double(1.),
                         "Thickness of the layer at z = 0 over that of the "
                         "layer at the far face z = Slice thickness; the "
                         "layers thin geometrically towards the far face "
                         "(a free cover end), 1: uniform");
      declare_core_tube(prm);
      prm.leave_subsection();
    }

    void
    ThreeD::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Three d");
      enabled               = prm.get_bool("Enabled");
      slice_thickness       = prm.get_double("Slice thickness");
      layers                = prm.get_integer("Layers");
      fix_far_face          = prm.get("Far face") == "fixed axial";
      approach_step         = prm.get_double("Approach step");
      max_newton_iterations = prm.get_integer("Max Newton iterations");
      core_deflection       = prm.get("Core deflection");
      // Parses it: a bad expression is refused here, naming the entry.
      const three_d::CoreDeflection check_core(core_deflection);
      axial_grading       = prm.get_double("Axial grading");
      elastic_core        = prm.get("Core") == "elastic";
      core_inner_radius   = prm.get_double("Core inner radius");
      core_youngs_modulus = prm.get_double("Core Young's modulus");
      core_poisson_ratio  = prm.get_double("Core Poisson ratio");
      bearing_distance    = prm.get_double("Bearing distance");
      prm.leave_subsection();
      AssertThrow(slice_thickness > 0 && slice_thickness <= 1e5,
                  ExcMessage("Three d/Slice thickness must lie in (0, 1e5] "
                             "mm, got " +
                             number(slice_thickness) + " mm"));
      AssertThrow(axial_grading >= 1 && axial_grading <= 1e4,
                  ExcMessage("Three d/Axial grading must lie in [1, 1e4], "
                             "got " +
                             number(axial_grading)));
      AssertThrow(approach_step > 0,
                  ExcMessage("Three d/Approach step must be positive"));
    }
  } // namespace Parameters
} // namespace rollnip
