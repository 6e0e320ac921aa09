#ifndef rollnip_rolling_annulus_mesh_h
#define rollnip_rolling_annulus_mesh_h

#include <deal.II/grid/tria.h>

#include <rollnip/global.h>

#include <vector>

namespace rollnip
{
  /// The layout of the whole-circle cover mesh of the full steady rolling
  /// (doc/rolling.md, section 7).
  struct AnnulusLayout
  {
    /// Radii of the layer boundaries, from the core R1 to the surface R0
    /// [mm] (layers + 1 entries).
    std::vector<double> layer_radii;
    /// Half-width of the uniformly fine zone about the nip [rad].
    double fine_half_angle = 0.2;
    /// Cells across the fine zone (an even number keeps theta = 0 a node).
    unsigned int fine_cells = 60;
    /// Radial cells of the whole cover (at least one per layer).
    unsigned int radial_cells = 12;
    /// Outermost over innermost radial cell of each layer (< 1: thinner at
    /// the surface).
    double radial_grading = 0.5;
    /// Angular growth factor of the cells beyond the fine zone. The
    /// dissipation integrated along the circles misses about 7 (growth - 1)
    /// per cent of the loss in the growing cells while the contact moment
    /// hardly moves (doc/rolling.md, section 7): keep it near 1, and bring
    /// it towards 1 when refining the fine zone.
    double growth = 1.05;
  };

  /**
   * The whole annulus R1 < r < R0 as a structured mesh of rings: node
   * angles theta_i in [-pi, pi), uniform in the fine zone about theta = 0
   * and growing geometrically beyond it, symmetric about theta = 0; node
   * radii per layer. Cell (ring j, sector i) is cell number j * n + i, its
   * unit x runs outward and unit y along increasing theta, its material id
   * is its layer. The ring closes on itself (no symmetry edge); the bond
   * and the surface carry the builtin mesh's boundary ids (inner_arc,
   * outer_arc).
   */
  class AnnulusMesh
  {
  public:
    explicit AnnulusMesh(const AnnulusLayout &layout);

    /// Builds the coarse (unrefined) triangulation into @p tria.
    void
    create(Triangulation<dim> &tria) const;

    /// Node angles [rad], increasing, the first -pi.
    const std::vector<double> &
    angles() const
    {
      return node_angles;
    }
    /// Node radii [mm], increasing.
    const std::vector<double> &
    radii() const
    {
      return node_radii;
    }
    /// The layer of ring @p j.
    unsigned int
    ring_layer(const unsigned int j) const
    {
      return layer_of_ring[j];
    }
    unsigned int
    n_sectors() const
    {
      return node_angles.size();
    }
    unsigned int
    n_rings() const
    {
      return node_radii.size() - 1;
    }

  private:
    std::vector<double>       node_angles, node_radii;
    std::vector<unsigned int> layer_of_ring;
  };
} // namespace rollnip

#endif
