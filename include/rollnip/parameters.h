#ifndef rollnip_parameters_h
#define rollnip_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/boundary_ids.h>
#include <rollnip/global.h>
#include <rollnip/loading/line_load_unit.h>

#include <array>
#include <string>
#include <vector>

/**
 * The run-time parameters of rollnip, one struct per subsection of the .prm
 * file, each with its own declare/parse pair (implemented in
 * source/parameters.cc). Lengths are in mm, stresses in MPa, angles in degrees
 * in the file and radians in the program.
 */
namespace rollnip
{
  namespace Parameters
  {
    struct Geometry
    {
      double inner_radius; ///< R1 [mm]
      double outer_radius; ///< R0 [mm]
      double sector_angle; ///< modelled sector [rad], in (0, pi]
      /// Given as Roll diameter and Cover thickness (engineering_inputs.md).
      bool from_diameters = false;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    enum class MeshSource
    {
      builtin,
      gmsh
    };

    enum class NipFitting
    {
      automatic, ///< fitted for contact scenes on the builtin mesh
      on,
      off
    };

    struct Mesh
    {
      MeshSource   source;
      std::string  mesh_file;
      unsigned int radial_cells;
      unsigned int circumferential_cells;
      /// Ratio of the widest to the narrowest coarse cell in theta (>= 1);
      /// the narrowest cells sit at theta = 0, the nip.
      double circumferential_grading;
      /// Ratio of the outermost to the innermost coarse cell in r; < 1 makes
      /// cells thinner towards the loaded surface.
      double       radial_grading;
      unsigned int global_refinements;
      /// Solves before the real run whose error indicator re-cuts the
      /// coarse circumferential cells (r-adaptivity; 0: none).
      unsigned int adaptive_passes;
      /// Whether the builtin mesh follows the nip (nip_fitted_mesh.h).
      NipFitting nip_fitting;
      /// Coarse circumferential cells in [0, theta0] of the fitted mesh.
      unsigned int nip_cells;
      /// Width of the central over the edge nip cell (>= 1).
      double nip_grading;
      /// Halvings of the fitted mesh's cells about the contact edge.
      unsigned int edge_refinements = 0;
      /// Set by drivers, not the .prm: explicit coarse cell widths in theta
      /// [rad] (summing to the sector angle) instead of cells and grading.
      std::vector<double> circumferential_steps;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    enum class Theory
    {
      nonlinear,
      linear
    };

    enum class Element
    {
      q1_p0,
      q2_p1
    };

    struct Material
    {
      /// Mooney-Rivlin constants of every layer of the cover, from the
      /// core out [MPa]; one entry for an unlayered cover.
      std::vector<double> layer_C1, layer_C2;
      /// Thickness of every layer [mm]; empty: one layer, the whole cover.
      std::vector<double> layer_thicknesses;
      /// Poisson's ratio of every layer (one value: all layers); 0.5, the
      /// default: exactly incompressible (material/compressibility.h).
      std::vector<double> layer_poisson_ratio;
      /// Bulk modulus of every layer [MPa] (one value: all layers); empty:
      /// from the Poisson ratio.
      std::vector<double> layer_bulk_modulus;
      Theory              theory;

      unsigned int
      n_layers() const
      {
        return layer_C1.size();
      }
      /// Young's modulus [MPa] estimated from Material/Hardness, which then
      /// set C1 and C2 (doc/engineering_inputs.md); 0: C1, C2 were given.
      double hardness_modulus = 0;
      /// The reading and the relation used, e.g. "60 Shore A, Gent (1958)".
      std::string hardness_description;
      /// The surface layer's hardness reading and its scale's name as in
      /// Material/Hardness scale (0, empty: none), for the modulus band of
      /// the published correlations (Hardness::modulus_band).
      double      surface_hardness = 0;
      std::string hardness_scale;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct Discretization
    {
      Element element;

      unsigned int
      displacement_degree() const
      {
        return element == Element::q1_p0 ? 1 : 2;
      }

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /// What happens on one boundary id (doc/intro.md, section 1).
    enum class BoundaryCondition
    {
      fixed,    ///< u = 0 (bonded)
      free,     ///< zero traction
      symmetry, ///< zero normal displacement and zero shear traction
      pressure  ///< follower pressure given by Load/Pressure function
    };

    struct BoundaryConditions
    {
      std::array<BoundaryCondition, BoundaryIds::n_boundaries> condition;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct Load
    {
      std::string pressure_function;
      double      p0;     ///< [MPa], a constant usable in the expression
      double      theta0; ///< [rad], a constant usable in the expression

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct LoadStepping
    {
      unsigned int n_initial_steps;
      double       growth_factor;
      bool         extrapolate; ///< predictor from the last two states
      unsigned int fast_newton_iterations;
      unsigned int max_cutbacks;
      double       min_increment;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct NonlinearSolver
    {
      unsigned int max_iterations;
      double       residual_tolerance;
      double       increment_tolerance;
      double       constraint_tolerance;
      bool         line_search;
      unsigned int max_line_search_steps;
      bool         verbose;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct LinearSolver
    {
      std::string  method;              ///< "direct" or "gmres-amg"
      std::string  direct_solver;       ///< an Amesos solver name
      double       iterative_tolerance; ///< relative residual of GMRES
      unsigned int max_iterations;      ///< of GMRES per solve

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /// The units of reported numbers (Output/Units): SI (mm, MPa, N/mm
    /// or kN/m, m/min) or US customary (in, psi, pli, fpm).
    enum class UnitSystem
    {
      si,
      us
    };

    /// How much a run prints (Output/Verbosity): quiet prints only the
    /// report, warnings and errors; detailed adds the Newton iterations.
    enum class Verbosity
    {
      quiet,
      normal,
      detailed
    };

    struct Output
    {
      std::string directory;
      bool        write_vtu;
      bool        vtu_every_step;
      bool        write_csv;
      bool        csv_every_step;
      bool        print_timing;
      UnitSystem  units     = UnitSystem::si;
      Verbosity   verbosity = Verbosity::normal;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    enum class ContactMode
    {
      none,       ///< the pressure of Load/Pressure function is applied
      nip_angle,  ///< Batra's inverse iteration: theta0 given, f found
      load,       ///< P given: theta0 found by an outer iteration
      indentation ///< u0 given: theta0 found by an outer iteration
    };

    struct Contact
    {
      ContactMode mode;
      double      indenter_radius; ///< Rbar [mm]; infinity: flat
      /// The controlled values, one nip each: theta0 [rad], P [N/mm] or
      /// u0 [mm] by mode.
      std::vector<double> values;
      double              tolerance; ///< conformity, as a fraction of u0
      double              control_tolerance; ///< relative, on P or u0
      unsigned int        max_iterations;
      bool                compare_linear;
      /// The unit of line loads in Values (load mode) and in the nip
      /// report; Values are converted to N/mm when read.
      LineLoadUnit load_unit;
      /// Surface speed of the roll [m/min] for the dwell time; 0: none.
      double surface_speed = 0;
      /// Contact/Values or Indenter radius differ from their defaults:
      /// with Mode = none they would be silently ignored.
      bool keys_set_without_mode = false;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /// A refinement study (doc/intro.md section 8): the scene at several
    /// mesh levels and, if asked, with several elements.
    struct Study
    {
      /// Mesh/Global refinements of each run; empty: no study.
      std::vector<unsigned int> levels;
      /// Elements to compare; empty: Discretization/Element only.
      std::vector<Element> elements;
      /// Sector angles [rad] to compare; empty: Geometry/Sector angle only.
      std::vector<double> sector_angles;
      /// Load stepping/Initial steps to compare; empty: that value only.
      std::vector<unsigned int> initial_steps;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /// How sure the reported numbers are (doc/accuracy.md, "Error
    /// estimates").
    struct Accuracy
    {
      /// Whether each nip is solved again one mesh level coarser (finer
      /// at level 0) to estimate the error of every reported number.
      bool error_estimate = true;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /// The roll the cover is pressed against, when it is a covered roll
    /// rather than the rigid circle or plane of Contact/Indenter radius.
    struct MatingRoll
    {
      bool covered = false;
      /// Its cover, its mesh, and the outer iterations of the two-roll
      /// contact (TwoRollContact).
      Geometry     geometry;
      Mesh         mesh;
      Material     material;
      unsigned int max_iterations = 60;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    struct AllParameters
    {
      Geometry           geometry;
      Mesh               mesh;
      Material           material;
      Discretization     discretization;
      BoundaryConditions boundary_conditions;
      Load               load;
      LoadStepping       load_stepping;
      NonlinearSolver    nonlinear_solver;
      LinearSolver       linear_solver;
      Output             output;
      Contact            contact;
      MatingRoll         mating_roll;
      Study              study;
      Accuracy           accuracy;

      /// The scene of the covered mating roll: these parameters with its
      /// geometry, material and mesh, its theory this roll's, output in
      /// Output/Directory/mating_roll.
      AllParameters
      mating_roll_parameters() const;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);

      /// Reads a .prm file; throws with a one-line message on any error:
      /// unknown entries, values out of range, inconsistent geometry.
      void
      read(const std::string &filename);
      /// The same, with every entry declared in and parsed into @p prm,
      /// for the subsections that other parts of the program read from it
      /// (RunParameters).
      void
      read(const std::string &filename, ParameterHandler &prm);

      /**
       * Checks what the patterns of ParameterHandler cannot: relations
       * between entries (R1 < R0, ...), that the load expression parses, and
       * that the conditions make sense. Throws ExcMessage naming the entry.
       */
      void
      validate() const;
      /// The scene as a whole: the load expression on the arc, sector
      /// studies on a builtin mesh, contact entries without a mode (each
      /// roll's own entries: validate_rolls(), scene/scene_validation.h).
      void
      validate_scene() const;
      /// A contact scene's conditions and values (validate()).
      void
      validate_contact() const;
      /// Nip fitting against the contact mode and values (each roll's mesh
      /// entries: validate_rolls(), scene/scene_validation.h).
      void
      validate_mesh() const;
      /// The constants and thicknesses of the layers of the cover.
      void
      validate_material() const;
      /// That a covered mating roll has a contact scene (its own entries:
      /// validate_rolls(), with messages prefixed "Mating roll/").
      void
      validate_mating_roll() const;
      /// Output directory, the number of nips and the size (validate()).
      void
      validate_output() const;

      /// Whether the mesh is the nip-fitted one: Mesh/Nip fitting = on, or
      /// automatic for a contact scene on the builtin mesh without
      /// adaptive grading.
      bool
      nip_fitted_mesh() const;
    };

    /// Human-readable name of a condition, as written in the .prm file.
    std::string
    to_string(BoundaryCondition condition);
  } // namespace Parameters
} // namespace rollnip

#endif
