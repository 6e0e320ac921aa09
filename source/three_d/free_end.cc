#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <rollnip/three_d/free_end.h>

#include <algorithm>
#include <limits>
#include <set>
#include <tuple>

namespace rollnip
{
  namespace three_d
  {
    namespace
    {
      /// Half the layers on either side of plane @p j [mm].
      double
      tributary_length(const std::vector<std::pair<double, double>> &profile,
                       const unsigned int                            j)
      {
        const unsigned int n = profile.size() - 1;
        return ((j < n ? profile[j + 1].first : profile[j].first) -
                (j > 0 ? profile[j - 1].first : profile[j].first)) /
               2.;
      }

      /// Distance from the end at which q first reaches @p fraction of
      /// q(0), coming from the end.
      double
      rise_distance(const std::vector<std::pair<double, double>> &profile,
                    const double                                  fraction)
      {
        const double target = fraction * profile.front().second;
        const double L      = profile.back().first;
        for (unsigned int j = profile.size(); j-- > 0;)
          if (profile[j].second >= target)
            {
              if (j + 1 == profile.size())
                return 0.;
              const auto  &in = profile[j], &out = profile[j + 1];
              const double t = (target - out.second) / (in.second - out.second);
              return L - (out.first + t * (in.first - out.first));
            }
        return L;
      }

      /// The entry with the largest [0] over all processes.
      template <std::size_t n>
      std::array<double, n>
      global_max(const std::array<double, n> &local, const MPI_Comm comm)
      {
        std::array<double, n> best = local;
        for (const auto &other : Utilities::MPI::all_gather(comm, local))
          if (other[0] > best[0])
            best = other;
        return best;
      }

      /// Key, reference position, sigma_rr, tau_rtheta, tau_rz.
      using BondRecord = std::array<double, 7>;

      BondRecord
      record(const double key, const BondStress &s)
      {
        return {{key,
                 s.where[0],
                 s.where[1],
                 s.where[2],
                 s.sigma_rr,
                 s.tau_rtheta,
                 s.tau_rz}};
      }

      BondStress
      stress(const BondRecord &r)
      {
        BondStress s;
        s.where      = Point<dim>(r[1], r[2], r[3]);
        s.sigma_rr   = r[4];
        s.tau_rtheta = r[5];
        s.tau_rz     = r[6];
        return s;
      }
    } // namespace

    EndDecay
    end_decay(const std::vector<std::pair<double, double>> &profile,
              const std::vector<double>                    &widths)
    {
      AssertThrow(widths.empty() || widths.size() == profile.size(),
                  ExcMessage("end_decay: one width per plane"));
      AssertThrow(profile.size() >= 2,
                  ExcMessage("end_decay: the profile needs two planes"));
      EndDecay d;
      d.length        = profile.back().first;
      d.q_far         = profile.front().second;
      d.q_end         = profile.back().second;
      double integral = 0;
      for (unsigned int j = 0; j < profile.size(); ++j)
        integral += profile[j].second *
                    (widths.empty() ? tributary_length(profile, j) : widths[j]);
      d.q_mean         = integral / d.length;
      d.deficit_length = d.q_far > 0 ? d.length - integral / d.q_far : 0.;
      d.rise_95        = d.q_far > 0 ? rise_distance(profile, 0.95) : 0.;
      d.rise_99        = d.q_far > 0 ? rise_distance(profile, 0.99) : 0.;
      return d;
    }

    namespace
    {
      /// The largest u_z on the far face and where (reference point).
      std::array<double, 4>
      end_face_bulge(const SliceBody &body)
      {
        const auto &u     = body.current_solution();
        const auto  owned = body.get_dof_handler().locally_owned_dofs();
        std::array<double, 4> best = {
          {-std::numeric_limits<double>::max(), 0., 0., 0.}};
        for (const auto &[x_dof, node] :
             body.boundary_nodes(SliceIds::far_face))
          if (owned.is_element(node.dofs[2]) && u[node.dofs[2]] > best[0])
            best = {{u[node.dofs[2]], node.X[0], node.X[1], node.X[2]}};
        return global_max(best, body.mpi_communicator());
      }

      /// The x dofs of the nodes on the boundary @p id.
      std::set<types::global_dof_index>
      nodes_on(const SliceBody &body, const types::boundary_id id)
      {
        std::set<types::global_dof_index> nodes;
        for (const auto &[x_dof, node] : body.boundary_nodes(id))
          nodes.insert(x_dof);
        return nodes;
      }

      /// The bond stresses of every locally owned bonded node (Q2: vertex,
      /// edge and face nodes) but those on the far edge (whose reaction
      /// holds the far edge's support too), from its reaction over its
      /// lumped area. On the symmetry planes theta = 0 and z = 0 the
      /// reaction normal to the plane holds the plane's support: the shear
      /// across it is zero by symmetry and is set so.
      std::vector<BondStress>
      bond_stresses(const SliceBody &body)
      {
        const auto &reactions = body.nodal_reactions();
        const auto  owned     = body.get_dof_handler().locally_owned_dofs();
        const TrilinosWrappers::MPI::Vector area =
          body.lumped_areas(SliceIds::inner_arc, false);
        const auto on_far_edge  = nodes_on(body, SliceIds::far_edge);
        const auto on_nip_plane = nodes_on(body, SliceIds::symmetry_edge);
        const auto on_middle    = nodes_on(body, SliceIds::near_face);
        std::vector<BondStress> result;
        for (const auto &[x_dof, node] :
             body.boundary_nodes(SliceIds::inner_arc))
          {
            if (!owned.is_element(x_dof) || on_far_edge.count(x_dof))
              continue;
            const Point<dim> &X = node.X;
            Tensor<1, dim>    t; // on the cover, by the core [MPa]
            for (unsigned int c = 0; c < dim; ++c)
              t[c] = reactions[node.dofs[c]] / area[x_dof];
            const double r = std::hypot(X[0], X[1]);
            // The cover's outer normal at the bond is -e_r.
            BondStress s;
            s.where      = X;
            s.sigma_rr   = -(t[0] * X[0] + t[1] * X[1]) / r;
            s.tau_rtheta = on_nip_plane.count(x_dof)
                             ? 0.
                             : -(-t[0] * X[1] + t[1] * X[0]) / r;
            s.tau_rz     = on_middle.count(x_dof) ? 0. : -t[2];
            result.push_back(s);
          }
        return result;
      }

      /// sigma_rr and tau_rz at the bonded corner averaged with the tent
      /// of length @p s (FreeEnd::corner_sigma_rr) [MPa].
      std::pair<double, double>
      corner_average(const SliceBody &body, const double s)
      {
        const auto &reactions = body.nodal_reactions();
        const auto  owned     = body.get_dof_handler().locally_owned_dofs();
        const TrilinosWrappers::MPI::Vector area =
          body.lumped_areas(SliceIds::inner_arc, false);
        const double L      = body.three_d_parameters().slice_thickness;
        double       sum[3] = {0, 0, 0}; // w a, -w R . e_r, -w R_z
        for (const auto &[x_dof, node] :
             body.boundary_nodes(SliceIds::inner_arc))
          {
            if (!owned.is_element(x_dof))
              continue;
            const Point<dim> &X = node.X;
            const double      r = std::hypot(X[0], X[1]);
            const double      w = std::max(0., 1. - (L - X[2]) / s) *
                             std::max(0., 1. - r * std::atan2(X[1], X[0]) / s);
            if (w == 0)
              continue;
            sum[0] += w * area[x_dof];
            sum[1] -= w *
                      (reactions[node.dofs[0]] * X[0] +
                       reactions[node.dofs[1]] * X[1]) /
                      r;
            sum[2] -= w * reactions[node.dofs[2]];
          }
        const double a = Utilities::MPI::sum(sum[0], body.mpi_communicator());
        return {Utilities::MPI::sum(sum[1], body.mpi_communicator()) / a,
                Utilities::MPI::sum(sum[2], body.mpi_communicator()) / a};
      }
    } // namespace

    FreeEnd
    evaluate_free_end(const SliceBody &body, const double u0)
    {
      FreeEnd result;
      result.u0 = u0;
      result.decay =
        end_decay(body.line_load_profile(), body.line_load_widths());
      const MPI_Comm              comm  = body.mpi_communicator();
      const std::array<double, 4> bulge = end_face_bulge(body);
      result.bulge                      = bulge[0];
      result.bulge_at = Point<dim>(bulge[1], bulge[2], bulge[3]);

      const auto  &g = body.parameters_of_mesh().geometry;
      const double h = g.outer_radius - g.inner_radius;
      for (unsigned int k = 0; k < 2; ++k)
        std::tie(result.corner_sigma_rr[k], result.corner_tau_rz[k]) =
          corner_average(body, (k + 1) * h / 2);

      const std::vector<double> z      = body.node_planes();
      const double              lowest = -std::numeric_limits<double>::max();
      BondRecord                shear[2], compression[2], tension[2];
      for (unsigned int k = 0; k < 2; ++k)
        shear[k] = compression[k] = tension[k] = {{lowest, 0, 0, 0, 0, 0, 0}};
      std::vector<double> max_rz(z.size(), 0.), max_shear(z.size(), 0.),
        max_rr(z.size(), lowest), min_rr(z.size(), -lowest);
      for (const BondStress &s : bond_stresses(body))
        {
          const unsigned int j = nearest_plane(z, s.where[2]);
          // k = 0: the whole bond; k = 1: the middle plane z = 0 too (the
          // first station holds the nodes of about a cell).
          const bool middle = body.has_node_planes()
                                ? j == 0
                                : std::abs(s.where[2]) < 1e-9 * z.back();
          for (unsigned int k = 0; k < (middle ? 2u : 1u); ++k)
            {
              if (s.shear() > shear[k][0])
                shear[k] = record(s.shear(), s);
              if (-s.sigma_rr > compression[k][0])
                compression[k] = record(-s.sigma_rr, s);
              if (s.sigma_rr > tension[k][0])
                tension[k] = record(s.sigma_rr, s);
            }
          max_rz[j]    = std::max(max_rz[j], std::abs(s.tau_rz));
          max_shear[j] = std::max(max_shear[j], s.shear());
          max_rr[j]    = std::max(max_rr[j], s.sigma_rr);
          min_rr[j]    = std::min(min_rr[j], s.sigma_rr);
        }
      result.shear_peak         = stress(global_max(shear[0], comm));
      result.shear_middle       = stress(global_max(shear[1], comm));
      result.compression_peak   = stress(global_max(compression[0], comm));
      result.compression_middle = stress(global_max(compression[1], comm));
      result.tension_peak       = stress(global_max(tension[0], comm));
      result.tension_middle     = stress(global_max(tension[1], comm));
      const auto reduce = [&](std::vector<double> &v, const bool maximum) {
        const std::vector<double> local = v;
        if (maximum)
          Utilities::MPI::max(local, comm, v);
        else
          Utilities::MPI::min(local, comm, v);
      };
      reduce(max_rz, true);
      reduce(max_shear, true);
      reduce(max_rr, true);
      reduce(min_rr, false);
      for (unsigned int j = 0; j < z.size(); ++j)
        result.bond_along_axis.push_back(
          {{z[j], max_rz[j], max_shear[j], max_rr[j], min_rr[j]}});
      return result;
    }
  } // namespace three_d
} // namespace rollnip
