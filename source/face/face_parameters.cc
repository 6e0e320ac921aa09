#include <rollnip/face/crown.h>
#include <rollnip/face/face_parameters.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/parameters.h>

#include <filesystem>

namespace rollnip
{
  namespace Parameters
  {
    void
    FaceCore::declare(ParameterHandler &prm)
    {
      declare_documented(prm,
                         "Outer diameter",
                         "94.4",
                         Patterns::Double(0.),
                         "Outer diameter of the core (the tube under the "
                         "cover, or the bare roll) [mm]");
      declare_documented(prm,
                         "Inner diameter",
                         "60",
                         Patterns::Double(0.),
                         "Bore of the tube [mm]; 0: a solid shaft");
      declare_documented(prm,
                         "Young's modulus",
                         "210000",
                         Patterns::Double(0.),
                         "Young's modulus of the core [MPa] (steel 210000, "
                         "cast iron about 110000)");
      declare_documented(prm,
                         "Poisson ratio",
                         "0.3",
                         Patterns::Double(0., 0.5),
                         "Poisson ratio of the core, for its shear modulus");
      declare_documented(prm,
                         "Density",
                         "7850",
                         Patterns::Double(0.),
                         "Density of the core [kg/m^3], for Face/Own weight");
    }

    void
    FaceCore::parse(ParameterHandler &prm)
    {
      outer_diameter = prm.get_double("Outer diameter");
      inner_diameter = prm.get_double("Inner diameter");
      youngs_modulus = prm.get_double("Young's modulus");
      poisson_ratio  = prm.get_double("Poisson ratio");
      density        = prm.get_double("Density");
    }

    void
    FaceCrown::declare(ParameterHandler &prm)
    {
      declare_documented(
        prm,
        "Shape",
        "none",
        Patterns::Selection("none|parabolic|sine|circular|ideal|table"),
        "The crown, zero at the face ends: parabolic, sine (a cosine "
        "half-wave) or circular with Amount at the centre; ideal: the "
        "roll's own deflection under the design load (computed); table: "
        "read from Table file");
      declare_documented(prm,
                         "Amount",
                         "0",
                         Patterns::Double(),
                         "Crown at the face centre over the face ends [mm], "
                         "on the diameter or radius as Given on says");
      declare_documented(prm,
                         "Given on",
                         "diameter",
                         Patterns::Selection("diameter|radius"),
                         "Whether Amount and the table are changes of the "
                         "diameter (as roll makers quote them) or of the "
                         "radius");
      declare_documented(prm,
                         "Table file",
                         "",
                         Patterns::Anything(),
                         "Shape = table: a CSV file with a header line and "
                         "rows 'y [mm], change [mm]', y from the face centre; "
                         "rows with y >= 0 only are mirrored");
      declare_documented(prm,
                         "Design line load",
                         "0",
                         Patterns::Double(0.),
                         "Shape = ideal: the mean line load the crown makes "
                         "uniform [N/mm]; 0: the face's own load");
    }

    void
    FaceCrown::parse(ParameterHandler &prm)
    {
      const std::string s = prm.get("Shape");
      shape               = s == "parabolic"  ? CrownShape::parabolic
                            : s == "sine"     ? CrownShape::sine
                            : s == "circular" ? CrownShape::circular
                            : s == "ideal"    ? CrownShape::ideal
                            : s == "table"    ? CrownShape::table
                                              : CrownShape::none;
      amount              = prm.get_double("Amount");
      on_diameter         = prm.get("Given on") == "diameter";
      table_file          = prm.get("Table file");
      design_line_load    = prm.get_double("Design line load");
    }

    namespace
    {
      /// Face: the rolls, the face and the load.
      void
      declare_face_scene(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Enabled",
                           "false",
                           Patterns::Bool(),
                           "true: run the face model (doc/face.md) with the "
                           "file's scene as the nip's cross-section, instead "
                           "of the cross-section alone");
        declare_documented(prm,
                           "Face length",
                           "1000",
                           Patterns::Double(0.),
                           "Length of the covered face [mm]");
        declare_documented(prm,
                           "Bearing distance",
                           "1200",
                           Patterns::Double(0.),
                           "Distance between the bearings of each roll [mm], "
                           "at least Face length (the journals are outside "
                           "the face)");
        declare_documented(prm,
                           "Loading",
                           "mean line load",
                           Patterns::Selection("mean line load|bearing forces"),
                           "mean line load: the total nip force is Mean line "
                           "load x Face length; bearing forces: Bearing force "
                           "at each bearing of the roll (plus its weight)");
        declare_documented(prm,
                           "Mean line load",
                           "20",
                           Patterns::Double(0.),
                           "Loading = mean line load: the total nip force "
                           "over the face length [N/mm]");
        declare_documented(prm,
                           "Bearing force",
                           "10000",
                           Patterns::Double(0.),
                           "Loading = bearing forces: the force of the "
                           "loading cylinder at each bearing [N]");
        declare_documented(prm,
                           "Own weight",
                           "false",
                           Patterns::Bool(),
                           "Whether the cores' weight loads the beams: the "
                           "roll is on top, the mating roll below");
        declare_documented(prm,
                           "Mating roll",
                           "rigid",
                           Patterns::Selection("rigid|beam"),
                           "rigid: the mating roll is rigid and straight; "
                           "beam: it bends as Mating core says");
      }

      /// Face: the discretisation and the foundation.
      void
      declare_face_model(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Shear deformation",
                           "true",
                           Patterns::Bool(),
                           "true: Timoshenko beams (shear correction of a "
                           "tube); false: Euler-Bernoulli");
        declare_documented(prm,
                           "Elements",
                           "100",
                           Patterns::Integer(2, 100000),
                           "Beam elements along the face (the journals get "
                           "elements of the same length)");
        declare_documented(prm,
                           "Foundation",
                           "cross-section",
                           Patterns::Selection("cross-section|linear"),
                           "cross-section: q = P_2D(delta), the nip law of "
                           "the file's scene; linear: q = k delta, a check "
                           "against closed forms");
        declare_documented(prm,
                           "Foundation stiffness",
                           "10",
                           Patterns::Double(0.),
                           "Foundation = linear: k [N/mm^2]");
        declare_documented(prm,
                           "Law samples",
                           "16",
                           Patterns::Integer(3, 200),
                           "Approaches of the cross-section sweep that "
                           "samples P_2D, geometric in u0");
        declare_documented(prm,
                           "Law maximum approach",
                           "0",
                           Patterns::Double(0.),
                           "Largest approach of the sweep [mm]; 0: from the "
                           "thin-layer estimate at 3 times the mean line "
                           "load");
        declare_documented(prm,
                           "Law range",
                           "50",
                           Patterns::Double(2.),
                           "Largest over smallest approach of the sweep; "
                           "below it the law is a power law");
        declare_documented(prm,
                           "Law cache directory",
                           "",
                           Patterns::Anything(),
                           "Where the sampled law is kept and looked up, "
                           "keyed by the cross-section's parameters; empty: "
                           "Output/Directory");
        declare_documented(prm,
                           "Non-local cover ends",
                           "false",
                           Patterns::Bool(),
                           "true: q - l^2 q'' = P_2D(delta) with q = 0 at "
                           "the cover ends, for the rubber flowing out "
                           "axially (not measured; doc/face.md)");
        declare_documented(prm,
                           "Non-local length factor",
                           "0.63",
                           Patterns::Double(0.),
                           "l over the nip half-width at the mean line load "
                           "(thin-layer theory: l^2 = 0.4 a^2)");
        declare_documented(prm,
                           "Surface speed",
                           "0",
                           Patterns::Double(0.),
                           "Surface speed [m/min] for the dwell time along "
                           "the face; 0: none");
      }
    } // namespace

    void
    Face::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Face");
      declare_face_scene(prm);
      declare_face_model(prm);
      for (const char *core : {"Roll core", "Mating core"})
        {
          prm.enter_subsection(core);
          FaceCore::declare(prm);
          prm.leave_subsection();
        }
      for (const char *crown : {"Roll crown", "Mating crown"})
        {
          prm.enter_subsection(crown);
          FaceCrown::declare(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    Face::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Face");
      enabled              = prm.get_bool("Enabled");
      face_length          = prm.get_double("Face length");
      bearing_distance     = prm.get_double("Bearing distance");
      loading              = prm.get("Loading") == "bearing forces"
                               ? FaceLoading::bearing_forces
                               : FaceLoading::mean_line_load;
      mean_line_load       = prm.get_double("Mean line load");
      bearing_force        = prm.get_double("Bearing force");
      own_weight           = prm.get_bool("Own weight");
      mate_is_beam         = prm.get("Mating roll") == "beam";
      shear_deformation    = prm.get_bool("Shear deformation");
      elements             = prm.get_integer("Elements");
      foundation           = prm.get("Foundation") == "linear"
                               ? FaceFoundation::linear
                               : FaceFoundation::cross_section;
      foundation_stiffness = prm.get_double("Foundation stiffness");
      law_samples          = prm.get_integer("Law samples");
      law_maximum_approach = prm.get_double("Law maximum approach");
      law_range            = prm.get_double("Law range");
      law_cache_directory  = prm.get("Law cache directory");
      nonlocal             = prm.get_bool("Non-local cover ends");
      nonlocal_factor      = prm.get_double("Non-local length factor");
      surface_speed        = prm.get_double("Surface speed");
      prm.enter_subsection("Roll core");
      roll_core.parse(prm);
      prm.leave_subsection();
      prm.enter_subsection("Mating core");
      mate_core.parse(prm);
      prm.leave_subsection();
      prm.enter_subsection("Roll crown");
      roll_crown.parse(prm);
      prm.leave_subsection();
      prm.enter_subsection("Mating crown");
      mate_crown.parse(prm);
      prm.leave_subsection();
      prm.leave_subsection();
    }

    namespace
    {
      void
      validate_core(const FaceCore &core, const std::string &name)
      {
        AssertThrow(core.outer_diameter > 0,
                    ExcMessage("Face/" + name +
                               "/Outer diameter must be positive"));
        AssertThrow(core.inner_diameter < core.outer_diameter,
                    ExcMessage("Face/" + name + "/Inner diameter (" +
                               number(core.inner_diameter) +
                               " mm) must be below Outer diameter (" +
                               number(core.outer_diameter) + " mm)"));
        AssertThrow(core.youngs_modulus > 0,
                    ExcMessage("Face/" + name +
                               "/Young's modulus must be positive"));
      }

      void
      validate_crown(const FaceCrown &crown, const std::string &name)
      {
        if (crown.shape == CrownShape::table)
          rollnip::Face::read_crown_table(crown.table_file,
                                          "Face/" + name + "/Table file");
        if (crown.shape == CrownShape::circular)
          AssertThrow(crown.amount != 0,
                      ExcMessage("Face/" + name +
                                 "/Amount must not be 0 for a circular "
                                 "crown"));
      }
    } // namespace

    void
    Face::validate() const
    {
      if (!enabled)
        return;
      AssertThrow(face_length > 0,
                  ExcMessage("Face/Face length must be positive"));
      AssertThrow(bearing_distance >= face_length,
                  ExcMessage("Face/Bearing distance (" +
                             number(bearing_distance) +
                             " mm) must be at least Face/Face length (" +
                             number(face_length) + " mm)"));
      AssertThrow(loading != FaceLoading::mean_line_load || mean_line_load > 0,
                  ExcMessage("Face/Mean line load must be positive"));
      AssertThrow(loading != FaceLoading::bearing_forces || bearing_force > 0 ||
                    own_weight,
                  ExcMessage("Face/Bearing force must be positive"));
      AssertThrow(foundation != FaceFoundation::linear ||
                    foundation_stiffness > 0,
                  ExcMessage("Face/Foundation stiffness must be positive "
                             "for Foundation = linear"));
      AssertThrow(!nonlocal || nonlocal_factor > 0,
                  ExcMessage("Face/Non-local length factor must be "
                             "positive"));
      AssertThrow(!nonlocal || foundation == FaceFoundation::cross_section,
                  ExcMessage("Face/Non-local cover ends needs Face/"
                             "Foundation = cross-section (l is a multiple "
                             "of the nip half-width)"));
      validate_core(roll_core, "Roll core");
      if (mate_is_beam)
        validate_core(mate_core, "Mating core");
      validate_crown(roll_crown, "Roll crown");
      validate_crown(mate_crown, "Mating crown");
      AssertThrow(mate_crown.shape != CrownShape::ideal || mate_is_beam,
                  ExcMessage("Face/Mating crown/Shape = ideal needs Face/"
                             "Mating roll = beam (a rigid roll does not "
                             "bend)"));
    }
  } // namespace Parameters
} // namespace rollnip
