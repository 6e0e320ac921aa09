#include <deal.II/base/numbers.h>

#include <rollnip/app/accuracy_target.h>
#include <rollnip/app/refinement_study.h>
#include <rollnip/cost_estimate.h>
#include <rollnip/engineering_inputs.h>
#include <rollnip/face/face_parameters.h>
#include <rollnip/ignored_entries.h>
#include <rollnip/loading/pressure_load.h>
#include <rollnip/material/layer_order.h>
#include <rollnip/output/units.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/parameters.h>
#include <rollnip/rolling/rolling_parameters.h>
#include <rollnip/run_errors.h>
#include <rollnip/scene/scene_validation.h>
#include <rollnip/three_d/three_d_parameters.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace rollnip
{
  namespace Parameters
  {
    namespace
    {
      const char *const boundary_names[BoundaryIds::n_boundaries] = {
        "Inner arc (id 0)",
        "Outer arc (id 1)",
        "Symmetry edge (id 2)",
        "Far edge (id 3)"};

      BoundaryCondition
      condition_from_string(const std::string &s)
      {
        if (s == "fixed")
          return BoundaryCondition::fixed;
        if (s == "free")
          return BoundaryCondition::free;
        if (s == "symmetry")
          return BoundaryCondition::symmetry;
        return BoundaryCondition::pressure;
      }

      constexpr double degree = numbers::PI / 180.;
      /// Defaults of the contact keys that only a contact scene reads.
      const char *const default_values          = "8";
      const char *const default_indenter_radius = "76.2";

    } // namespace

    void
    declare_documented(ParameterHandler            &prm,
                       const std::string           &name,
                       const std::string           &default_value,
                       const Patterns::PatternBase &pattern,
                       const std::string           &doc)
    {
      prm.declare_entry(name,
                        default_value,
                        pattern,
                        doc + ". Allowed: " +
                          pattern.description(Patterns::PatternBase::Text));
    }

    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    std::string
    with_entry_prefix(const std::string &message, const std::string &prefix)
    {
      std::string out;
      for (std::size_t i = 0; i < message.size();)
        {
          bool named = false;
          // An entry of a roll's subsection, at a word's start: "Geometry/",
          // "Geometry:" (and Material, Mesh), not already under another.
          if (i == 0 || message[i - 1] == ' ' || message[i - 1] == '(')
            for (const std::string section : {"Geometry", "Material", "Mesh"})
              if (message.compare(i, section.size(), section) == 0 &&
                  i + section.size() < message.size() &&
                  (message[i + section.size()] == '/' ||
                   message[i + section.size()] == ':'))
                named = true;
          if (named)
            out += prefix;
          out += message[i++];
        }
      return out;
    }

    std::string
    to_string(const BoundaryCondition condition)
    {
      switch (condition)
        {
          case BoundaryCondition::fixed:
            return "fixed";
          case BoundaryCondition::free:
            return "free";
          case BoundaryCondition::symmetry:
            return "symmetry";
          default:
            return "pressure";
        }
    }

    void
    Geometry::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      declare_documented(prm,
                         "Inner radius",
                         "47.2",
                         Patterns::Double(0.),
                         "R1: radius of the rigid core = inner radius of the "
                         "cover, the bond surface [mm]");
      declare_documented(prm,
                         "Outer radius",
                         "60.7",
                         Patterns::Double(0.),
                         "R0: outer radius of the undeformed cover [mm]");
      declare_documented(prm,
                         "Sector angle",
                         "90",
                         Patterns::Double(),
                         "Angle of the modelled sector, measured from the line "
                         "of centres, in (0, 180] [deg]");
      EngineeringInputs::declare_geometry(prm);
      prm.leave_subsection();
    }

    void
    Geometry::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      inner_radius = prm.get_double("Inner radius");
      outer_radius = prm.get_double("Outer radius");
      sector_angle = prm.get_double("Sector angle") * degree;
      EngineeringInputs::parse_geometry(prm, *this);
      prm.leave_subsection();
    }

    namespace
    {
      /// Mesh: where the coarse mesh comes from.
      void
      declare_mesh_source(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Source",
                           "builtin",
                           Patterns::Selection("builtin|gmsh"),
                           "builtin: a structured sector annulus; gmsh: read "
                           "'Mesh file' (physical curve tags = boundary ids)");
        declare_documented(
          prm,
          "Mesh file",
          "",
          Patterns::Anything(),
          "A gmsh .msh file (format 2 or 4), used when Source = "
          "gmsh; relative paths are taken from the working "
          "directory");
      }

      /// Mesh: the coarse cells of the builtin mesh and their refinement.
      void
      declare_mesh_cells(ParameterHandler &prm)
      {
        declare_documented(prm,
                           "Radial cells",
                           "4",
                           Patterns::Integer(1),
                           "Coarse cells through the cover thickness");
        declare_documented(prm,
                           "Circumferential cells",
                           "16",
                           Patterns::Integer(1),
                           "Coarse cells along the sector");
        declare_documented(prm,
                           "Circumferential grading",
                           "8",
                           Patterns::Double(1.),
                           "Width of the widest coarse cell (at the far edge) "
                           "over the narrowest (at theta = 0, the nip); 1 is "
                           "uniform");
        declare_documented(prm,
                           "Radial grading",
                           "1",
                           Patterns::Double(0.),
                           "Thickness of the outermost coarse cell over the "
                           "innermost; below 1 refines towards the surface");
        declare_documented(prm,
                           "Global refinements",
                           "1",
                           Patterns::Integer(0, 12),
                           "Uniform refinements of the coarse mesh");
      }

      /// Mesh: the meshes that adapt to the solution (grading, nip fitting).
      void
      declare_mesh_adaptation(ParameterHandler &prm)
      {
        declare_documented(
          prm,
          "Adaptive grading passes",
          "0",
          Patterns::Integer(0, 10),
          "Before the run, solve the scene this many times and after each "
          "solve re-cut the coarse circumferential cells (same number) so that "
          "they equidistribute the Kelly error indicator: r-adaptivity without "
          "hanging nodes (builtin mesh only; the first Contact/Values for a "
          "contact scene). 0: the graded mesh as given");
        declare_documented(
          prm,
          "Nip fitting",
          "automatic",
          Patterns::Selection("automatic|on|off"),
          "on: the builtin mesh follows the nip, so that for every half nip "
          "angle theta0 the contact edge is a surface vertex and P(theta0) is "
          "smooth (only vertex positions change, doc/accuracy.md); off: a "
          "fixed mesh graded by Circumferential grading, on which P(theta0) "
          "steps wherever theta0 crosses a node; automatic: on for contact "
          "scenes on the builtin mesh without adaptive grading");
        declare_documented(
          prm,
          "Nip cells",
          "6",
          Patterns::Integer(1),
          "Nip-fitted mesh: coarse circumferential cells in "
          "the contact zone [0, theta0], out of Circumferential "
          "cells (at least 2 must remain beyond it)");
        declare_documented(prm,
                           "Nip grading",
                           "2",
                           Patterns::Double(1.),
                           "Nip-fitted mesh: width of the central coarse nip "
                           "cell over the one at the contact edge (where the "
                           "pressure falls like a square root) for a nip "
                           "small against the cover; it relaxes towards 1 "
                           "(uniform) as the nip half-width reaches the "
                           "cover thickness (doc/accuracy.md)");
        declare_documented(prm,
                           "Edge refinements",
                           "0",
                           Patterns::Integer(0, 8),
                           "Nip-fitted mesh: times the cells touching the "
                           "contact edge are halved after Global "
                           "refinements (hanging nodes); with theta0 "
                           "prescribed each halves the first-order error "
                           "that the edge's cells put into P with Q2-P1 "
                           "(doc/accuracy.md)");
      }
    } // namespace

    void
    Mesh::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      declare_mesh_source(prm);
      declare_mesh_cells(prm);
      declare_mesh_adaptation(prm);
      prm.leave_subsection();
    }

    void
    Mesh::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      source =
        prm.get("Source") == "gmsh" ? MeshSource::gmsh : MeshSource::builtin;
      mesh_file                 = prm.get("Mesh file");
      radial_cells              = prm.get_integer("Radial cells");
      circumferential_cells     = prm.get_integer("Circumferential cells");
      circumferential_grading   = prm.get_double("Circumferential grading");
      radial_grading            = prm.get_double("Radial grading");
      global_refinements        = prm.get_integer("Global refinements");
      adaptive_passes           = prm.get_integer("Adaptive grading passes");
      const std::string fitting = prm.get("Nip fitting");
      nip_fitting               = fitting == "on"    ? NipFitting::on
                                  : fitting == "off" ? NipFitting::off
                                                     : NipFitting::automatic;
      nip_cells                 = prm.get_integer("Nip cells");
      nip_grading               = prm.get_double("Nip grading");
      edge_refinements          = prm.get_integer("Edge refinements");
      prm.leave_subsection();
    }

    void
    Material::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      declare_documented(prm,
                         "C1",
                         "0.25",
                         Patterns::List(Patterns::Double(), 1),
                         "Mooney-Rivlin constant C1 [MPa]; for a layered "
                         "cover one value per layer, from the core out");
      declare_documented(prm,
                         "C2",
                         "0.25",
                         Patterns::List(Patterns::Double(), 1),
                         "Mooney-Rivlin constant C2 [MPa], one value per "
                         "layer like C1; in-plane results depend on C1 + C2 "
                         "only");
      declare_documented(prm,
                         "Layer thicknesses",
                         "",
                         Patterns::List(Patterns::Double(), 0),
                         "Thickness of every layer of a layered cover [mm], "
                         "from the core out, summing to Outer radius - Inner "
                         "radius; empty: one layer. The mesh puts a cell "
                         "boundary on every interface");
      declare_documented(prm,
                         "Theory",
                         "nonlinear",
                         Patterns::Selection("nonlinear|linear"),
                         "nonlinear: finite strain, follower load, load "
                         "stepping; linear: small strain with shear modulus "
                         "G = 2 (C1 + C2), whole load in one step on the "
                         "undeformed surface");
      declare_documented(prm,
                         "Poisson ratio",
                         "0.5",
                         Patterns::List(Patterns::Double(), 1),
                         "Poisson's ratio nu of the cover in [0, 0.5], one "
                         "value for all layers or one per layer; 0.5: exactly "
                         "incompressible (solid rubber); below 0.5 a "
                         "compressible cover (microcellular, polyurethane) "
                         "with bulk modulus K = 2 G (1 + nu) / (3 (1 - 2 nu))");
      declare_documented(prm,
                         "Bulk modulus",
                         "",
                         Patterns::List(Patterns::Double(), 0),
                         "Bulk modulus K of the cover [MPa], one value for all "
                         "layers or one per layer, instead of Poisson ratio; "
                         "empty: from Poisson ratio");
      EngineeringInputs::declare_material(prm);
      LayerOrder::declare(prm);
      prm.leave_subsection();
    }

    void
    Material::parse(ParameterHandler &prm)
    {
      auto numbers = [&](const std::string &key) {
        std::vector<double> values;
        for (const auto &v : Utilities::split_string_list(prm.get(key)))
          values.push_back(Utilities::string_to_double(v));
        return values;
      };
      prm.enter_subsection("Material");
      layer_C1            = numbers("C1");
      layer_C2            = numbers("C2");
      layer_thicknesses   = numbers("Layer thicknesses");
      layer_poisson_ratio = numbers("Poisson ratio");
      layer_bulk_modulus  = numbers("Bulk modulus");
      theory =
        prm.get("Theory") == "linear" ? Theory::linear : Theory::nonlinear;
      EngineeringInputs::parse_material(prm, *this);
      prm.leave_subsection();
    }

    void
    Discretization::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      declare_documented(prm,
                         "Element",
                         "Q1-P0",
                         Patterns::Selection("Q1-P0|Q2-P1"),
                         "Q1-P0: bilinear displacement, cellwise constant "
                         "pressure (the paper's element); Q2-P1: biquadratic "
                         "displacement, discontinuous linear pressure "
                         "(inf-sup stable)");
      prm.leave_subsection();
    }

    void
    Discretization::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      element = prm.get("Element") == "Q2-P1" ? Element::q2_p1 : Element::q1_p0;
      prm.leave_subsection();
    }

    void
    BoundaryConditions::declare(ParameterHandler &prm)
    {
      const char *defaults[BoundaryIds::n_boundaries] = {"fixed",
                                                         "pressure",
                                                         "symmetry",
                                                         "free"};
      prm.enter_subsection("Boundary conditions");
      for (unsigned int b = 0; b < BoundaryIds::n_boundaries; ++b)
        declare_documented(prm,
                           boundary_names[b],
                           defaults[b],
                           Patterns::Selection("fixed|free|symmetry|pressure"),
                           "fixed: u = 0; free: no traction; symmetry: no "
                           "normal displacement, no shear traction; pressure: "
                           "follower pressure of Load/Pressure function");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      for (unsigned int b = 0; b < BoundaryIds::n_boundaries; ++b)
        condition[b] = condition_from_string(prm.get(boundary_names[b]));
      prm.leave_subsection();
    }

    void
    Load::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Load");
      declare_documented(
        prm,
        "Pressure function",
        "theta < theta0 ? p0 * (1 - (theta/theta0)^2) : 0",
        Patterns::Anything(),
        "Follower pressure f [MPa] on every boundary whose "
        "condition is 'pressure', a muparser expression in "
        "the REFERENCE angle theta [rad] of the surface point; "
        "constants p0, theta0 [rad], R0, R1 [mm] and pi may be "
        "used. Positive f pushes into the body.");
      declare_documented(
        prm,
        "p0",
        "0.1",
        Patterns::Double(),
        "Pressure scale usable as 'p0' in the expression [MPa]");
      declare_documented(prm,
                         "theta0",
                         "10",
                         Patterns::Double(0.),
                         "Half nip angle usable as 'theta0' in the expression; "
                         "given in [deg], seen by the expression in [rad]");
      prm.leave_subsection();
    }

    void
    Load::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Load");
      pressure_function = prm.get("Pressure function");
      p0                = prm.get_double("p0");
      theta0            = prm.get_double("theta0") * degree;
      prm.leave_subsection();
    }

    void
    LoadStepping::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      declare_documented(prm,
                         "Initial steps",
                         "10",
                         Patterns::Integer(1),
                         "The first load increment is 1 / (Initial steps) of "
                         "the full load");
      declare_documented(prm,
                         "Growth factor",
                         "1.5",
                         Patterns::Double(1.),
                         "After a step that converged fast the increment is "
                         "multiplied by this; 1 gives fixed equal steps");
      declare_documented(prm,
                         "Extrapolate",
                         "true",
                         Patterns::Bool(),
                         "Start each load step's Newton iteration from the "
                         "linear extrapolation of the last two converged "
                         "states (fewer iterations); if that start fails, the "
                         "step is retried from the last converged state");
      declare_documented(prm,
                         "Fast Newton iterations",
                         "4",
                         Patterns::Integer(1),
                         "A step that needed at most this many Newton "
                         "iterations counts as fast");
      declare_documented(prm,
                         "Maximum cutbacks",
                         "8",
                         Patterns::Integer(0),
                         "How many times in a row the increment may be halved "
                         "after a failed step before the run stops");
      declare_documented(prm,
                         "Minimum increment",
                         "1e-6",
                         Patterns::Double(0.),
                         "The run stops if a cutback would make the load "
                         "increment smaller than this fraction of the load");
      prm.leave_subsection();
    }

    void
    LoadStepping::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      n_initial_steps        = prm.get_integer("Initial steps");
      growth_factor          = prm.get_double("Growth factor");
      extrapolate            = prm.get_bool("Extrapolate");
      fast_newton_iterations = prm.get_integer("Fast Newton iterations");
      max_cutbacks           = prm.get_integer("Maximum cutbacks");
      min_increment          = prm.get_double("Minimum increment");
      prm.leave_subsection();
    }

    void
    NonlinearSolver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      declare_documented(prm,
                         "Maximum iterations",
                         "15",
                         Patterns::Integer(1),
                         "Newton iterations allowed per load step");
      declare_documented(prm,
                         "Residual tolerance",
                         "1e-9",
                         Patterns::Double(0.),
                         "Converged when |R_u| / |F_ext| is below this "
                         "(Euclidean norms of nodal force vectors)");
      declare_documented(
        prm,
        "Increment tolerance",
        "1e-8",
        Patterns::Double(0.),
        "... and |du| / |u| of the last Newton update, or of a chord step "
        "with the last tangent after it (doc/intro.md, section 5), is below "
        "this");
      declare_documented(prm,
                         "Constraint tolerance",
                         "1e-10",
                         Patterns::Double(0.),
                         "... and sum over cells of |integral(J - 1)| / area "
                         "of the body is below this");
      declare_documented(prm,
                         "Line search",
                         "true",
                         Patterns::Bool(),
                         "Backtrack along the Newton direction when the "
                         "residual grows or J <= 0 somewhere");
      declare_documented(
        prm,
        "Maximum line search steps",
        "6",
        Patterns::Integer(0, 60),
        "Halvings of the Newton step tried by the line search");
      declare_documented(prm,
                         "Verbose",
                         "false",
                         Patterns::Bool(),
                         "Print one line per Newton iteration");
      prm.leave_subsection();
    }

    void
    NonlinearSolver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      max_iterations        = prm.get_integer("Maximum iterations");
      residual_tolerance    = prm.get_double("Residual tolerance");
      increment_tolerance   = prm.get_double("Increment tolerance");
      constraint_tolerance  = prm.get_double("Constraint tolerance");
      line_search           = prm.get_bool("Line search");
      max_line_search_steps = prm.get_integer("Maximum line search steps");
      verbose               = prm.get_bool("Verbose");
      prm.leave_subsection();
    }

    void
    LinearSolver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      declare_documented(prm,
                         "Method",
                         "direct",
                         Patterns::Selection("direct|gmres-amg"),
                         "direct: sparse LU (robust; best up to about a "
                         "million DoFs in 2D, see doc/accuracy.md); gmres-amg: "
                         "GMRES with a block preconditioner, AMG on the "
                         "displacement block and the pressure mass matrix "
                         "for the Schur complement");
      declare_documented(prm,
                         "Direct solver",
                         "Amesos_Mumps",
                         Patterns::Selection("Amesos_Mumps|Amesos_Klu"),
                         "Sparse direct solver (through Trilinos Amesos) for "
                         "the indefinite, non-symmetric Newton system");
      declare_documented(prm,
                         "Iterative tolerance",
                         "1e-9",
                         Patterns::Double(1e-14, 1e-2),
                         "gmres-amg: stop when |b - K x| <= this |b|");
      declare_documented(prm,
                         "Max iterations",
                         "500",
                         Patterns::Integer(1, 100000),
                         "gmres-amg: iterations per linear solve before the "
                         "run is refused");
      prm.leave_subsection();
    }

    void
    LinearSolver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      method              = prm.get("Method");
      direct_solver       = prm.get("Direct solver");
      iterative_tolerance = prm.get_double("Iterative tolerance");
      max_iterations      = prm.get_integer("Max iterations");
      prm.leave_subsection();
    }

    void
    Output::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      declare_documented(prm,
                         "Directory",
                         "output",
                         Patterns::Anything(),
                         "Where results go; created if missing");
      declare_documented(prm,
                         "Write VTU",
                         "true",
                         Patterns::Bool(),
                         "Write VTU/PVTU files and a PVD record for ParaView");
      declare_documented(prm,
                         "VTU every step",
                         "true",
                         Patterns::Bool(),
                         "Write VTU for every converged load step (else only "
                         "the final state)");
      declare_documented(prm,
                         "Write CSV",
                         "true",
                         Patterns::Bool(),
                         "Write outer_surface.csv, bond_surface.csv and "
                         "load_steps.csv");
      declare_documented(prm,
                         "CSV every step",
                         "true",
                         Patterns::Bool(),
                         "Also write outer_surface-NNNN.csv and "
                         "bond_surface-NNNN.csv for every converged load step "
                         "(the files without a number hold the final state)");
      declare_documented(prm,
                         "Print timing",
                         "true",
                         Patterns::Bool(),
                         "Print the TimerOutput summary at the end");
      declare_documented(prm,
                         "Units",
                         "SI",
                         Patterns::Anything(),
                         "Units of the reported numbers (screen, nip report, "
                         "CSV headers). Allowed: SI (mm, MPa, N/mm or the "
                         "Contact/Load unit, m/min) or US (in, psi, pli, lbf, "
                         "fpm), any case");
      declare_documented(prm,
                         "Verbosity",
                         "normal",
                         Patterns::Anything(),
                         "What a run prints. Allowed: quiet (only the report, "
                         "warnings and errors), normal, detailed (also the "
                         "Newton iterations of every solve), any case");
      prm.leave_subsection();
    }

    void
    Output::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory               = prm.get("Directory");
      write_vtu               = prm.get_bool("Write VTU");
      vtu_every_step          = prm.get_bool("VTU every step");
      write_csv               = prm.get_bool("Write CSV");
      csv_every_step          = prm.get_bool("CSV every step");
      print_timing            = prm.get_bool("Print timing");
      units                   = Units::system_from_string(prm.get("Units"));
      const std::string level = Units::lower_case(prm.get("Verbosity"));
      AssertThrow(level == "quiet" || level == "normal" || level == "detailed",
                  ExcMessage("Output/Verbosity: unknown level '" +
                             prm.get("Verbosity") +
                             "' (quiet, normal or detailed)"));
      verbosity = level == "quiet"    ? Verbosity::quiet
                  : level == "normal" ? Verbosity::normal
                                      : Verbosity::detailed;
      prm.leave_subsection();
    }

    void
    Contact::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      declare_documented(prm,
                         "Mode",
                         "none",
                         Patterns::Selection("none|nip angle|load|indentation"),
                         "none: apply Load/Pressure function; otherwise "
                         "contact with the indenter (the outer arc must have "
                         "condition 'pressure'), controlled by: nip angle "
                         "(Batra's inverse iteration, theta0 given), load "
                         "(P given) or indentation (u0 given)");
      declare_documented(prm,
                         "Values",
                         default_values,
                         Patterns::List(Patterns::Double(0.), 1),
                         "The controlled quantity, one nip per value, "
                         "comma-separated (several make a sweep): theta0 "
                         "[deg], P [Load unit, two-sided] or u0 [mm] by "
                         "Mode");
      declare_documented(prm,
                         "Indenter radius",
                         default_indenter_radius,
                         Patterns::Anything(),
                         "Rbar, radius of the rigid indenter [mm]; 'inf' for "
                         "a flat rigid plane (two equal rolls by symmetry)");
      declare_documented(prm,
                         "Conformity tolerance",
                         "1e-6",
                         Patterns::Double(0., 0.1),
                         "Largest distance of a contact-zone surface node "
                         "from the indenter, as a fraction of the "
                         "indentation u0 (the paper accepted 1e-2)");
      declare_documented(prm,
                         "Control tolerance",
                         "1e-6",
                         Patterns::Double(0., 0.1),
                         "Relative tolerance on P or u0 for Mode = load or "
                         "indentation");
      declare_documented(prm,
                         "Maximum iterations",
                         "40",
                         Patterns::Integer(1),
                         "Contact (Newton) iterations on the pressure "
                         "parameters, and outer iterations on theta0");
      declare_documented(prm,
                         "Compare with linear theory",
                         "true",
                         Patterns::Bool(),
                         "Also solve each nip (same theta0) with the linear "
                         "theory and report it beside the nonlinear one");
      EngineeringInputs::declare_contact(prm);
      prm.leave_subsection();
    }

    void
    Contact::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      const std::string m = prm.get("Mode");
      mode                = m == "nip angle"     ? ContactMode::nip_angle
                            : m == "load"        ? ContactMode::load
                            : m == "indentation" ? ContactMode::indentation
                                                 : ContactMode::none;
      values.clear();
      for (const auto &v : Utilities::split_string_list(prm.get("Values")))
        {
          double x = 0;
          try
            {
              x = std::stod(v);
            }
          catch (...) // out of range: denormal or beyond double
            {
              AssertThrow(false,
                          ExcMessage("Contact/Values: '" + v +
                                     "' is not a representable number"));
            }
          values.push_back(x * (mode == ContactMode::nip_angle ? degree : 1.));
        }
      const std::string r = prm.get("Indenter radius");
      // Compared as numbers: "8.0" is the default "8".
      const auto as_numbers = [](const std::string &text) {
        std::vector<double> x;
        for (const auto &v : Utilities::split_string_list(text))
          x.push_back(std::strtod(v.c_str(), nullptr));
        return x;
      };
      keys_set_without_mode =
        mode == ContactMode::none &&
        (as_numbers(prm.get("Values")) != as_numbers(default_values) ||
         as_numbers(r) != as_numbers(default_indenter_radius));
      if (r == "inf" || r == "infinity")
        indenter_radius = std::numeric_limits<double>::infinity();
      else
        {
          std::size_t used = 0;
          try
            {
              indenter_radius = std::stod(r, &used);
            }
          catch (...)
            {
              used = 0;
            }
          AssertThrow(used == r.size() && used > 0 && indenter_radius > 0,
                      ExcMessage("Contact/Indenter radius must be a positive "
                                 "number of mm or 'inf', got '" +
                                 r + "'"));
        }
      tolerance         = prm.get_double("Conformity tolerance");
      control_tolerance = prm.get_double("Control tolerance");
      max_iterations    = prm.get_integer("Maximum iterations");
      compare_linear    = prm.get_bool("Compare with linear theory");
      EngineeringInputs::parse_contact(prm, *this);
      prm.leave_subsection();
    }

    void
    MatingRoll::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mating roll");
      declare_documented(prm,
                         "Type",
                         "rigid",
                         Patterns::Selection("rigid|covered roll"),
                         "rigid: the circle or plane of Contact/Indenter "
                         "radius; covered roll: a second covered roll, "
                         "described by the subsections below (same entries "
                         "as the top-level ones), both rolls deformable");
      declare_documented(prm,
                         "Maximum iterations",
                         "60",
                         Patterns::Integer(1),
                         "Outer iterations between the two rolls per nip "
                         "(each one a contact solve of the first roll and "
                         "a solve of the mating roll)");
      Geometry::declare(prm);
      Material::declare(prm);
      Mesh::declare(prm);
      prm.leave_subsection();
    }

    void
    MatingRoll::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mating roll");
      covered        = prm.get("Type") == "covered roll";
      max_iterations = prm.get_integer("Maximum iterations");
      // The same code reads both rolls' entries: its messages name them
      // from the subsection, here under "Mating roll/".
      try
        {
          geometry.parse(prm);
          material.parse(prm);
          mesh.parse(prm);
        }
      catch (const ExceptionBase &e)
        {
          AssertThrow(false,
                      ExcMessage(with_entry_prefix(one_line_message(e),
                                                   "Mating roll/")));
        }
      prm.leave_subsection();
    }

    AllParameters
    AllParameters::mating_roll_parameters() const
    {
      AllParameters mate = *this;
      mate.geometry      = mating_roll.geometry;
      mate.material      = mating_roll.material;
      mate.mesh          = mating_roll.mesh;
      // One theory for both rolls (the linear companion switches both).
      mate.material.theory        = material.theory;
      mate.mating_roll.covered    = false;
      mate.contact.compare_linear = false;
      mate.output.directory       = output.directory + "/mating_roll";
      mate.output.print_timing    = false;
      // A study refines the first roll only.
      mate.study.levels.clear();
      return mate;
    }

    void
    Study::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Study");
      declare_documented(prm,
                         "Refinement levels",
                         "",
                         Patterns::List(Patterns::Integer(0, 12), 0),
                         "A refinement study: the scene is run at each of "
                         "these Mesh/Global refinements (e.g. 0, 1, 2, 3) and "
                         "a convergence table with Richardson-extrapolated "
                         "errors, observed orders, wall time and memory is "
                         "written (study.csv, study.txt); empty: a single "
                         "run");
      declare_documented(prm,
                         "Elements",
                         "",
                         Patterns::List(Patterns::Selection("Q1-P0|Q2-P1"), 0),
                         "Elements to compare in the study (e.g. Q1-P0, "
                         "Q2-P1); empty: Discretization/Element only");
      declare_documented(prm,
                         "Sector angles",
                         "",
                         Patterns::List(Patterns::Double(), 0),
                         "Sector angles [deg] to compare in the study (e.g. "
                         "30, 45, 90, 180); the coarse cells near the nip "
                         "stay as they are and cells are added or dropped at "
                         "the far end; 180 makes the far edge a symmetry edge "
                         "(the untruncated half roll); empty: Geometry/Sector "
                         "angle only");
      declare_documented(prm,
                         "Initial load steps",
                         "",
                         Patterns::List(Patterns::Integer(1), 0),
                         "Values of Load stepping/Initial steps to compare in "
                         "the study (e.g. 1, 10, 100); empty: that value only");
      prm.leave_subsection();
    }

    void
    Study::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Study");
      levels.clear();
      for (const auto &v :
           Utilities::split_string_list(prm.get("Refinement levels")))
        levels.push_back(std::stoi(v));
      // Richardson extrapolation and the rates assume h halves per row.
      for (unsigned int i = 1; i < levels.size(); ++i)
        AssertThrow(levels[i] == levels[i - 1] + 1,
                    ExcMessage("Study/Refinement levels: the levels must be "
                               "consecutive and increasing (e.g. 0, 1, 2, 3)"));
      elements.clear();
      for (const auto &v : Utilities::split_string_list(prm.get("Elements")))
        elements.push_back(v == "Q2-P1" ? Element::q2_p1 : Element::q1_p0);
      sector_angles.clear();
      for (const auto &v :
           Utilities::split_string_list(prm.get("Sector angles")))
        {
          const double a = Utilities::string_to_double(v);
          AssertThrow(a > 0 && a <= 180,
                      ExcMessage("Study/Sector angles: " + v +
                                 " is not in (0, 180] deg"));
          sector_angles.push_back(a * degree);
        }
      initial_steps.clear();
      for (const auto &v :
           Utilities::split_string_list(prm.get("Initial load steps")))
        initial_steps.push_back(Utilities::string_to_int(v));
      prm.leave_subsection();
    }

    void
    Accuracy::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Accuracy");
      declare_documented(prm,
                         "Error estimate",
                         "true",
                         Patterns::Bool(),
                         "Solve each nip a second time one mesh level "
                         "coarser (finer at level 0) and report, beside P, "
                         "u0, theta0, the nip width, the pressures and the "
                         "bond stresses, their estimated error from the "
                         "difference and the element's order of convergence "
                         "(doc/accuracy.md); it costs a solve on a quarter "
                         "of the cells (on four times the cells at level 0)");
      prm.leave_subsection();
    }

    void
    Accuracy::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Accuracy");
      error_estimate = prm.get_bool("Error estimate");
      prm.leave_subsection();
    }

    void
    AllParameters::declare(ParameterHandler &prm)
    {
      Geometry::declare(prm);
      Mesh::declare(prm);
      Material::declare(prm);
      Discretization::declare(prm);
      BoundaryConditions::declare(prm);
      Load::declare(prm);
      LoadStepping::declare(prm);
      NonlinearSolver::declare(prm);
      LinearSolver::declare(prm);
      Output::declare(prm);
      Contact::declare(prm);
      MatingRoll::declare(prm);
      Study::declare(prm);
      Accuracy::declare(prm);
      Face::declare(prm);
      ThreeD::declare(prm);
      AccuracyTarget::declare(prm);
      StudyValues::declare(prm);
      Rolling::declare(prm);
    }

    void
    AllParameters::parse(ParameterHandler &prm)
    {
      geometry.parse(prm);
      mesh.parse(prm);
      material.parse(prm);
      discretization.parse(prm);
      boundary_conditions.parse(prm);
      load.parse(prm);
      load_stepping.parse(prm);
      nonlinear_solver.parse(prm);
      linear_solver.parse(prm);
      output.parse(prm);
      contact.parse(prm);
      mating_roll.parse(prm);
      study.parse(prm);
      accuracy.parse(prm);
      // Detailed output is the Newton solver's own log; quiet prints no
      // timing table.
      if (output.verbosity == Verbosity::detailed)
        nonlinear_solver.verbose = true;
      if (output.verbosity == Verbosity::quiet)
        output.print_timing = false;
      if (mating_roll.covered)
        {
          // The rigid indenter's radius would be silently ignored.
          AssertThrow(contact.indenter_radius ==
                        std::stod(default_indenter_radius),
                      ExcMessage("Contact/Indenter radius (or diameter) "
                                 "describes a rigid mating roll, but Mating "
                                 "roll/Type = covered roll: remove it"));
          AssertThrow(mating_roll.material.theory == material.theory,
                      ExcMessage("Mating roll/Material/Theory differs from "
                                 "Material/Theory: both rolls take one "
                                 "theory"));
        }
    }

    void
    AllParameters::read(const std::string &filename)
    {
      ParameterHandler prm;
      read(filename, prm);
    }

    void
    AllParameters::read(const std::string &filename, ParameterHandler &prm)
    {
      {
        std::ifstream in(filename);
        AssertThrow(in.good(),
                    ExcMessage("parameter file '" + filename +
                               "' cannot be opened"));
        // A directory opens as an empty stream: the default scene would run.
        AssertThrow(std::filesystem::is_regular_file(filename),
                    ExcMessage("parameter file '" + filename +
                               "' is not a regular file (a directory?)"));
      }
      declare(prm);
      const ChangedEntries changed(prm);
      prm.parse_input(filename);
      parse(prm);
      LayerOrder::apply(prm, *this);
      validate();
      warn_ignored_entries(*this, changed);
    }

    void
    AllParameters::validate() const
    {
      // Each roll first: the scene's checks below take its geometry as read.
      validate_rolls(*this);
      validate_scene();
      validate_contact();
      validate_mesh();
      validate_output();
      validate_mating_roll();
    }

    void
    AllParameters::validate_mating_roll() const
    {
      // Its own entries are checked by validate_rolls(), by the first
      // roll's code; here what concerns the scene.
      if (!mating_roll.covered)
        return;
      AssertThrow(contact.mode != ContactMode::none,
                  ExcMessage("Mating roll/Type = covered roll needs a contact "
                             "scene (Contact/Mode)"));
    }

    void
    AllParameters::validate_scene() const
    {
      AssertThrow(study.sector_angles.empty() ||
                    mesh.source == MeshSource::builtin,
                  ExcMessage("Study/Sector angles needs Mesh/Source = builtin "
                             "(a gmsh mesh has its own sector)"));
      // The load expression must parse and be finite on the whole arc.
      PressureLoad check(load, geometry);
      check.check_finite();
      AssertThrow(!contact.keys_set_without_mode,
                  ExcMessage("Contact/Values or Contact/Indenter radius is "
                             "set but Contact/Mode = none, so they would be "
                             "ignored: set Mode (nip angle, load or "
                             "indentation) or remove them"));
      if (contact.mode == ContactMode::none &&
          load.pressure_function.find("theta0") != std::string::npos)
        AssertThrow(load.theta0 <= geometry.sector_angle * (1 + 1e-12) ||
                      !check.loads_beyond(load.theta0),
                    ExcMessage("Load/theta0 (" + number(load.theta0 / degree) +
                               " deg) reaches beyond Geometry/Sector angle (" +
                               number(geometry.sector_angle / degree) +
                               " deg): the load beyond the sector would be "
                               "dropped"));
    }

    void
    AllParameters::validate_contact() const
    {
      validate_targets(*this);
      const double R0 = geometry.outer_radius;
      if (contact.mode != ContactMode::none)
        {
          AssertThrow(boundary_conditions.condition[BoundaryIds::outer_arc] ==
                        BoundaryCondition::pressure,
                      ExcMessage("Contact/Mode needs Boundary conditions/Outer "
                                 "arc (id 1) = pressure"));
          // The inverse iteration mirrors the nip about the line of centres.
          AssertThrow(
            boundary_conditions.condition[BoundaryIds::symmetry_edge] ==
              BoundaryCondition::symmetry,
            ExcMessage("Contact/Mode needs Boundary conditions/Symmetry edge "
                       "(id 2) = symmetry: the contact iteration takes the "
                       "line of centres as a symmetry line"));
          AssertThrow(std::isinf(contact.indenter_radius) ||
                        contact.indenter_radius <= 1e6 * R0,
                      ExcMessage("Contact/Indenter radius = " +
                                 number(contact.indenter_radius) +
                                 " mm is more than 1e6 times the roll's: "
                                 "write 'inf' for a flat indenter"));
          for (const double v : contact.values)
            AssertThrow(v > 0 && (contact.mode != ContactMode::nip_angle ||
                                  v < geometry.sector_angle),
                        ExcMessage("Contact/Values: every value must be "
                                   "positive (and, for nip angles, below "
                                   "Geometry/Sector angle)"));
        }
    }

    void
    AllParameters::validate_material() const
    {
      // One code for both rolls (scene/scene_validation.h).
      validate_cover(material, geometry, "");
    }

    void
    AllParameters::validate_mesh() const
    {
      // The mesh entries of each roll are checked by validate_rolls().
      AssertThrow(mesh.nip_fitting != NipFitting::on ||
                    contact.mode != ContactMode::none,
                  ExcMessage("Mesh/Nip fitting = on needs a contact "
                             "scene (Contact/Mode): there is no nip "
                             "to fit otherwise"));
    }

    void
    AllParameters::validate_output() const
    {
      AssertThrow(!output.directory.empty(),
                  ExcMessage("Output/Directory must not be empty"));
      AssertThrow(contact.values.size() <= max_nips_per_run,
                  ExcMessage("Contact/Values has " +
                             std::to_string(contact.values.size()) +
                             " values; one run takes at most " +
                             std::to_string(max_nips_per_run) +
                             " (each is at least one full contact solve)"));
      AssertThrow(!std::filesystem::exists(output.directory) ||
                    std::filesystem::is_directory(output.directory),
                  ExcMessage("Output/Directory '" + output.directory +
                             "' exists and is not a directory"));
    }

    bool
    AllParameters::nip_fitted_mesh() const
    {
      if (mesh.nip_fitting == NipFitting::automatic)
        return contact.mode != ContactMode::none &&
               mesh.source == MeshSource::builtin && mesh.adaptive_passes == 0;
      return mesh.nip_fitting == NipFitting::on;
    }
  } // namespace Parameters
} // namespace rollnip
