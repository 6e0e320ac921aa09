#ifndef rollnip_postprocess_surface_data_h
#define rollnip_postprocess_surface_data_h

#include <rollnip/global.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rollnip
{
  /// One node of the outer surface r = R0 (all lengths mm, stresses MPa).
  struct OuterSurfacePoint
  {
    double theta; ///< reference angle [rad]
    double X, Y;  ///< reference position
    double x, y;  ///< deformed position
    double u_r, u_theta;
    double applied_pressure; ///< the load f(theta) times the load fraction
    /// -sigma_nn on the deformed surface, from the adjacent cells' stress.
    double normal_pressure;
    double shear_traction; ///< sigma_nt from the adjacent cells' stress
  };

  /// One node of the bond surface r = R1 [MPa]. sigma_rr and sigma_rtheta
  /// are the traction on the bond (there n = e_r: the core does not move),
  /// recovered from the nodal reactions of the core; the hoop and axial
  /// stresses are the adjacent cells' own.
  struct BondSurfacePoint
  {
    double theta; ///< reference angle [rad]
    double sigma_rr, sigma_rtheta, sigma_thetatheta, sigma_zz;
  };

  /// One node of an interface between two layers [MPa]. The traction
  /// sigma n (n the deformed interface's normal pointing away from the
  /// axis, s its counter-clockwise tangent) is continuous across a bonded
  /// interface and recovered from the inner layer's nodal forces; the
  /// hoop stress (polar, at the deformed point) jumps and is given on each
  /// side from its cells.
  struct InterfacePoint
  {
    double theta;    ///< reference angle [rad]
    double sigma_nn; ///< n . sigma n
    double sigma_nt; ///< s . sigma n
    double sigma_thetatheta_inner, sigma_thetatheta_outer;
  };

  /// Extremes of the bond-surface stresses [MPa]; all 0 for no points
  /// (ranks other than 0 hold none).
  struct BondExtremes
  {
    double sigma_rr_min = 0, sigma_rr_max = 0;
    double sigma_rtheta_max_abs = 0;
  };

  inline BondExtremes
  bond_extremes(const std::vector<BondSurfacePoint> &bond)
  {
    BondExtremes e;
    if (bond.empty())
      return e;
    e.sigma_rr_min = e.sigma_rr_max = bond.front().sigma_rr;
    for (const auto &p : bond)
      {
        e.sigma_rr_min = std::min(e.sigma_rr_min, p.sigma_rr);
        e.sigma_rr_max = std::max(e.sigma_rr_max, p.sigma_rr);
        e.sigma_rtheta_max_abs =
          std::max(e.sigma_rtheta_max_abs, std::abs(p.sigma_rtheta));
      }
    return e;
  }

  /// The two-sided load P [N/mm] from the normal Cauchy traction -sigma_nn
  /// on the deformed outer surface (the check of the applied P): on the
  /// outer arc, counter-clockwise, n ds = (dx2, -dx1), so P is twice the
  /// integral of -sigma_nn dx2 (0 for no points).
  inline double
  load_from_traction(const std::vector<OuterSurfacePoint> &outer)
  {
    double P = 0;
    for (unsigned int i = 1; i < outer.size(); ++i)
      P += (outer[i].normal_pressure + outer[i - 1].normal_pressure) *
           (outer[i].y - outer[i - 1].y);
    return P; // 2 * (1/2 mean) * dx2
  }

  /// Cell-wide extremes over the whole cover.
  struct FieldExtremes
  {
    double min_J                 = 1;
    double max_abs_J_minus_1     = 0;
    double max_principal_stretch = 1;
    double min_principal_stretch = 1;
    double max_von_mises         = 0; ///< plane-strain von Mises [MPa]
    double min_sigma_rr = 0, max_sigma_rr = 0;
    double max_abs_sigma_rtheta = 0;
  };

  /// Everything postprocess.cc extracts of one state, gathered on rank 0
  /// (other ranks hold empty vectors but the same extremes).
  struct SurfaceData
  {
    std::vector<OuterSurfacePoint> outer;
    std::vector<BondSurfacePoint>  bond;
    /// The interfaces of a layered cover, from the core out.
    std::vector<std::vector<InterfacePoint>> interfaces;
    FieldExtremes                            extremes;
  };
} // namespace rollnip

#endif
