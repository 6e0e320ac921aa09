#include <rollnip/parameter_entries.h>
#include <rollnip/parameters.h>
#include <rollnip/three_d/core_deflection.h>
#include <rollnip/three_d/three_d_parameters.h>

namespace rollnip
{
  namespace Parameters
  {
    void
    ThreeD::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Three d");
      declare_documented(prm,
                         "Enabled",
                         "false",
                         Patterns::Bool(),
                         "Run the 3D body instead of the 2D cross-section: "
                         "the builtin mesh of Geometry and Mesh extruded "
                         "along the roll axis, pressed by the indenter of "
                         "Contact at the approaches u0 of Contact/Values "
                         "(Mode = indentation), Q1-P0 or Q2-P1 as "
                         "Discretization/Element (Q2-P1 with the direct "
                         "linear solver)");
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
      axial_grading = prm.get_double("Axial grading");
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

    void
    ThreeD::read(const std::string &filename)
    {
      ParameterHandler prm;
      AllParameters::declare(prm);
      prm.parse_input(filename);
      parse(prm);
    }
  } // namespace Parameters
} // namespace rollnip
