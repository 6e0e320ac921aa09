#include <deal.II/base/mpi.h>

#include <rollnip/app/cross_section_law.h>
#include <rollnip/app/face_run.h>
#include <rollnip/app/nip_report.h>
#include <rollnip/face/crown.h>
#include <rollnip/face/face_solver.h>
#include <rollnip/output/atomic_file.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

namespace rollnip
{
  namespace
  {
    using namespace Face;

    /// The face's numbers at one load.
    struct FaceFigures
    {
      double q_centre, q_end, b_centre, b_end, contact_length;
    };

    /// The foundation of Face/Foundation and, for the cross-section's, its
    /// samples.
    struct Foundation
    {
      std::unique_ptr<FoundationLaw> law;
      LawSamples                     samples;
    };

    double
    total_force(const Parameters::Face &face, const BeamSection &roll)
    {
      if (face.loading == Parameters::FaceLoading::mean_line_load)
        return face.mean_line_load * face.face_length;
      // The roll on top: its weight adds to the cylinders' forces.
      return 2 * face.bearing_force +
             (face.own_weight ? roll.weight * face.bearing_distance : 0.);
    }

    Foundation
    make_foundation(const Parameters::AllParameters &parameters,
                    const Parameters::Face          &face,
                    const double                     line_load,
                    MPI_Comm                         communicator)
    {
      Foundation f;
      if (face.foundation == Parameters::FaceFoundation::linear)
        {
          f.law = std::make_unique<LinearFoundation>(face.foundation_stiffness);
          return f;
        }
      f.samples = cross_section_law(parameters,
                                    face,
                                    law_approaches(parameters, face, line_load),
                                    communicator);
      f.law     = std::make_unique<SampledLaw>(f.samples.approach,
                                           f.samples.line_load,
                                           f.samples.half_width,
                                           f.samples.peak_pressure);
      return f;
    }

    /// The crown of one roll; the ideal one is its deflection under the
    /// design load (the face's when Design line load = 0).
    Crown
    roll_crown(const Parameters::FaceCrown &crown,
               const FaceModel             &model,
               const BeamSection           &section,
               const double                 beam_load)
    {
      if (crown.shape != Parameters::CrownShape::ideal)
        return make_crown(crown, model.face_length);
      const double   design = crown.design_line_load > 0
                                ? crown.design_line_load
                                : model.total_force / model.face_length;
      const FaceMesh mesh(model.face_length,
                          model.bearing_distance,
                          model.elements);
      return ideal_crown(
        mesh,
        section,
        simply_supported_deflection(mesh, section, design, beam_load),
        model.face_length);
    }

    /// The nip half-width b [mm] where the law carries @p line_load: the
    /// length that scales the non-local foundation.
    double
    mean_half_width(const FoundationLaw &law, const double line_load)
    {
      double lo = 0, hi = law.largest_approach();
      for (unsigned int i = 0; i < 200; ++i)
        {
          const double mid                      = (lo + hi) / 2;
          (law.load(mid) < line_load ? lo : hi) = mid;
        }
      return law.half_width((lo + hi) / 2);
    }

    FaceModel
    make_model(const Parameters::Face &face,
               const FoundationLaw    &law,
               const double            force)
    {
      FaceModel m;
      m.face_length      = face.face_length;
      m.bearing_distance = face.bearing_distance;
      m.elements         = face.elements;
      m.roll             = tube_section(face.roll_core, face.shear_deformation);
      m.mate_is_beam     = face.mate_is_beam;
      m.mate             = tube_section(face.mate_core, face.shear_deformation);
      if (face.own_weight)
        {
          m.roll_beam_load = -m.roll.weight;
          m.mate_beam_load = m.mate.weight;
        }
      m.total_force = force;
      m.law         = &law;
      const Crown a = roll_crown(face.roll_crown, m, m.roll, m.roll_beam_load);
      const Crown b =
        m.mate_is_beam
          ? roll_crown(face.mate_crown, m, m.mate, m.mate_beam_load)
          : make_crown(face.mate_crown, m.face_length);
      m.crown = [a, b](const double y) { return a(y) + b(y); };
      if (face.nonlocal)
        m.nonlocal_length =
          face.nonlocal_factor * mean_half_width(law, force / m.face_length);
      return m;
    }

    FaceFigures
    figures(const FaceSolution &s)
    {
      const FaceModel &m = *s.model;
      const double     L = m.face_length;
      FaceFigures      f;
      f.q_centre = s.line_load(0);
      f.q_end    = (s.line_load(-L / 2) + s.line_load(L / 2)) / 2;
      f.b_centre = 2 * m.law->half_width(s.approach_at(0));
      f.b_end    = (m.law->half_width(s.approach_at(-L / 2)) +
                 m.law->half_width(s.approach_at(L / 2)));
      // The length in contact, to a thousandth of an element.
      const unsigned int n = 1000 * m.elements;
      f.contact_length     = 0;
      for (unsigned int i = 0; i < n; ++i)
        if (s.approach_at(-L / 2 + (i + 0.5) * L / n) > 0)
          f.contact_length += L / n;
      return f;
    }

    /// The ratio a / b, infinity when b = 0.
    double
    ratio(const double a, const double b)
    {
      return b > 0 ? a / b : std::numeric_limits<double>::infinity();
    }

    /// Refuses a face that needs approaches beyond the sampled law.
    void
    check_law_range(const FaceSolution &s)
    {
      const FaceModel &m       = *s.model;
      double           largest = 0;
      for (unsigned int i = s.mesh.first_face_node; i <= s.mesh.last_face_node;
           ++i)
        largest = std::max(largest, s.approach_at(s.mesh.y[i]));
      AssertThrow(largest <= m.law->largest_approach() * (1 + 1e-9),
                  ExcMessage("Face: the face needs approaches up to " +
                             std::to_string(largest) +
                             " mm, beyond the law's " +
                             std::to_string(m.law->largest_approach()) +
                             " mm: raise Face/Law maximum approach"));
    }

    /// face.csv: the nip at every face node.
    void
    write_face_csv(const FaceSolution     &s,
                   const Parameters::Face &face,
                   const std::string      &file)
    {
      const FoundationLaw &law = *s.model->law;
      write_atomically(file, [&](std::ostream &out) {
        out << "y_mm,line_load_N_per_mm,nip_width_2b_mm,approach_mm,"
               "peak_pressure_MPa,mean_pressure_MPa,dwell_ms,"
               "roll_deflection_mm,mate_deflection_mm,crown_radius_mm\n"
            << std::setprecision(10);
        for (unsigned int i = s.mesh.first_face_node;
             i <= s.mesh.last_face_node;
             ++i)
          {
            const double y = s.mesh.y[i], d = s.approach_at(y);
            const double q = s.line_load(y), w = 2 * law.half_width(d);
            out << y << ',' << q << ',' << w << ',' << d << ','
                << law.peak_pressure(d) << ',' << (w > 0 ? q / w : 0.) << ','
                << (face.surface_speed > 0 && w > 0
                      ? dwell_time_ms(w, face.surface_speed)
                      : 0.)
                << ',' << s.roll_deflection(y) << ',' << s.mate_deflection(y)
                << ',' << s.crown(y) << '\n';
          }
      });
    }

    /// The ideal crown at the face's load, as a change of the diameter of
    /// the roll: both beams' deflection at the centre over the ends.
    double
    ideal_crown_on_diameter(const FaceModel &m)
    {
      const FaceMesh mesh(m.face_length, m.bearing_distance, m.elements);
      const double   q   = m.total_force / m.face_length;
      double         c   = 0;
      const auto     add = [&](const BeamSection &s, const double load) {
        const Eigen::VectorXd w = simply_supported_deflection(mesh, s, q, load);
        c += deflection_at(mesh, s, w, 0) -
             deflection_at(mesh, s, w, m.face_length / 2);
      };
      add(m.roll, m.roll_beam_load);
      if (m.mate_is_beam)
        add(m.mate, m.mate_beam_load);
      return 2 * c;
    }

    void
    write_summary(const FaceSolution &s,
                  const Foundation   &foundation,
                  const double        seconds,
                  const std::string  &file)
    {
      const FaceModel  &m = *s.model;
      const FaceFigures f = figures(s);
      const double      L = m.face_length;
      write_atomically(file, [&](std::ostream &out) {
        out << std::setprecision(10) << "total_force_N = " << m.total_force
            << '\n'
            << "mean_line_load_N_per_mm = " << m.total_force / L << '\n'
            << "bearing_approach_mm = " << s.approach << '\n'
            << "centre_line_load_N_per_mm = " << f.q_centre << '\n'
            << "end_line_load_N_per_mm = " << f.q_end << '\n'
            << "line_load_centre_over_end = " << ratio(f.q_centre, f.q_end)
            << '\n'
            << "centre_nip_width_mm = " << f.b_centre << '\n'
            << "end_nip_width_mm = " << f.b_end << '\n'
            << "nip_width_centre_over_end = " << ratio(f.b_centre, f.b_end)
            << '\n'
            << "contact_length_mm = " << f.contact_length << '\n'
            << "roll_centre_deflection_mm = " << s.roll_deflection(0) << '\n'
            << "mate_centre_deflection_mm = " << s.mate_deflection(0) << '\n'
            << "roll_bearing_force_left_N = " << s.roll_bearings[0] << '\n'
            << "roll_bearing_force_right_N = " << s.roll_bearings[1] << '\n'
            << "mate_bearing_force_left_N = " << s.mate_bearings[0] << '\n'
            << "mate_bearing_force_right_N = " << s.mate_bearings[1] << '\n'
            << "ideal_crown_on_diameter_mm = " << ideal_crown_on_diameter(m)
            << '\n'
            << "nonlocal_length_mm = " << m.nonlocal_length << '\n'
            << "elements = " << m.elements << '\n'
            << "newton_iterations = " << s.iterations << '\n'
            << "face_solve_seconds = " << seconds << '\n';
        if (!foundation.samples.file.empty())
          out << "law_file = " << foundation.samples.file << '\n'
              << "law_samples = " << foundation.samples.approach.size() << '\n'
              << "law_from_cache = "
              << (foundation.samples.from_cache ? "yes" : "no") << '\n'
              << "law_sweep_seconds = " << foundation.samples.sweep_seconds
              << '\n'
              << "law_largest_approach_mm = "
              << foundation.samples.approach.back() << '\n';
      });
    }

    /// off_design.csv: a crowned face at 0.5 to 1.5 times its load.
    void
    write_off_design(const FaceModel &model, const std::string &file)
    {
      std::ostringstream out;
      out << "load_factor,mean_line_load_N_per_mm,centre_line_load_N_per_mm,"
             "end_line_load_N_per_mm,line_load_centre_over_end,"
             "centre_nip_width_mm,end_nip_width_mm,nip_width_centre_over_end"
             "\n"
          << std::setprecision(10);
      for (const double factor : {0.5, 0.75, 1., 1.25, 1.5})
        {
          FaceModel m          = model;
          m.total_force        = factor * model.total_force;
          const FaceSolution s = solve_face(m);
          check_law_range(s);
          const FaceFigures f = figures(s);
          out << factor << ',' << m.total_force / m.face_length << ','
              << f.q_centre << ',' << f.q_end << ','
              << ratio(f.q_centre, f.q_end) << ',' << f.b_centre << ','
              << f.b_end << ',' << ratio(f.b_centre, f.b_end) << '\n';
        }
      write_atomically(file, [&](std::ostream &o) { o << out.str(); });
    }

    void
    print_face(const FaceSolution &s, const Foundation &foundation)
    {
      const FaceFigures  f = figures(s);
      std::ostringstream out;
      out << std::setprecision(6);
      out << "Face: " << s.model->face_length << " mm, " << s.model->elements
          << " elements, nip force " << s.model->total_force << " N, ";
      if (foundation.samples.file.empty())
        out << "linear foundation";
      else
        out << "law of " << foundation.samples.approach.size()
            << " approaches up to " << foundation.samples.approach.back()
            << " mm "
            << (foundation.samples.from_cache
                  ? "read from "
                  : "swept in " +
                      std::to_string(foundation.samples.sweep_seconds) +
                      " s into ")
            << foundation.samples.file;
      out << "\n  line load centre " << f.q_centre << " N/mm, end " << f.q_end
          << " N/mm (ratio " << ratio(f.q_centre, f.q_end)
          << ")\n  nip width 2b centre " << f.b_centre << " mm, end " << f.b_end
          << " mm; in contact over " << f.contact_length
          << " mm\n  bearing approach " << s.approach
          << " mm, roll deflection at the centre " << s.roll_deflection(0)
          << " mm" << std::endl;
      std::cout << out.str();
    }
  } // namespace

  int
  run_face(const Parameters::AllParameters &parameters,
           const Parameters::Face          &face,
           MPI_Comm                         communicator)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    const std::string &dir = parameters.output.directory;
    const double       force =
      total_force(face, tube_section(face.roll_core, face.shear_deformation));
    double design = force / face.face_length;
    for (const auto *crown : {&face.roll_crown, &face.mate_crown})
      design = std::max(design, crown->design_line_load);
    const Foundation foundation =
      make_foundation(parameters, face, design, communicator);
    const FaceModel    model    = make_model(face, *foundation.law, force);
    const auto         start    = std::chrono::steady_clock::now();
    const FaceSolution solution = solve_face(model);
    const double       seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    check_law_range(solution);
    if (root)
      {
        make_directories(dir);
        write_face_csv(solution, face, dir + "/face.csv");
        write_summary(solution, foundation, seconds, dir + "/summary.txt");
        if (face.roll_crown.shape != Parameters::CrownShape::none ||
            face.mate_crown.shape != Parameters::CrownShape::none)
          write_off_design(model, dir + "/off_design.csv");
        print_face(solution, foundation);
      }
    return 0;
  }
} // namespace rollnip
