#ifndef rollnip_geometry_nip_fitted_mesh_h
#define rollnip_geometry_nip_fitted_mesh_h

#include <deal.II/base/point.h>

#include <deal.II/distributed/tria.h>

#include <rollnip/global.h>
#include <rollnip/parameters.h>

#include <vector>

namespace rollnip
{
  /// The worst cells of a mesh (doc/accuracy.md, "The nip-fitted mesh").
  struct MeshQuality
  {
    /// min over cells of (smallest corner Jacobian / largest); 1 for a
    /// parallelogram, 0 for a degenerate cell.
    double min_jacobian_ratio = 1;
    /// max over cells of the ratio of the largest to the smallest singular
    /// value of the Jacobian (deal.II's aspect ratio).
    double max_aspect_ratio = 1;
  };

  /// The quality of the locally owned cells of @p triangulation, reduced
  /// over all processes.
  MeshQuality
  mesh_quality(const parallel::distributed::Triangulation<dim> &triangulation);

  /**
   * The builtin sector annulus whose vertices follow the nip (Mesh/Nip
   * fitting): for every half nip angle theta0 the contact edge is a
   * surface vertex. The mesh is built once, in logical coordinates (r, s)
   * with s in [0, 1] along the sector, and refined there; fit() then maps
   * each vertex to the angle theta(s; theta0):
   *  - the first Mesh/Nip cells coarse cells cover [0, theta0], their
   *    widths shrinking geometrically towards the edge by Mesh/Nip grading
   *    for a nip small against the cover (the pressure falls like a square
   *    root there), more evenly as the nip reaches the cover's size;
   *  - the remaining cells cover [theta0, sector angle], the first as wide
   *    as the last nip cell, growing geometrically to the far edge;
   *  - fine vertices are interpolated linearly in s between the coarse
   *    ones, which is where refinement in the angle would put them;
   *  - every radius keeps the same angles, so the cells below the surface
   *    follow the surface cells and stay (r, theta) rectangles;
   *  - the radial cells thin towards the surface where the cells under the
   *    nip would be too thick for their width: up to square for a nip
   *    small against the cover, up to 4 times for a nip of its size.
   * Only vertex positions change with theta0: the connectivity, the DoF
   * numbering and the sparsity pattern stay, so a factorisation's analysis
   * and the previous nip's state carry over. The map is smooth in theta0,
   * so P(theta0) and u0(theta0) are too.
   */
  class NipFittedMesh
  {
  public:
    explicit NipFittedMesh(const Parameters::AllParameters &parameters);

    /// Builds the refined mesh into @p triangulation (empty on entry),
    /// with boundary ids and the polar manifold, fitted to @p theta0.
    void
    build(parallel::distributed::Triangulation<dim> &triangulation,
          const double                               theta0);

    /// Moves the vertices so that the contact edge lies at @p theta0 [rad].
    void
    fit(parallel::distributed::Triangulation<dim> &triangulation,
        const double                               theta0) const;

    /// The angles [rad] of the coarse circumferential vertices, from 0 to
    /// the sector angle, for the nip @p theta0.
    std::vector<double>
    coarse_angles(const double theta0) const;

    /// The largest theta0 [rad] the mesh is fitted to: half the sector,
    /// so that the free surface beyond the nip keeps room to relax.
    double
    max_nip_angle() const
    {
      return 0.5 * sector_angle;
    }

  private:
    /// The radii [mm] of the coarse radial vertices for the nip @p theta0:
    /// the outermost cell about as thick as a coarse nip cell is wide.
    std::vector<double>
    coarse_radii(const double theta0) const;

    /// How much the nip @p theta0 [rad] is of the cover's size: 0 for a
    /// nip small against the cover thickness (a << h, Hertz-like), towards
    /// 1 once a is several tenths of h; smooth in theta0. It sets how much
    /// the nip cells are edge-graded and the surface cells thinned.
    double
    cover_weight(const double theta0) const;

    /// The coordinate of the logical @p s in [0, 1] for the coarse
    /// vertex coordinates @p T, linear between them.
    static double
    interpolate(const std::vector<double> &T, const double s);

    const double       sector_angle;
    const unsigned int n_cells;     ///< coarse cells along the sector
    const unsigned int n_nip_cells; ///< of which in [0, theta0]
    const double       nip_grading; ///< first over last nip cell width
    const Parameters::AllParameters &parameters;
    /// The logical (radial, circumferential) coordinates in [0, 1]^2 of
    /// every vertex, by vertex index.
    std::vector<Point<dim>> logical;
  };
} // namespace rollnip

#endif
