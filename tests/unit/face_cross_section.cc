// The face model on its cross-section's own nip law (doc/face.md): a
// hollow steel core (94.4 / 60 mm, face 1000 mm, bearings 1200 mm) with
// the run-30 cover against the rigid 76.2 mm roll at a mean line load of
// 20 N/mm.
// 1. The law passes through the sweep's nips, and the law of 8 approaches
//    predicts those of 15 between its samples (its interpolation error);
// 2. the centre/end ratio of q and 2b converges in the 1D mesh and in the
//    law's sampling;
// 3. the law is read back from its cache, and another cross-section
//    gets another file.
#include <rollnip/app/cross_section_law.h>
#include <rollnip/face/beam.h>
#include <rollnip/face/face_solver.h>
#include <rollnip/face/foundation_law.h>

#include "test_tools.h"

#include <cmath>
#include <filesystem>

using namespace rollnip;
using namespace rollnip::Face;
using testing::num;

namespace
{
  const std::string run30 = "subsection Geometry\n"
                            "  set Inner radius = 47.2\n"
                            "  set Outer radius = 60.7\n"
                            "end\n"
                            "subsection Mesh\n"
                            "  set Radial cells = 8\n"
                            "  set Circumferential cells = 18\n"
                            "  set Circumferential grading = 10\n"
                            "  set Global refinements = 1\n"
                            "end\n"
                            "subsection Contact\n"
                            "  set Mode = indentation\n"
                            "  set Indenter radius = 76.2\n"
                            "end\n"
                            "subsection Output\n"
                            "  set Directory = face_cross_section_output\n"
                            "end\n";

  Parameters::Face
  face_parameters(const unsigned int samples)
  {
    ParameterHandler prm;
    Parameters::Face::declare(prm);
    prm.parse_input_from_string(
      "subsection Face\n  set Enabled = true\n  set Law samples = " +
      std::to_string(samples) + "\n  set Law maximum approach = 6\nend\n");
    Parameters::Face face;
    face.parse(prm);
    return face;
  }

  struct Ratios
  {
    double q, b;
  };

  Ratios
  centre_over_end(const SampledLaw &law, const unsigned int elements)
  {
    Parameters::FaceCore core{94.4, 60, 210000, 0.3, 7850};
    FaceModel            m;
    m.face_length          = 1000;
    m.bearing_distance     = 1200;
    m.elements             = elements;
    m.roll                 = tube_section(core, true);
    m.total_force          = 20 * m.face_length;
    m.law                  = &law;
    const FaceSolution s   = solve_face(m);
    const double       end = m.face_length / 2;
    return {s.line_load(0) / s.line_load(end),
            law.half_width(s.approach_at(0)) /
              law.half_width(s.approach_at(end))};
  }

  SampledLaw
  law_of(const LawSamples &s)
  {
    return SampledLaw(s.approach, s.line_load, s.half_width, s.peak_pressure);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  std::filesystem::remove_all("face_cross_section_output");
  const Parameters::AllParameters p = testing::parameters_from_string(run30);
  const Parameters::Face          coarse_face = face_parameters(8),
                         fine_face            = face_parameters(15);
  const LawSamples coarse                     = cross_section_law(
    p, coarse_face, law_approaches(p, coarse_face, 20), MPI_COMM_WORLD);
  const LawSamples fine = cross_section_law(p,
                                            fine_face,
                                            law_approaches(p, fine_face, 20),
                                            MPI_COMM_WORLD);
  std::cout << "Sweeps: 8 approaches in " << num(coarse.sweep_seconds)
            << " s, 15 in " << num(fine.sweep_seconds) << " s, " << fine.n_cells
            << " cells" << std::endl;

  std::cout << "1. The law" << std::endl;
  const SampledLaw coarse_law = law_of(coarse), fine_law = law_of(fine);
  double           at_samples = 0, between = 0;
  for (unsigned int i = 0; i < fine.approach.size(); ++i)
    {
      const double u = fine.approach[i];
      at_samples     = std::max(at_samples,
                            std::abs(fine_law.load(u) / fine.line_load[i] - 1));
      if (i % 2 == 1)
        between =
          std::max(between,
                   std::abs(coarse_law.load(u) / fine.line_load[i] - 1));
    }
  checker.check(at_samples < 1e-12,
                "the law passes through its nips (" + num(at_samples) + ")");
  // About 1 % measured (0.99 %): the sampling error of 8 approaches.
  checker.check(between < 0.015,
                "8 approaches predict P_2D between them to " + num(between));

  std::cout << "2. Centre/end ratios (q, 2b)" << std::endl;
  std::vector<Ratios> mesh;
  for (const unsigned int n : {25u, 50u, 100u, 200u})
    {
      mesh.push_back(centre_over_end(fine_law, n));
      std::cout << "  " << n
                << " elements, 15 approaches: " << std::setprecision(8)
                << mesh.back().q << ", " << mesh.back().b << std::endl;
    }
  const Ratios sparse = centre_over_end(coarse_law, 200);
  std::cout << "  200 elements, 8 approaches: " << sparse.q << ", " << sparse.b
            << std::endl;
  checker.check(std::abs(mesh[2].q / mesh[3].q - 1) < 1e-5 &&
                  std::abs(mesh[2].b / mesh[3].b - 1) < 1e-5,
                "100 and 200 elements agree to 1e-5");
  checker.check(std::abs(sparse.q / mesh[3].q - 1) < 2e-3 &&
                  std::abs(sparse.b / mesh[3].b - 1) < 2e-3,
                "8 and 15 approaches agree to 2e-3 (q " +
                  num(sparse.q / mesh[3].q - 1) + ", 2b " +
                  num(sparse.b / mesh[3].b - 1) + ")");
  checker.check(mesh[3].q < 1 && mesh[3].b < 1,
                "the uncrowned roll bends away: the centre is light");

  std::cout << "3. The cache" << std::endl;
  const LawSamples again     = cross_section_law(p,
                                             fine_face,
                                             law_approaches(p, fine_face, 20),
                                             MPI_COMM_WORLD);
  double           read_back = 0;
  for (unsigned int i = 0; i < fine.line_load.size(); ++i)
    read_back =
      std::max(read_back, std::abs(again.line_load[i] / fine.line_load[i] - 1));
  // The file holds 10 digits.
  checker.check(again.from_cache && again.file == fine.file && read_back < 1e-9,
                "the law of 15 approaches is read back from " + again.file);
  Parameters::AllParameters other = p;
  other.material.layer_C1[0] *= 2;
  checker.check(cross_section_key(other, fine.approach) !=
                  cross_section_key(p, fine.approach),
                "another cover gets another key");
  return checker.result();
}
