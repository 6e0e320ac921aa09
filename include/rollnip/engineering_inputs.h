#ifndef rollnip_engineering_inputs_h
#define rollnip_engineering_inputs_h

#include <deal.II/base/parameter_handler.h>

#include <rollnip/parameters.h>

#include <string>

/**
 * The parameter entries that take a roll's data the way an engineer has
 * them (doc/engineering_inputs.md): hardness instead of C1, C2, diameters
 * and cover thickness instead of radii, line loads in N/mm, kN/m or pli,
 * the surface speed. Each declare_* is called inside its subsection by
 * the subsection's declare(), each parse_* at the end of its parse(); they
 * turn these entries into the program's own (mm, MPa, N/mm).
 */
namespace rollnip
{
  namespace EngineeringInputs
  {
    /// Geometry: Roll diameter, Cover thickness.
    void
    declare_geometry(ParameterHandler &prm);
    void
    parse_geometry(ParameterHandler &prm, Parameters::Geometry &geometry);

    /// Material: Hardness, Hardness scale, C2/C1 ratio.
    void
    declare_material(ParameterHandler &prm);
    void
    parse_material(ParameterHandler &prm, Parameters::Material &material);

    /// Contact: Indenter diameter, Load unit, Surface speed.
    void
    declare_contact(ParameterHandler &prm);
    void
    parse_contact(ParameterHandler &prm, Parameters::Contact &contact);

    /// The shear modulus G = 2 (C1 + C2) [MPa] and whether it lies in the
    /// range of rubbers, 0.01 to 100 MPa (warns otherwise, on rank 0:
    /// likely a unit mistake, but the tests scale the modulus on purpose);
    /// the entries are named with @p prefix ("" or "Mating roll/").
    void
    check_modulus(const Parameters::Material &material,
                  const std::string          &prefix);

    /// The inputs that were converted, one line each ("" if none), for the
    /// screen at the start of a run.
    std::string
    describe(const Parameters::AllParameters &parameters);

    /// summary.txt lines: the moduli used, where they came from, and the
    /// line load unit.
    std::string
    summary_entries(const Parameters::AllParameters &parameters);
  } // namespace EngineeringInputs
} // namespace rollnip

#endif
