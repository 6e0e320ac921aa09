#include <deal.II/base/mpi.h>

#include <rollnip/app/cross_section_law.h>
#include <rollnip/app/nip_study.h>
#include <rollnip/contact/nip_estimates.h>
#include <rollnip/output/atomic_file.h>
#include <rollnip/scene/scene_description.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace rollnip
{
  namespace Face
  {
    namespace
    {
      /// FNV-1a: a hash that is the same on every platform and build.
      std::uint64_t
      fnv1a(const std::string &text)
      {
        std::uint64_t h = 14695981039346656037ull;
        for (const unsigned char c : text)
          {
            h ^= c;
            h *= 1099511628211ull;
          }
        return h;
      }

      template <typename T>
      void
      put(std::ostream &out, const std::string &name, const T &value)
      {
        out << name << '=' << value << ';';
      }

      void
      put_list(std::ostream              &out,
               const std::string         &name,
               const std::vector<double> &values)
      {
        out << name << '=';
        for (const double v : values)
          out << v << ',';
        out << ';';
      }

      void
      put_roll(std::ostream               &out,
               const std::string          &prefix,
               const Parameters::Geometry &g,
               const Parameters::Mesh     &m,
               const Parameters::Material &material)
      {
        put(out, prefix + "R1", g.inner_radius);
        put(out, prefix + "R0", g.outer_radius);
        put(out, prefix + "sector", g.sector_angle);
        put(out, prefix + "mesh_source", static_cast<int>(m.source));
        put(out, prefix + "mesh_file", m.mesh_file);
        put(out, prefix + "radial_cells", m.radial_cells);
        put(out, prefix + "circumferential_cells", m.circumferential_cells);
        put(out, prefix + "circumferential_grading", m.circumferential_grading);
        put(out, prefix + "radial_grading", m.radial_grading);
        put(out, prefix + "refinements", m.global_refinements);
        put(out, prefix + "adaptive_passes", m.adaptive_passes);
        put(out, prefix + "nip_fitting", static_cast<int>(m.nip_fitting));
        put(out, prefix + "nip_cells", m.nip_cells);
        put(out, prefix + "nip_grading", m.nip_grading);
        put(out, prefix + "edge_refinements", m.edge_refinements);
        put_list(out, prefix + "C1", material.layer_C1);
        put_list(out, prefix + "C2", material.layer_C2);
        put_list(out, prefix + "layers", material.layer_thicknesses);
        put(out, prefix + "theory", static_cast<int>(material.theory));
      }

      /// The indentation sweep's scene: the cross-section with
      /// Contact/Values = @p approaches, no companions, output in @p dir.
      Parameters::AllParameters
      sweep_parameters(const Parameters::AllParameters &parameters,
                       const std::vector<double>       &approaches,
                       const std::string               &dir)
      {
        Parameters::AllParameters p     = parameters;
        p.contact.mode                  = Parameters::ContactMode::indentation;
        p.contact.values                = approaches;
        p.contact.compare_linear        = false;
        p.contact.keys_set_without_mode = false;
        p.accuracy.error_estimate       = false;
        p.output.directory              = dir;
        p.output.write_vtu              = false;
        p.output.vtu_every_step         = false;
        p.output.csv_every_step         = false;
        p.output.print_timing           = false;
        p.study                         = Parameters::Study();
        return p;
      }

      /// Reads @p file if it holds the law of @p key.
      bool
      read_cache(const std::string &file,
                 const std::string &key,
                 LawSamples        &law)
      {
        std::ifstream in(file);
        std::string   line;
        if (!in || !std::getline(in, line) || line != "# " + key)
          return false;
        while (std::getline(in, line))
          {
            if (line.empty() || line[0] == '#' || line[0] == 'a')
              continue;
            std::replace(line.begin(), line.end(), ',', ' ');
            std::istringstream s(line);
            double             u, P, b, peak;
            if (!(s >> u >> P >> b >> peak))
              return false;
            law.approach.push_back(u);
            law.line_load.push_back(P);
            law.half_width.push_back(b);
            law.peak_pressure.push_back(peak);
          }
        return law.approach.size() >= 2;
      }

      void
      write_cache(const LawSamples &law, const std::string &key)
      {
        std::ostringstream out;
        out << "# " << key << '\n'
            << "# P_2D(u0) of the cross-section above, swept by rollnip in "
               "indentation mode on "
            << law.n_cells << " cells in " << std::setprecision(3)
            << law.sweep_seconds << " s (doc/face.md)\n"
            << "approach_mm,line_load_N_per_mm,half_width_mm,"
               "peak_pressure_MPa\n"
            << std::setprecision(10);
        for (unsigned int i = 0; i < law.approach.size(); ++i)
          out << law.approach[i] << ',' << law.line_load[i] << ','
              << law.half_width[i] << ',' << law.peak_pressure[i] << '\n';
        write_atomically(law.file, [&](std::ostream &o) { o << out.str(); });
      }
    } // namespace

    std::vector<double>
    law_approaches(const Parameters::AllParameters &parameters,
                   const Parameters::Face          &face,
                   const double                     line_load)
    {
      double largest = face.law_maximum_approach;
      if (largest == 0)
        {
          // The thin bonded layer, P = 2 b^5 / (15 R C) with u0 = b^2 /
          // (2 R), at three times the line load, but at most half the
          // cover (beyond, the layer is not thin and the nip not small).
          const SceneDescription scene = describe_scene(parameters);
          const double           R     = NipEstimates::effective_radius(scene);
          const double           C = NipEstimates::thin_layer_compliance(scene);
          const double b = std::pow(15 * R * C * 3 * line_load / 2, 0.2);
          double       cover =
            parameters.geometry.outer_radius - parameters.geometry.inner_radius;
          if (parameters.mating_roll.covered)
            cover += parameters.mating_roll.geometry.outer_radius -
                     parameters.mating_roll.geometry.inner_radius;
          largest = std::min(b * b / (2 * R), 0.5 * cover);
        }
      std::vector<double> u(face.law_samples);
      for (unsigned int i = 0; i < u.size(); ++i)
        u[i] = largest * std::pow(face.law_range,
                                  -static_cast<double>(u.size() - 1 - i) /
                                    (u.size() - 1));
      return u;
    }

    std::string
    cross_section_key(const Parameters::AllParameters &p,
                      const std::vector<double>       &approaches)
    {
      std::ostringstream out;
      out << std::setprecision(17) << "rollnip face law 1;";
      put_roll(out, "", p.geometry, p.mesh, p.material);
      put(out, "element", static_cast<int>(p.discretization.element));
      for (const auto c : p.boundary_conditions.condition)
        put(out, "bc", static_cast<int>(c));
      put(out, "indenter_radius", p.contact.indenter_radius);
      put(out, "conformity", p.contact.tolerance);
      put(out, "control_tolerance", p.contact.control_tolerance);
      put(out, "contact_iterations", p.contact.max_iterations);
      put(out, "covered_mate", p.mating_roll.covered);
      if (p.mating_roll.covered)
        put_roll(out,
                 "mate_",
                 p.mating_roll.geometry,
                 p.mating_roll.mesh,
                 p.mating_roll.material);
      put(out, "initial_steps", p.load_stepping.n_initial_steps);
      put(out, "residual_tolerance", p.nonlinear_solver.residual_tolerance);
      put(out, "increment_tolerance", p.nonlinear_solver.increment_tolerance);
      put_list(out, "approaches", approaches);
      return out.str();
    }

    LawSamples
    cross_section_law(const Parameters::AllParameters &parameters,
                      const Parameters::Face          &face,
                      const std::vector<double>       &approaches,
                      MPI_Comm                         communicator)
    {
      const std::string  key = cross_section_key(parameters, approaches);
      std::ostringstream name;
      name << "face_law_" << std::hex << std::setw(16) << std::setfill('0')
           << fnv1a(key) << ".csv";
      const std::string dir = face.law_cache_directory.empty()
                                ? parameters.output.directory
                                : face.law_cache_directory;
      LawSamples        law;
      law.file = dir + "/" + name.str();
      // Every process reads the same file: the decision is collective.
      if (read_cache(law.file, key, law))
        {
          law.from_cache = true;
          return law;
        }
      law                           = LawSamples();
      law.file                      = dir + "/" + name.str();
      const std::string   sweep_dir = dir + "/face_law_sweep";
      const auto          start     = std::chrono::steady_clock::now();
      std::vector<NipRow> rows;
      const int           code =
        run_nip_study(sweep_parameters(parameters, approaches, sweep_dir),
                      communicator,
                      &rows,
                      nullptr,
                      false);
      AssertThrow(code == 0 && rows.size() == approaches.size(),
                  ExcMessage("Face: the cross-section's sweep stopped after " +
                             std::to_string(rows.size()) + " of " +
                             std::to_string(approaches.size()) +
                             " approaches (see '" + sweep_dir +
                             "'); lower Face/Law maximum approach"));
      law.sweep_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      for (const NipRow &row : rows)
        {
          law.approach.push_back(row.nonlinear.indentation);
          law.line_load.push_back(row.nonlinear.nip_load);
          law.half_width.push_back(row.nonlinear.half_chord);
          law.peak_pressure.push_back(row.nonlinear.peak_pressure);
          law.n_cells = row.n_cells;
        }
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          make_directories(dir);
          write_cache(law, key);
          // The sweep's nips are the law's raw material, not results.
          std::filesystem::remove_all(sweep_dir);
        }
      MPI_Barrier(communicator);
      return law;
    }
  } // namespace Face
} // namespace rollnip
