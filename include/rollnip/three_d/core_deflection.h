#ifndef rollnip_three_d_core_deflection_h
#define rollnip_three_d_core_deflection_h

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rollnip
{
  namespace three_d
  {
    /**
     * The prescribed bending line of the rigid core (Three d/Core
     * deflection, doc/three_d.md): v(z) [mm] at the axial position z [mm],
     * positive away from the nip, as the face model's beam deflection. The
     * bonded nodes at R1 get u = -v(z) e_x, so that the local approach of
     * the cross-section at z is u0 - v(z). A muparser expression in z with
     * the constant pi.
     */
    class CoreDeflection
    {
    public:
      /// Throws a one-line error naming Three d/Core deflection if
      /// @p expression does not parse.
      explicit CoreDeflection(const std::string &expression);

      /// v(z) [mm]; throws naming the entry if it is not finite.
      double
      value(const double z) const;

      /// The default "0": a straight core, nothing prescribed.
      bool
      is_zero() const
      {
        return zero;
      }

    private:
      std::unique_ptr<dealii::FunctionParser<1>> function;
      bool                                       zero;
    };

    /**
     * The line load q(z_j) [N/mm] at the node planes z_j of uniform layers
     * from the lumped one of SliceBody::line_load_profile() (nodal force
     * over the plane's share of the length): the piecewise linear q whose
     * consistent nodal forces are those forces, M q = f with the mass
     * matrix of linear elements along z. It is exact for a q linear between
     * planes, where the lumped value of an interior plane is off by about
     * h^2 q'' / 12.
     */
    std::vector<std::pair<double, double>>
    consistent_line_load(const std::vector<std::pair<double, double>> &lumped);

    /// PATH as CSV: z, v(z), the local approach u0 - v(z) and the line
    /// load at each node plane, consistent and lumped (@p lumped).
    void
    write_core_profile(const std::string                            &path,
                       const std::vector<std::pair<double, double>> &lumped,
                       const CoreDeflection                         &core,
                       const double                                  u0);
  } // namespace three_d
} // namespace rollnip

#endif
