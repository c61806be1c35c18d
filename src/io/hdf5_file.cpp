#include "isolab/io/hdf5_file.h"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <vector>

#include "isolab/core/errors.h"

namespace isolab::io {
namespace {

// Closes an HDF5 identifier with its matching call at the end of a scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

std::vector<hsize_t> Dimensions(std::span<const std::size_t> dims) {
  return std::vector<hsize_t>(dims.begin(), dims.end());
}

std::size_t Product(std::span<const std::size_t> dims) {
  std::size_t n = 1;
  for (const std::size_t d : dims) n *= d;
  return n;
}

}  // namespace

struct Hdf5File::Impl {
  std::string path;
  std::string temporary;
  hid_t file = -1;
  hid_t file_create = -1;    // track-times setting of the root group
  hid_t object_create = -1;  // datasets
  hid_t group_create = -1;   // groups
  H5E_auto2_t saved_handler = nullptr;
  void* saved_handler_data = nullptr;

  [[noreturn]] void Fail(const std::string& what) const {
    throw InputError({path}, fmt::format("cannot write ({})", what));
  }
  void Check(herr_t status, const std::string& what) const {
    if (status < 0) Fail(what);
  }
  void Check(hid_t id, const std::string& what) const {
    if (id < 0) Fail(what);
  }

  hid_t Space(std::span<const std::size_t> dims) const {
    if (dims.empty()) return H5Screate(H5S_SCALAR);
    const std::vector<hsize_t> d = Dimensions(dims);
    return H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr);
  }

  void Write(const std::string& name, std::span<const std::size_t> dims, hid_t type,
             const void* data, std::size_t count, const std::string& units) const {
    if (Product(dims) != count) Fail(fmt::format("{}: {} values for its dimensions", name, count));
    Handle space(Space(dims), H5Sclose);
    Check(space.get(), "space of " + name);
    Handle dataset(
        H5Dcreate2(file, name.c_str(), type, space.get(), H5P_DEFAULT, object_create, H5P_DEFAULT),
        H5Dclose);
    Check(dataset.get(), "dataset " + name);
    if (count > 0) {
      Check(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing " + name);
    }
    if (!units.empty()) WriteStringAttribute(dataset.get(), "units", units);
  }

  void WriteStringAttribute(hid_t object, const std::string& name, const std::string& value) const {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    Check(type.get(), "string type");
    Check(H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1)), "string size");
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attribute(
        H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose);
    Check(attribute.get(), "attribute " + name);
    Check(H5Awrite(attribute.get(), type.get(), value.empty() ? "" : value.c_str()),
          "attribute " + name);
  }

  void WithObject(const std::string& object, const std::function<void(hid_t)>& write) const {
    Handle handle(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose);
    Check(handle.get(), "object " + object);
    write(handle.get());
  }

  void Close() {
    for (hid_t* plist : {&file_create, &object_create, &group_create}) {
      if (*plist >= 0) H5Pclose(*plist);
      *plist = -1;
    }
    if (file >= 0) H5Fclose(file);
    file = -1;
  }
};

Hdf5File::Hdf5File(std::string path, bool reproducible) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.path = std::move(path);
  s.temporary = s.path + ".tmp";
  // HDF5 prints its error stack by default; errors here are reported through return codes.
  H5Eget_auto2(H5E_DEFAULT, &s.saved_handler, &s.saved_handler_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  s.file_create = H5Pcreate(H5P_FILE_CREATE);
  s.object_create = H5Pcreate(H5P_DATASET_CREATE);
  s.group_create = H5Pcreate(H5P_GROUP_CREATE);
  if (s.file_create < 0 || s.object_create < 0 || s.group_create < 0) {
    s.Close();
    H5Eset_auto2(H5E_DEFAULT, s.saved_handler, s.saved_handler_data);
    s.Fail("property lists");
  }
  if (reproducible) {
    for (const hid_t plist : {s.file_create, s.object_create, s.group_create}) {
      H5Pset_obj_track_times(plist, false);
    }
  }
  s.file = H5Fcreate(s.temporary.c_str(), H5F_ACC_TRUNC, s.file_create, H5P_DEFAULT);
  if (s.file < 0) {
    s.Close();
    H5Eset_auto2(H5E_DEFAULT, s.saved_handler, s.saved_handler_data);
    s.Fail("cannot create the file");
  }
}

Hdf5File::~Hdf5File() {
  const bool committed = impl_->file < 0;
  impl_->Close();
  if (!committed) {
    std::error_code ignored;
    std::filesystem::remove(impl_->temporary, ignored);
  }
  H5Eset_auto2(H5E_DEFAULT, impl_->saved_handler, impl_->saved_handler_data);
}

void Hdf5File::CreateGroup(const std::string& name) {
  Handle group(H5Gcreate2(impl_->file, name.c_str(), H5P_DEFAULT, impl_->group_create, H5P_DEFAULT),
               H5Gclose);
  impl_->Check(group.get(), "group " + name);
}

void Hdf5File::WriteDoubles(const std::string& name, std::span<const std::size_t> dims,
                            std::span<const double> data, const std::string& units) {
  impl_->Write(name, dims, H5T_NATIVE_DOUBLE, data.data(), data.size(), units);
}

void Hdf5File::WriteIntegers(const std::string& name, std::span<const std::size_t> dims,
                             std::span<const std::int32_t> data) {
  impl_->Write(name, dims, H5T_NATIVE_INT32, data.data(), data.size(), "");
}

void Hdf5File::WriteStrings(const std::string& name, std::span<const std::size_t> dims,
                            std::span<const std::string> values) {
  std::size_t width = 1;
  for (const std::string& value : values) width = std::max(width, value.size());
  // Padded with NULs rather than NUL-terminated, so a value as long as the field keeps its last
  // character.
  std::vector<char> buffer(width * values.size(), '\0');
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::copy(values[i].begin(), values[i].end(), buffer.data() + i * width);
  }
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  impl_->Check(type.get(), "string type");
  impl_->Check(H5Tset_size(type.get(), width), "string size");
  impl_->Check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "string padding");
  impl_->Write(name, dims, type.get(), buffer.data(), values.size(), "");
}

void Hdf5File::WriteAttribute(const std::string& object, const std::string& name,
                              const std::string& value) {
  impl_->WithObject(object, [&](hid_t id) { impl_->WriteStringAttribute(id, name, value); });
}

void Hdf5File::WriteAttribute(const std::string& object, const std::string& name, double value) {
  impl_->WithObject(object, [&](hid_t id) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attribute(
        H5Acreate2(id, name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose);
    impl_->Check(attribute.get(), "attribute " + name);
    impl_->Check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value), "attribute " + name);
  });
}

void Hdf5File::Commit() {
  Impl& s = *impl_;
  const herr_t status = H5Fclose(s.file);
  s.file = -1;
  if (status < 0) {
    std::error_code ignored;
    std::filesystem::remove(s.temporary, ignored);
    s.Fail("closing (flushing) the file");
  }
  std::error_code error;
  std::filesystem::rename(s.temporary, s.path, error);
  if (error) {
    const std::string why = error.message();
    std::filesystem::remove(s.temporary, error);
    s.Fail(fmt::format("renaming {}: {}", s.temporary, why));
  }
}

}  // namespace isolab::io
