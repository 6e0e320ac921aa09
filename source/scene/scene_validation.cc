#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <rollnip/contact/nip_estimates.h>
#include <rollnip/cost_estimate.h>
#include <rollnip/engineering_inputs.h>
#include <rollnip/geometry/gmsh_scan.h>
#include <rollnip/geometry/roll_mesh.h>
#include <rollnip/material/compressibility.h>
#include <rollnip/parameter_entries.h>
#include <rollnip/scene/scene_validation.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace rollnip
{
  namespace
  {
    /// The smallest core radius over the outer radius (validate_geometry()).
    constexpr double min_core_fraction = 0.01;

    constexpr double degree = numbers::PI / 180.;

    std::string
    degrees(const double radians)
    {
      return Parameters::number(radians / degree) + " deg";
    }

    /// Radii and sector angle of one roll.
    void
    validate_geometry(const Parameters::Geometry &g, const std::string &prefix)
    {
      const std::string G = prefix + "Geometry/";
      AssertThrow(g.inner_radius > 0,
                  ExcMessage(G + "Inner radius must be positive, got " +
                             Parameters::number(g.inner_radius) + " mm"));
      // A core thinner than this is a solid roll, which the bonded core
      // boundary cannot describe (its bond stresses are not finite).
      AssertThrow(g.inner_radius >= min_core_fraction * g.outer_radius ||
                    g.inner_radius >= g.outer_radius,
                  ExcMessage(G + "Inner radius (" +
                             Parameters::number(g.inner_radius) +
                             " mm) is less than 1 % of the outer radius (" +
                             Parameters::number(g.outer_radius) +
                             " mm): the cover must be bonded to a core; a "
                             "solid rubber roll is not modelled"));
      AssertThrow(g.inner_radius < g.outer_radius,
                  ExcMessage(
                    G + "Inner radius (" + Parameters::number(g.inner_radius) +
                    " mm) must be smaller than " + G + "Outer radius (" +
                    Parameters::number(g.outer_radius) + " mm)"));
      AssertThrow(g.sector_angle > 0 &&
                    g.sector_angle <= numbers::PI * (1 + 1e-12),
                  ExcMessage(G + "Sector angle must lie in (0, 180] deg, got " +
                             degrees(g.sector_angle)));
    }

    /// The Mooney-Rivlin constants of every layer.
    void
    validate_constants(const Parameters::Material &m, const std::string &M)
    {
      const unsigned int n = m.n_layers();
      for (unsigned int j = 0; j < n; ++j)
        {
          const double      C1 = m.layer_C1[j], C2 = m.layer_C2[j];
          const std::string layer =
            n == 1 ? "" : " of layer " + std::to_string(j + 1);
          const std::string got = ", got C1 = " + std::to_string(C1) +
                                  " MPa, C2 = " + std::to_string(C2) + " MPa";
          AssertThrow(C1 + C2 > 0,
                      ExcMessage(M + "C1 + C2" + layer +
                                 " must be positive (shear modulus 2 (C1 + "
                                 "C2))" +
                                 got));
          AssertThrow(C1 >= 0 && C2 >= 0,
                      ExcMessage(M + "C1 and C2" + layer +
                                 " must not be negative (Mooney-Rivlin "
                                 "stability)" +
                                 got));
          const double G = 2 * (C1 + C2);
          AssertThrow(G >= 1e-6 && G <= 1e9,
                      ExcMessage(M + "C1 + C2" + layer +
                                 ": the shear modulus 2 (C1 + C2) = " +
                                 Parameters::number(G) +
                                 " MPa is outside 1e-6 to 1e9 MPa (a unit "
                                 "mistake? C1 and C2 are in MPa)"));
        }
    }

    /// The mesh entries of one roll, among themselves.
    void
    validate_mesh_entries(const Parameters::AllParameters &roll,
                          const std::string               &prefix)
    {
      const auto       &mesh = roll.mesh;
      const std::string E    = prefix + "Mesh/";
      const bool builtin     = mesh.source == Parameters::MeshSource::builtin;
      AssertThrow(mesh.adaptive_passes == 0 || builtin,
                  ExcMessage(E + "Adaptive grading passes needs " + E +
                             "Source = builtin (it re-cuts the builtin mesh)"));
      AssertThrow(builtin || !mesh.mesh_file.empty(),
                  ExcMessage(E + "Mesh file must name a gmsh file when " + E +
                             "Source = gmsh"));
      if (mesh.nip_fitting == Parameters::NipFitting::on)
        {
          AssertThrow(builtin,
                      ExcMessage(E + "Nip fitting = on needs " + E +
                                 "Source = builtin (a gmsh mesh cannot be "
                                 "re-fitted)"));
          AssertThrow(mesh.adaptive_passes == 0,
                      ExcMessage(E + "Nip fitting = on and " + E +
                                 "Adaptive grading passes both move the "
                                 "cells: choose one"));
        }
      AssertThrow(mesh.edge_refinements == 0 || roll.nip_fitted_mesh(),
                  ExcMessage(E +
                             "Edge refinements needs the nip-fitted "
                             "mesh (a contact scene, " +
                             E +
                             "Source = builtin, Nip fitting not off): "
                             "on other meshes the contact edge is not a "
                             "vertex"));
      if (roll.nip_fitted_mesh())
        AssertThrow(mesh.nip_cells + 2 <= mesh.circumferential_cells,
                    ExcMessage(E + "Nip cells (" +
                               std::to_string(mesh.nip_cells) +
                               ") must leave at least 2 of " + E +
                               "Circumferential cells (" +
                               std::to_string(mesh.circumferential_cells) +
                               ") beyond the contact zone"));
    }

    /// Whether the roll's mesh takes the contact edges @p nips: up to
    /// half the sector on the nip-fitted mesh, inside it otherwise.
    void
    validate_reach(const Parameters::AllParameters &roll,
                   const std::string               &prefix,
                   const NipReach                  &nips)
    {
      const double sector = roll.geometry.sector_angle;
      const bool   fitted = roll.nip_fitted_mesh();
      const double reach  = fitted ? 0.5 * sector : sector;
      for (std::size_t i = 0; i < nips.angles.size(); ++i)
        AssertThrow(
          nips.angles[i] <= reach * (1 + 1e-12),
          ExcMessage(
            prefix + "Geometry/Sector angle (" + degrees(sector) + "): " +
            (fitted ? "the nip-fitted mesh takes contact edges up to half "
                      "of it (" +
                        degrees(reach) + ")"
                    : std::string("the mesh ends there")) +
            ", but " + nips.sources[i] + " puts " +
            (prefix.empty() ? "the" : "the mating roll's") + " contact edge " +
            (nips.estimated ? "at about " : "at ") + degrees(nips.angles[i]) +
            ": widen the sector or lower the value"));
    }

    /// A roll whose diameter is outside 5 mm to 5 m was most likely given
    /// in another unit than mm: one warning line on rank 0.
    void
    warn_unit(const Parameters::Geometry &g, const std::string &prefix)
    {
      const double D = 2 * g.outer_radius;
      if ((D >= 5 && D <= 5000) ||
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      const std::string G = prefix + "Geometry/";
      std::cerr
        << "rollnip: warning: "
        << (g.from_diameters
              ? G + "Roll diameter = " + Parameters::number(D) + " mm"
              : G + "Outer radius = " + Parameters::number(g.outer_radius) +
                  " mm (a roll diameter of " + Parameters::number(D) + " mm)")
        << " is outside 5 mm to 5 m, the range of rolls (a unit "
           "mistake? lengths are in mm)"
        << std::endl;
    }

    /// A total force on a face length outside 10 mm to 20 m most likely has
    /// the length in another unit than mm: one warning line on rank 0.
    void
    warn_face_length(const Parameters::Contact &c)
    {
      const double L = c.load_unit.face_length;
      if (!c.load_unit.is_total_force() || (L >= 10 && L <= 20000) ||
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      std::cerr << "rollnip: warning: Contact/Face length = "
                << Parameters::number(L)
                << " mm is outside 10 mm to 20 m, the range of roll faces "
                   "(a unit mistake? lengths are in mm); the line load is "
                   "the force over it"
                << std::endl;
    }

    /// The reach the first roll's and the mating roll's meshes need for
    /// the first roll's nip angles (Contact/Mode = nip angle).
    NipReach
    nip_reach(const Parameters::AllParameters &p, const bool of_mate)
    {
      NipReach reach;
      reach.estimated = of_mate;
      if (p.contact.mode != Parameters::ContactMode::nip_angle)
        return reach;
      for (const double theta0 : p.contact.values)
        {
          reach.angles.push_back(of_mate
                                   ? NipEstimates::mate_nip_angle(
                                       p.geometry.outer_radius,
                                       p.mating_roll.geometry.outer_radius,
                                       theta0)
                                   : theta0);
          reach.sources.push_back("Contact/Values = " + degrees(theta0));
        }
      return reach;
    }
  } // namespace

  void
  validate_cover(const Parameters::Material &m,
                 const Parameters::Geometry &g,
                 const std::string          &prefix)
  {
    const std::string  M         = prefix + "Material/";
    const unsigned int n         = m.n_layers();
    const std::string  per_layer = " value(s) but " + M + "C1 has " +
                                  std::to_string(n) + ": give one per layer";
    AssertThrow(m.layer_C2.size() == n,
                ExcMessage(M + "C2 has " + std::to_string(m.layer_C2.size()) +
                           per_layer));
    AssertThrow(m.layer_thicknesses.empty() || m.layer_thicknesses.size() == n,
                ExcMessage(M + "Layer thicknesses has " +
                           std::to_string(m.layer_thicknesses.size()) +
                           per_layer));
    AssertThrow(n == 1 || !m.layer_thicknesses.empty(),
                ExcMessage(M + "C1 has " + std::to_string(n) +
                           " values (layers) but " + M +
                           "Layer thicknesses is empty: give the thickness "
                           "of every layer [mm]"));
    validate_constants(m, M);
    Compressibility::validate(m, M);
    const double h   = g.outer_radius - g.inner_radius;
    double       sum = 0;
    for (const double t : m.layer_thicknesses)
      {
        AssertThrow(t > 0,
                    ExcMessage(M +
                               "Layer thicknesses must be positive, "
                               "got " +
                               Parameters::number(t) + " mm"));
        sum += t;
      }
    AssertThrow(m.layer_thicknesses.empty() || std::abs(sum - h) <= 1e-9 * h,
                ExcMessage(M + "Layer thicknesses sum to " +
                           Parameters::number(sum) +
                           " mm, but the cover "
                           "is " +
                           prefix +
                           "Geometry/Outer radius - Inner "
                           "radius = " +
                           Parameters::number(h) + " mm thick"));
  }

  namespace
  {
    /// The largest shear modulus [MPa] of the layers of both covers.
    double
    stiffest_layer(const Parameters::AllParameters &p)
    {
      double     G   = 0;
      const auto add = [&G](const Parameters::Material &m) {
        for (unsigned int j = 0; j < m.n_layers(); ++j)
          G = std::max(G, 2 * (m.layer_C1[j] + m.layer_C2[j]));
      };
      add(p.material);
      if (p.mating_roll.covered)
        add(p.mating_roll.material);
      return G;
    }

    /// How the user gave the line load @p P [N/mm]: "Contact/Values = 2 kN
    /// over Contact/Face length = 1e-300 mm is a line load of 2e+303
    /// N/mm", or "Contact/Values = 5 N/mm".
    std::string
    given_as(const Parameters::Contact &c, const double P)
    {
      const LineLoadUnit &u = c.load_unit;
      const std::string   typed =
        "Contact/Values = " + Parameters::number(P / u.to_n_per_mm) + " " +
        u.name;
      if (u.is_total_force())
        return typed + " over Contact/Face length = " +
               Parameters::number(u.face_length) + " mm is a line load of " +
               Parameters::number(P) + " N/mm";
      if (u.name != "N/mm")
        return typed + " (" + Parameters::number(P) + " N/mm)";
      return typed;
    }
  } // namespace

  void
  validate_targets(const Parameters::AllParameters &p)
  {
    const auto &c = p.contact;
    if (c.mode == Parameters::ContactMode::load)
      {
        const double R0    = p.geometry.outer_radius;
        const double G     = stiffest_layer(p);
        const double limit = max_load_over_G_R0 * G * R0;
        for (const double P : c.values)
          AssertThrow(std::isfinite(P) && P <= limit,
                      ExcMessage(
                        given_as(c, P) + (std::isfinite(P) ? "," : "") +
                        " more than " + Parameters::number(max_load_over_G_R0) +
                        " G R0 = " + Parameters::number(limit) +
                        " N/mm (G = " + Parameters::number(G) +
                        " MPa, the stiffest layer's, R0 = " +
                        Parameters::number(R0) +
                        " mm): no cover carries it (a unit mistake?)"));
      }
    if (c.mode == Parameters::ContactMode::indentation)
      {
        double h = p.geometry.outer_radius - p.geometry.inner_radius;
        if (p.mating_roll.covered)
          h += p.mating_roll.geometry.outer_radius -
               p.mating_roll.geometry.inner_radius;
        for (const double u0 : c.values)
          AssertThrow(u0 < h,
                      ExcMessage("Contact/Values = " + Parameters::number(u0) +
                                 " mm: the indentation reaches through the "
                                 "cover" +
                                 (p.mating_roll.covered ? "s (" : " (") +
                                 Parameters::number(h) +
                                 " mm thick): the core would touch the "
                                 "mating surface"));
      }
    warn_face_length(p.contact);
  }

  double
  validate_roll(const Parameters::AllParameters &roll,
                const std::string               &prefix,
                const NipReach                  &nips)
  {
    validate_geometry(roll.geometry, prefix);
    validate_cover(roll.material, roll.geometry, prefix);
    EngineeringInputs::check_modulus(roll.material, prefix);
    validate_mesh_entries(roll, prefix);
    validate_reach(roll, prefix, nips);
    warn_unit(roll.geometry, prefix);
    // A 3D mesh is the 3D body's (three_d/drawn_mesh.h checks it there);
    // a 2D run refuses it where it reads the mesh.
    if (roll.mesh.source == Parameters::MeshSource::gmsh &&
        gmsh_mesh_dimension(roll.mesh.mesh_file) == 3)
      return 0;
    if (roll.mesh.source == Parameters::MeshSource::gmsh)
      return check_gmsh_mesh(roll, prefix);
    return double(roll.mesh.radial_cells) * roll.mesh.circumferential_cells;
  }

  void
  validate_rolls(const Parameters::AllParameters &p)
  {
    const double cells = validate_roll(p, "", nip_reach(p, false));
    if (!p.mating_roll.covered)
      {
        check_cost(p, cells);
        return;
      }
    const double mate_cells = validate_roll(p.mating_roll_parameters(),
                                            "Mating roll/",
                                            nip_reach(p, true));
    check_cost(p, cells, mate_cells);
  }
} // namespace rollnip
