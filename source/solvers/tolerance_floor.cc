#include <rollnip/solvers/tolerance_floor.h>

#include <iomanip>
#include <sstream>

namespace rollnip
{
  namespace ToleranceFloor
  {
    namespace
    {
      /// Raises @p value to @p floor, with a warning naming @p entry.
      void
      clamp(double                   &value,
            const double              floor,
            const std::string        &entry,
            std::vector<std::string> &warnings)
      {
        if (value >= floor)
          return;
        std::ostringstream s;
        s << std::setprecision(3) << entry << " = " << value
          << " is below what double precision resolves; using " << floor
          << " (a smaller tolerance would end in an iteration stalled on "
             "round-off)";
        warnings.push_back(s.str());
        value = floor;
      }
    } // namespace

    std::vector<std::string>
    apply(Parameters::AllParameters &p)
    {
      std::vector<std::string> warnings;
      auto                    &newton = p.nonlinear_solver;
      clamp(newton.residual_tolerance,
            relative,
            "Nonlinear solver/Residual tolerance",
            warnings);
      clamp(newton.increment_tolerance,
            relative,
            "Nonlinear solver/Increment tolerance",
            warnings);
      clamp(newton.constraint_tolerance,
            relative,
            "Nonlinear solver/Constraint tolerance",
            warnings);
      if (p.contact.mode != Parameters::ContactMode::none)
        {
          clamp(p.contact.tolerance,
                relative,
                "Contact/Conformity tolerance",
                warnings);
          if (p.contact.mode != Parameters::ContactMode::nip_angle ||
              p.mating_roll.covered)
            clamp(p.contact.control_tolerance,
                  control,
                  "Contact/Control tolerance",
                  warnings);
        }
      AssertThrow(p.contact.mode == Parameters::ContactMode::none ||
                    p.contact.max_iterations > 1,
                  ExcMessage("Contact/Maximum iterations = 1: the contact "
                             "iteration needs at least 2 (the first measures "
                             "the gaps of the first pressure guess)"));
      AssertThrow(!p.mating_roll.covered || p.mating_roll.max_iterations > 1,
                  ExcMessage("Mating roll/Maximum iterations = 1: the "
                             "two-roll iteration needs at least 2 passes "
                             "(the first only measures how far the mating "
                             "surface moves)"));
      return warnings;
    }

    double
    conformity_round_off(const double R0, const double u0)
    {
      return 10 * std::numeric_limits<double>::epsilon() * R0 / u0;
    }
  } // namespace ToleranceFloor
} // namespace rollnip
