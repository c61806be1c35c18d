#include "hdf5_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "isolab/core/errors.h"

namespace isolab::io::hdf5 {

Handle::Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
  if (id_ < 0) throw std::runtime_error("HDF5: " + what);
}

Handle::~Handle() {
  if (id_ >= 0) close_(id_);
}

void Handle::Close(const std::string& what) {
  const herr_t status = close_(id_);
  id_ = -1;
  if (status < 0) throw std::runtime_error("HDF5: " + what);
}

void Check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what);
}

Handle CreateGroup(hid_t location, const std::string& name) {
  return Handle(H5Gcreate2(location, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "group " + name);
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

void WriteDataset(hid_t location, const std::string& name, const double* data,
                  const std::vector<hsize_t>& dimensions, const std::string& units) {
  Handle space(H5Screate_simple(static_cast<int>(dimensions.size()), dimensions.data(), nullptr),
               H5Sclose, "space " + name);
  Handle dataset(H5Dcreate2(location, name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose, "dataset " + name);
  hsize_t size = 1;
  for (const hsize_t n : dimensions) size *= n;
  if (size > 0) {
    Check(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "writing " + name);
  }
  WriteStringAttribute(dataset.get(), "units", units);
}

void WriteFileAtomically(const std::string& path, const std::string& what,
                         const std::function<void(hid_t file)>& write) {
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
    write(file.get());
    file.Close("closing (flushing) the file");
    std::filesystem::rename(temporary, path);
  } catch (const std::exception& error) {
    H5Eset_auto2(H5E_DEFAULT, handler, handler_data);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw InputError({path}, fmt::format("cannot write {} ({})", what, error.what()));
  }
  H5Eset_auto2(H5E_DEFAULT, handler, handler_data);
}

}  // namespace isolab::io::hdf5
