#ifndef rollnip_three_d_free_end_h
#define rollnip_three_d_free_end_h

#include <deal.II/base/point.h>

#include <rollnip/three_d/axial_grading.h>
#include <rollnip/three_d/slice_body.h>

#include <array>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rollnip
{
  namespace three_d
  {
    /**
     * How the line load q(z) of SliceBody::line_load_profile() (one value
     * per plane of surface nodes, z = 0 the middle of the face, z = L the
     * free end) falls towards the end. q at the end plane is not zero on
     * a discrete mesh (the end node carries the load of half a layer), so
     * the decay is measured by integrals and crossings, not by q(L).
     */
    struct EndDecay
    {
      double length = 0; ///< L [mm]
      double q_far  = 0; ///< q(0), the middle of the face [N/mm]
      double q_end  = 0; ///< q(L), the end plane [N/mm]
      /// The integral of q over the face divided by L: the nodal forces
      /// summed, i.e. the P of the run [N/mm].
      double q_mean = 0;
      /// l = int_0^L (1 - q / q_far) dz [mm]: the load the end loses,
      /// in lengths of full line load. The non-local face model
      /// q - l^2 q'' = P_2D with q(L) = 0 (doc/face.md) loses exactly
      /// q_far l, so this is the l that model needs.
      double deficit_length = 0;
      /// Distance from the end at which q first reaches 95 % and 99 % of
      /// q_far, coming from the end (linear between node planes) [mm];
      /// L if it never does.
      double rise_95 = 0, rise_99 = 0;
    };

    /// The decay of the profile @p profile ((z [mm], q [N/mm]) from z = 0
    /// to z = L, each q the nodal force over the plane's share @p widths
    /// of the length (SliceBody::line_load_widths()); empty @p widths:
    /// half the distances to the neighbouring planes (Q1)).
    EndDecay
    end_decay(const std::vector<std::pair<double, double>> &profile,
              const std::vector<double> &widths = std::vector<double>());

    /// The bond stresses at one bonded node [MPa], from its reaction over
    /// its lumped area on the core (the bonded surface does not move, so
    /// the nominal traction is the Cauchy one): sigma_rr (> 0: tension,
    /// pulls the cover off the core), tau_rtheta and tau_rz.
    struct BondStress
    {
      Point<dim> where; ///< reference position [mm]
      double     sigma_rr = 0, tau_rtheta = 0, tau_rz = 0;
      double
      shear() const
      {
        return std::hypot(tau_rtheta, tau_rz);
      }
    };

    /// What a free cover end does, for one converged approach.
    struct FreeEnd
    {
      double   u0 = 0; ///< [mm]
      EndDecay decay;
      /// The end-face bulge: the largest axial displacement u_z on z = L
      /// [mm] and the reference point where it is.
      double     bulge = 0;
      Point<dim> bulge_at;
      /// The largest bond shear over the whole bond and over the plane
      /// z = 0 (the plane-strain middle), the most compressive and the
      /// most tensile sigma_rr over the whole bond and over z = 0.
      BondStress shear_peak, shear_middle;
      BondStress compression_peak, compression_middle;
      BondStress tension_peak, tension_middle;
      /// The bond traction at the bonded corner (r = R1, theta = 0, z = L)
      /// averaged with the tent weight w = (1 - (L - z) / s)+ (1 - R1
      /// theta / s)+ for s = h / 2 and s = h (h = R2 - R1): sigma_rr and
      /// tau_rz [MPa]. The weighted sum of the consistent nodal reactions
      /// over that of the lumped areas is the exact w-weighted mean of the
      /// discrete traction, so it converges where the nodal peak at the
      /// (singular) corner grows with refinement.
      std::array<double, 2> corner_sigma_rr = {{0, 0}};
      std::array<double, 2> corner_tau_rz   = {{0, 0}};
      /// Per plane of bonded nodes (last approach): z [mm], the largest
      /// |tau_rz|, bond shear, sigma_rr and the smallest sigma_rr [MPa].
      std::vector<std::array<double, 5>> bond_along_axis;
    };

    /// The free-end measures of the current state of @p body at @p u0.
    FreeEnd
    evaluate_free_end(const SliceBody &body, const double u0);

    /// free_end.csv: one row per approach, with a header and units.
    void
    write_free_end_table(const std::string          &path,
                         const std::vector<FreeEnd> &rows);

    /// bond_traction_along_axis.csv of @p result.
    void
    write_bond_along_axis(const std::string &path, const FreeEnd &result);

    /// 'key = value' lines of @p result for summary.txt (units in keys).
    void
    write_free_end_summary(std::ostream &out, const FreeEnd &result);
  } // namespace three_d
} // namespace rollnip

#endif
