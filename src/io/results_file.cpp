#include "isolab/io/results_file.h"

#include <fmt/format.h>

#include <vector>

#include "hdf5_writer.h"
#include "isolab/io/run_analysis.h"

namespace isolab::io {
namespace {

using integrators::RowMatrix;

using hdf5::Handle;
using hdf5::WriteNumberAttribute;
using hdf5::WriteStringAttribute;
using hdf5::WriteStringDataset;

// A row-major rows x columns array (columns = 0 for a vector).
void WriteDataset(hid_t location, const std::string& name, const double* data, hsize_t rows,
                  hsize_t columns, const std::string& units) {
  hdf5::WriteDataset(location, name, data,
                     columns == 0 ? std::vector<hsize_t>{rows} : std::vector<hsize_t>{rows, columns},
                     units);
}

void WriteMatrix(hid_t location, const std::string& name, const RowMatrix& matrix, int rows,
                 const std::string& units) {
  WriteDataset(location, name, matrix.data(), rows, matrix.cols(), units);
}

// Columns `connections` of the connection forces, or deformations between DOFs.
RowMatrix Columns(const RowMatrix& source, const std::vector<int>& columns, int rows) {
  RowMatrix out(rows, columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) out.col(c) = source.col(columns[c]).head(rows);
  return out;
}

void WriteContents(hid_t file, const RunDescription& run) {
  const auto& r = *run.response;
  const auto& setup = *run.setup;
  const auto& units = run.model->units;
  const int rows = r.rows_written;
  const std::string length = DescribeUnits(units, dimension::kLength);
  const std::string force = DescribeUnits(units, dimension::kForce);
  const std::string velocity = DescribeUnits(units, dimension::kVelocity);
  const std::string acceleration = DescribeUnits(units, dimension::kAcceleration);
  const std::string energy = fmt::format("{}*{}", units.force(), units.length());

  WriteDataset(file, "time", r.time.data(), rows, 0, units.time());
  WriteMatrix(file, "displacement", r.displacement, rows, length);
  WriteMatrix(file, "velocity", r.velocity, rows, velocity);
  WriteMatrix(file, "acceleration", r.acceleration, rows, acceleration);
  WriteMatrix(file, "absolute_acceleration", r.absolute_acceleration, rows, acceleration);
  WriteMatrix(file, "connection_force", r.connection_force, rows, force);

  const auto& connections = setup.structure.connections();
  if (setup.layout.isolation >= 0) {
    const int k = setup.layout.isolation;
    Handle group(H5Gcreate2(file, "isolator", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 "group isolator");
    const Eigen::VectorXd u = r.displacement.col(connections[k].dof_j).head(rows);
    const Eigen::VectorXd f = r.connection_force.col(k).head(rows);
    WriteDataset(group.get(), "displacement", u.data(), rows, 0, length);
    WriteDataset(group.get(), "force", f.data(), rows, 0, force);
    const std::size_t first = setup.structure.law_offset(k);
    const std::size_t count = connections[k].assembly.size();
    const RowMatrix components = r.law_force.block(0, first, rows, count);
    WriteMatrix(group.get(), "component_force", components, rows, force);
    std::string names;
    for (const auto& component : connections[k].assembly.components()) {
      names += (names.empty() ? "" : ",") + component.name;
    }
    WriteStringAttribute(group.get(), "component_names", names);
  }
  if (!setup.layout.stories.empty()) {
    Handle group(H5Gcreate2(file, "story", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 "group story");
    RowMatrix drift(rows, setup.layout.stories.size());
    for (std::size_t s = 0; s < setup.layout.stories.size(); ++s) {
      for (int row = 0; row < rows; ++row)
        drift(row, s) = StoryDrift(setup, r.displacement, row, s);
    }
    WriteMatrix(group.get(), "drift", drift, rows, length);
    WriteMatrix(group.get(), "shear", Columns(r.connection_force, setup.layout.stories, rows), rows,
                force);
  }
  {
    Handle group(H5Gcreate2(file, "energy", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 "group energy");
    std::vector<double> column(rows);
    const auto write = [&](const char* name, double integrators::Energies::*term) {
      for (int i = 0; i < rows; ++i) column[i] = r.energies[i].*term;
      WriteDataset(group.get(), name, column.data(), rows, 0, energy);
    };
    write("input", &integrators::Energies::input);
    write("kinetic", &integrators::Energies::kinetic);
    write("damping", &integrators::Energies::damping);
    write("elastic", &integrators::Energies::elastic);
    write("hysteretic", &integrators::Energies::hysteretic);
  }

  const auto& summary = *run.summary;
  WriteStringAttribute(file, "isolab_version", run.version);
  WriteStringAttribute(file, "model_file", run.model->path);
  WriteStringDataset(file, "model_yaml", run.model->text);
  WriteStringAttribute(file, "record", setup.record_path);
  WriteNumberAttribute(file, "record_scale", setup.scale);
  WriteStringAttribute(
      file, "units",
      fmt::format("force {}, length {}, time {}", units.force(), units.length(), units.time()));
  WriteStringAttribute(file, "integrator", DescribeIntegrator(*run.analysis, setup.grid.dt));
  WriteNumberAttribute(file, "ida_steps", static_cast<double>(summary.ida_steps));
  WriteNumberAttribute(file, "events", static_cast<double>(summary.events));
  WriteNumberAttribute(file, "newton_iterations", static_cast<double>(summary.newton_iterations));
  WriteNumberAttribute(file, "solves_per_step", summary.SolvesPerStep());
  WriteStringAttribute(file, "termination", summary.ok() ? "completed" : "failed");
  WriteStringAttribute(file, "message", summary.message);
  WriteNumberAttribute(file, "energy_balance_error", summary.energy_balance_error);
}

}  // namespace

void WriteResultsFile(const std::string& path, const RunDescription& run) {
  hdf5::WriteFileAtomically(path, "results", [&](hid_t file) { WriteContents(file, run); });
}

}  // namespace isolab::io
