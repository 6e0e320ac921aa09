#include <deal.II/base/mpi.h>

#include <rollnip/geometry/angles.h>
#include <rollnip/loading/applied_load.h>
#include <rollnip/loading/pressure_load.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace rollnip
{
  namespace
  {
    constexpr double deg = 180. / numbers::PI;

    /// The loaded zone as the mesh sees it: the surface cells it spans
    /// (each counted by the part of it where the pressure is non-zero),
    /// their mean angular size, the quadrature points that see it and the
    /// resultant [N/mm].
    struct DiscreteLoad
    {
      double         cells_spanned = 0;
      double         cell_angle    = 0; ///< [rad], of the cells spanned
      double         mean_angle    = 0; ///< [rad], of all loaded faces
      double         n_points_seen = 0;
      Tensor<1, dim> resultant;
    };

    /// Samples per surface cell for the part of it under pressure.
    constexpr unsigned int samples_per_cell = 64;

    DiscreteLoad
    measure(const RollBody &body)
    {
      const FollowerLoad &load = body.load();
      const auto fe_face = load.make_face_values(body.mapping(), body.fe());
      std::vector<Tensor<2, dim>> grad_u;
      DiscreteLoad                d;
      double                      angle_sum = 0, all_angles = 0, n_faces = 0;
      for (const auto &cell : body.dofs().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            for (const auto f : cell->face_indices())
              if (load.acts_on(cell, f))
                {
                  const double a = reference_angle(cell->face(f)->vertex(0));
                  const double b = reference_angle(cell->face(f)->vertex(1));
                  unsigned int loaded = 0;
                  for (unsigned int i = 0; i < samples_per_cell; ++i)
                    loaded +=
                      load.value(a + (b - a) * (i + 0.5) / samples_per_cell,
                                 1.) != 0;
                  const double part = double(loaded) / samples_per_cell;
                  d.cells_spanned += part;
                  all_angles += std::abs(b - a);
                  ++n_faces;
                  angle_sum += part * std::abs(b - a);
                }
            load.for_each_point(cell,
                                *fe_face,
                                body.solution(),
                                grad_u,
                                [&](const unsigned int,
                                    const double theta,
                                    const Tensor<2, dim> &,
                                    const Tensor<1, dim> &N,
                                    const double          JxW) {
                                  const double p = load.value(theta, 1.);
                                  d.n_points_seen += p != 0;
                                  d.resultant -= p * N * JxW;
                                });
          }
      const MPI_Comm comm = body.communicator();
      d.cells_spanned     = Utilities::MPI::sum(d.cells_spanned, comm);
      d.n_points_seen     = Utilities::MPI::sum(d.n_points_seen, comm);
      angle_sum           = Utilities::MPI::sum(angle_sum, comm);
      all_angles          = Utilities::MPI::sum(all_angles, comm);
      n_faces             = Utilities::MPI::sum(n_faces, comm);
      d.mean_angle        = n_faces > 0 ? all_angles / n_faces : 0;
      for (unsigned int c = 0; c < dim; ++c)
        d.resultant[c] = Utilities::MPI::sum(d.resultant[c], comm);
      d.cell_angle =
        d.cells_spanned > 0 ? angle_sum / d.cells_spanned : d.mean_angle;
      return d;
    }

    /// The entry to blame: Load/theta0 if the expression uses it.
    std::string
    culprit(const Parameters::Load &load)
    {
      std::ostringstream s;
      s << std::setprecision(4);
      if (load.pressure_function.find("theta0") != std::string::npos)
        s << "Load/theta0 = " << load.theta0 * deg << " deg";
      else
        s << "Load/Pressure function";
      return s.str();
    }
  } // namespace

  std::string
  check_applied_load(const RollBody &body)
  {
    const auto        &parameters = body.scene();
    const PressureLoad pressure(parameters.load, parameters.geometry);
    const double       zone = pressure.loaded_angle();
    const DiscreteLoad d    = measure(body);
    std::ostringstream s;
    s << std::setprecision(4);
    if (zone > 0 && (d.n_points_seen == 0 || d.cells_spanned < 2))
      {
        s << culprit(parameters.load) << " loads " << zone * deg
          << " deg of the arc, narrower than 2 surface cells ("
          << d.cell_angle * deg << " deg at this mesh; " << d.n_points_seen
          << " quadrature point(s) see the load)"
          << ": refine the mesh to cells below " << zone / 2 * deg
          << " deg there, or check the unit (angles in degrees; radians?)";
        AssertThrow(false, ExcMessage(s.str()));
      }
    s << pressure.describe() << "; resultant of the discrete load on the "
      << "undeformed arc (" << d.resultant[0] << ", " << d.resultant[1]
      << ") N/mm";
    return s.str();
  }
} // namespace rollnip
