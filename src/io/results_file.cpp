#include "isolab/io/results_file.h"

#include <fmt/format.h>
#include <hdf5.h>

#include <filesystem>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/io/run_analysis.h"

namespace isolab::io {
namespace {

using integrators::RowMatrix;

// Owns an HDF5 identifier and closes it with the matching call.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error("HDF5: " + what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  // Closes now and reports failure (a file's close flushes it: the status matters).
  void Close(const std::string& what) {
    const herr_t status = close_(id_);
    id_ = -1;
    if (status < 0) throw std::runtime_error("HDF5: " + what);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void Check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what);
}

void WriteStringAttribute(hid_t object, const std::string& name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  Check(H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1)), "string size");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attribute(
      H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
      "attribute " + name);
  Check(H5Awrite(attribute.get(), type.get(), value.empty() ? "" : value.c_str()),
        "attribute " + name);
}

// Text of any length (attributes stop near 64 KiB): a scalar fixed-length string dataset.
void WriteStringDataset(hid_t location, const std::string& name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  Check(H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1)), "string size");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle dataset(H5Dcreate2(location, name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose, "dataset " + name);
  Check(H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                 value.empty() ? "" : value.c_str()),
        "writing " + name);
}

void WriteNumberAttribute(hid_t object, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attribute(
      H5Acreate2(object, name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose, "attribute " + name);
  Check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value), "attribute " + name);
}

// A row-major rows x columns array (columns = 0 for a vector).
void WriteDataset(hid_t location, const std::string& name, const double* data, hsize_t rows,
                  hsize_t columns, const std::string& units) {
  const hsize_t dims[2] = {rows, columns};
  Handle space(H5Screate_simple(columns == 0 ? 1 : 2, dims, nullptr), H5Sclose, "space " + name);
  Handle dataset(H5Dcreate2(location, name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose, "dataset " + name);
  if (rows > 0) {
    Check(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "writing " + name);
  }
  WriteStringAttribute(dataset.get(), "units", units);
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
  WriteStringAttribute(file, "termination", summary.ok() ? "completed" : "failed");
  WriteStringAttribute(file, "message", summary.message);
  WriteNumberAttribute(file, "energy_balance_error", summary.energy_balance_error);
}

}  // namespace

void WriteResultsFile(const std::string& path, const RunDescription& run) {
  const std::string temporary = path + ".tmp";
  // HDF5 prints its own error stack by default; ours are reported through the return codes, so
  // printing is off while writing and the caller's handler is restored afterwards.
  H5E_auto2_t handler = nullptr;
  void* handler_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &handler, &handler_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  try {
    Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                "cannot create the file");
    WriteContents(file.get(), run);
    file.Close("closing (flushing) the file");
    std::filesystem::rename(temporary, path);
  } catch (const std::exception& error) {
    H5Eset_auto2(H5E_DEFAULT, handler, handler_data);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw InputError({path}, fmt::format("cannot write results ({})", error.what()));
  }
  H5Eset_auto2(H5E_DEFAULT, handler, handler_data);
}

}  // namespace isolab::io
