// The crowns of the face model (doc/face.md, "Crowns"): each shape's
// values at the centre, the ends and between against its formula, the
// circular crown on its circle, a table mirrored and interpolated, the
// diameter halved to the radius, and a bad table refused naming its line.
#include <deal.II/base/numbers.h>

#include <rollnip/face/crown.h>
#include <rollnip/run_errors.h>

#include "test_tools.h"

#include <cmath>
#include <fstream>

using namespace rollnip;
using namespace rollnip::Face;
using testing::num;

namespace
{
  Parameters::FaceCrown
  crown(const Parameters::CrownShape shape,
        const double                 amount,
        const bool                   on_diameter,
        const std::string           &table = "")
  {
    return {shape, amount, on_diameter, table, 0.};
  }

  double
  worst_of(const Crown &c, const std::function<double(double)> &exact)
  {
    double worst = 0;
    for (double y = -600; y <= 600; y += 25)
      worst = std::max(worst, std::abs(c(y) - exact(y)));
    return worst;
  }
} // namespace

int
main()
{
  testing::Checker checker;
  using Parameters::CrownShape;
  const double L = 1200, h = L / 2, pi = numbers::PI;

  const Crown parabolic =
    make_crown(crown(CrownShape::parabolic, 0.4, true), L);
  checker.check(worst_of(parabolic,
                         [&](double y) {
                           return 0.2 * (1 - y * y / (h * h));
                         }) < 1e-15 &&
                  parabolic(0) == 0.2 && std::abs(parabolic(h)) < 1e-15,
                "parabolic, 0.4 mm on the diameter: 0.2 mm on the radius at "
                "the centre, 0 at the ends, C (1 - s^2) between");

  const Crown sine = make_crown(crown(CrownShape::sine, 0.3, false), L);
  checker.check(worst_of(sine,
                         [&](double y) { return 0.3 * std::cos(pi * y / L); }) <
                    1e-15 &&
                  std::abs(sine(h)) < 1e-15,
                "sine, 0.3 mm on the radius: C cos(pi s / 2)");

  for (const double C : {0.25, -0.25})
    {
      const Crown  arc = make_crown(crown(CrownShape::circular, C, false), L);
      const double R   = (h * h + C * C) / (2 * C);
      double       off = 0;
      for (double y = -h; y <= h; y += 25)
        off =
          std::max(off, std::abs(std::hypot(y, arc(y) + R - C) - std::abs(R)));
      checker.check(std::abs(arc(0) - C) < 1e-12 && std::abs(arc(h)) < 1e-9 &&
                      std::abs(arc(-h)) < 1e-9 && off < 1e-9,
                    "circular, " + num(C) +
                      " mm: through the ends and the centre, on a circle of "
                      "radius " +
                      num(R) + " mm (off by " + num(off) + " mm)");
    }

  {
    std::ofstream out("face_crown_table.csv");
    out << "y_mm,change_mm\n0,0.5\n300,0.3\n600,0\n";
  }
  const Crown table =
    make_crown(crown(CrownShape::table, 0, true, "face_crown_table.csv"), L);
  checker.check(std::abs(table(0) - 0.25) < 1e-15 &&
                  std::abs(table(-150) - 0.2) < 1e-15 &&
                  std::abs(table(450) - 0.075) < 1e-15 && table(-600) == 0 &&
                  table(150) == table(-150),
                "a table of y >= 0 on the diameter: mirrored, halved, linear "
                "between its rows (c(-150) = " +
                  num(table(-150)) + " mm)");

  {
    std::ofstream out("face_crown_bad.csv");
    out << "y_mm,change_mm\n0,0.5\n300,0.3\n200,0\n";
  }
  std::string message;
  try
    {
      read_crown_table("face_crown_bad.csv", "Face/Roll crown/Table file");
    }
  catch (const ExceptionBase &e)
    {
      message = one_line_message(e);
    }
  checker.check(message.find("Face/Roll crown/Table file 'face_crown_bad.csv', "
                             "line 4: y must increase") != std::string::npos,
                "a table whose y falls is refused, naming the entry and the "
                "line: " +
                  message);
  return checker.result();
}
