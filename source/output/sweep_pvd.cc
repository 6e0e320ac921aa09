#include <deal.II/base/mpi.h>

#include <rollnip/output/atomic_file.h>
#include <rollnip/output/sweep_pvd.h>

#include <iomanip>

namespace rollnip
{
  SweepPvd::SweepPvd(const std::string &filename,
                     const std::string &time_meaning)
      : filename(filename)
      , time_meaning(time_meaning)
  {}

  void
  SweepPvd::add(const double       time,
                const std::string &file,
                const unsigned int part)
  {
    records.push_back({time, part, file});
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    write_atomically(filename, [&](std::ostream &out) {
      out << "<?xml version=\"1.0\"?>\n"
          << "<!-- rollnip nip sweep: time = " << time_meaning << " -->\n"
          << "<VTKFile type=\"Collection\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n"
          << "  <Collection>\n"
          << std::setprecision(10);
      for (const auto &r : records)
        out << "    <DataSet timestep=\"" << r.time << "\" group=\"\" part=\""
            << r.part << "\" file=\"" << r.file << "\"/>\n";
      out << "  </Collection>\n</VTKFile>\n";
    });
  }
} // namespace rollnip
