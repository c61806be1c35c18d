#include "isolab/io/hdf5_file.h"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"

namespace isolab::io {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "Rows keeps a hid_t as std::int64_t");

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

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

std::size_t Product(const std::vector<std::size_t>& dims) {
  std::size_t n = 1;
  for (const std::size_t d : dims) n *= d;
  return n;
}

// Variable-length UTF-8 strings: h5py reads them as str, not bytes.
hid_t Utf8StringType() {
  const hid_t type = H5Tcopy(H5T_C_S1);
  if (type >= 0 && (H5Tset_size(type, H5T_VARIABLE) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0)) {
    H5Tclose(type);
    return -1;
  }
  return type;
}

// Why the last HDF5 call on this thread failed, from HDF5's error stack: the system's reason for
// a failed write ("File too large", "No space left on device") when there is one, else the
// innermost description.
std::string LastHdf5Cause() {
  std::string cause;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* entry, void* data) -> herr_t {
        auto& text = *static_cast<std::string*>(data);
        const std::string description = entry->desc != nullptr ? entry->desc : "";
        const std::string marker = "error message = '";
        if (const auto at = description.find(marker); at != std::string::npos) {
          const auto begin = at + marker.size();
          text = description.substr(begin, description.find('\'', begin) - begin);
          return 1;  // the system's reason: stop here
        }
        if (text.empty()) text = description;
        return 0;
      },
      &cause);
  return cause;
}

// UTF-8 strings of `width` bytes, null-padded; h5py's .asstr() reads them as str.
hid_t FixedUtf8StringType(std::size_t width) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  if (type >= 0 && (H5Tset_size(type, width) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0 ||
                    H5Tset_strpad(type, H5T_STR_NULLPAD) < 0)) {
    H5Tclose(type);
    return -1;
  }
  return type;
}

std::vector<const char*> Pointers(std::span<const std::string> values) {
  std::vector<const char*> pointers;
  pointers.reserve(values.size());
  for (const std::string& value : values) pointers.push_back(value.c_str());
  return pointers;
}

}  // namespace

struct Hdf5File::Impl {
  std::optional<AtomicFile> output;
  hid_t file = -1;
  hid_t dataset_create = -1;  // no timestamps
  hid_t group_create = -1;
  H5E_auto2_t saved_handler = nullptr;
  void* saved_handler_data = nullptr;

  // An HDF5 call failed: the disk is full, the file too large, or the disk failed.
  [[noreturn]] void Fail(const std::string& what) const {
    const std::string cause = LastHdf5Cause();
    throw ResourceError(output->path(), fmt::format("cannot write ({}){}", what,
                                                    cause.empty() ? "" : ": " + cause));
  }
  void Check(herr_t status, const std::string& what) const {
    if (status < 0) Fail(what);
  }
  void Check(hid_t id, const std::string& what) const {
    if (id < 0) Fail(what);
  }

  hid_t Space(const std::vector<std::size_t>& dims) const {
    if (dims.empty()) return H5Screate(H5S_SCALAR);
    const std::vector<hsize_t> d(dims.begin(), dims.end());
    return H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr);
  }

  void Write(const std::string& name, const std::vector<std::size_t>& dims, hid_t type,
             const void* data, std::size_t count, const std::string& units) const {
    if (Product(dims) != count) {
      throw std::logic_error(fmt::format("{}: {} values for its dimensions", name, count));
    }
    Handle space(Space(dims), H5Sclose);
    Check(space.get(), "space of " + name);
    Handle dataset(
        H5Dcreate2(file, name.c_str(), type, space.get(), H5P_DEFAULT, dataset_create, H5P_DEFAULT),
        H5Dclose);
    Check(dataset.get(), "dataset " + name);
    if (count > 0) {
      Check(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing " + name);
    }
    if (!units.empty()) WriteStringAttribute(dataset.get(), "units", units);
  }

  void WriteAttributeData(hid_t object, const std::string& name, hid_t type,
                          const std::vector<std::size_t>& dims, const void* data) const {
    // HDF5 refuses zero-sized attributes: an empty array is a null dataspace.
    Handle space(Product(dims) == 0 ? H5Screate(H5S_NULL) : Space(dims), H5Sclose);
    Check(space.get(), "space of attribute " + name);
    Handle attribute(H5Acreate2(object, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                     H5Aclose);
    Check(attribute.get(), "attribute " + name);
    if (Product(dims) > 0) Check(H5Awrite(attribute.get(), type, data), "attribute " + name);
  }

  void WriteStringAttribute(hid_t object, const std::string& name, const std::string& value) const {
    Handle type(Utf8StringType(), H5Tclose);
    Check(type.get(), "string type");
    const char* pointer = value.c_str();
    WriteAttributeData(object, name, type.get(), {}, &pointer);
  }

  void WithObject(const std::string& object, const std::function<void(hid_t)>& write) const {
    if (object == "/") return write(file);  // a file's attributes are its root group's
    Handle handle(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose);
    Check(handle.get(), "object " + object);
    write(handle.get());
  }

  void Close() {
    for (hid_t* plist : {&dataset_create, &group_create}) {
      if (*plist >= 0) H5Pclose(*plist);
      *plist = -1;
    }
    if (file >= 0) H5Fclose(file);
    file = -1;
  }
};

Hdf5File::Hdf5File(std::string path) : impl_(std::make_unique<Impl>()) {
  // HDF5 1.10 (Debian 12) frees a file whose close failed (a full disk) but keeps its identifier,
  // and its exit handler then closes it again: a crash after the error was reported (fixed in
  // HDF5 1.14, HDFGroup/hdf5#2291). Without the handler nothing is closed twice; isolab closes
  // every file it opens itself. Effective only when isolab is the first to use HDF5.
  static const herr_t no_exit_handler = H5dont_atexit();
  (void)no_exit_handler;
  Impl& s = *impl_;
  s.output.emplace(std::move(path), AtomicFile::Temporary::kNamed);
  // HDF5 prints its error stack by default; errors here are reported through return codes. (The
  // setting is per thread in the thread-safe library Debian ships.)
  H5Eget_auto2(H5E_DEFAULT, &s.saved_handler, &s.saved_handler_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  try {
    Handle file_create(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
    Handle file_access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    s.dataset_create = H5Pcreate(H5P_DATASET_CREATE);
    s.group_create = H5Pcreate(H5P_GROUP_CREATE);
    for (const hid_t plist :
         {file_create.get(), file_access.get(), s.dataset_create, s.group_create}) {
      s.Check(plist, "property lists");
    }
    for (const hid_t plist : {file_create.get(), s.dataset_create, s.group_create}) {
      s.Check(H5Pset_obj_track_times(plist, false), "property lists");
    }
    // Closing with objects still open is an error (Commit's check), not a silent deferral.
    s.Check(H5Pset_fclose_degree(file_access.get(), H5F_CLOSE_SEMI), "property lists");
    s.file = H5Fcreate(s.output->temporary_path().c_str(), H5F_ACC_TRUNC, file_create.get(),
                       file_access.get());
    s.Check(s.file, "cannot create the file");
  } catch (...) {
    s.Close();
    H5Eset_auto2(H5E_DEFAULT, s.saved_handler, s.saved_handler_data);
    throw;
  }
}

Hdf5File::~Hdf5File() {
  impl_->Close();
  H5Eset_auto2(H5E_DEFAULT, impl_->saved_handler, impl_->saved_handler_data);
}

void Hdf5File::CreateGroup(const std::string& name) {
  Handle group(H5Gcreate2(impl_->file, name.c_str(), H5P_DEFAULT, impl_->group_create, H5P_DEFAULT),
               H5Gclose);
  impl_->Check(group.get(), "group " + name);
}

void Hdf5File::WriteDoubles(const std::string& name, const std::vector<std::size_t>& dims,
                            std::span<const double> data, const std::string& units) {
  impl_->Write(name, dims, H5T_NATIVE_DOUBLE, data.data(), data.size(), units);
}

void Hdf5File::WriteIntegers(const std::string& name, const std::vector<std::size_t>& dims,
                             std::span<const std::int64_t> data, const std::string& units) {
  impl_->Write(name, dims, H5T_NATIVE_INT64, data.data(), data.size(), units);
}

void Hdf5File::WriteStrings(const std::string& name, const std::vector<std::size_t>& dims,
                            std::span<const std::string> values) {
  // Fixed length, the longest's, null-padded, packed in one buffer: a variable-length string
  // goes through HDF5's global heap, about 20,000 instructions each (a 5,000-run study's summary
  // holds 20,000 of them).
  std::size_t width = 1;
  for (const std::string& value : values) width = std::max(width, value.size());
  std::vector<char> packed(values.size() * width, '\0');
  for (std::size_t k = 0; k < values.size(); ++k) {
    std::copy(values[k].begin(), values[k].end(), packed.begin() + static_cast<long>(k * width));
  }
  Handle type(FixedUtf8StringType(width), H5Tclose);
  impl_->Check(type.get(), "string type");
  impl_->Write(name, dims, type.get(), packed.data(), values.size(), "");
}

void Hdf5File::WriteText(const std::string& name, const std::string& value) {
  // Fixed length: one string needs no global heap (much cheaper to write than a variable-length
  // one).
  WriteStrings(name, {}, std::span<const std::string>(&value, 1));
}

void Hdf5File::WriteAttribute(const std::string& object, const std::string& name,
                              const std::string& value) {
  impl_->WithObject(object, [&](hid_t id) { impl_->WriteStringAttribute(id, name, value); });
}

void Hdf5File::WriteAttribute(const std::string& object, const std::string& name, double value) {
  impl_->WithObject(object, [&](hid_t id) {
    impl_->WriteAttributeData(id, name, H5T_NATIVE_DOUBLE, {}, &value);
  });
}

void Hdf5File::WriteIntegerAttribute(const std::string& object, const std::string& name,
                                     std::int64_t value) {
  impl_->WithObject(
      object, [&](hid_t id) { impl_->WriteAttributeData(id, name, H5T_NATIVE_INT64, {}, &value); });
}

void Hdf5File::WriteStringsAttribute(const std::string& object, const std::string& name,
                                     std::span<const std::string> values) {
  impl_->WithObject(object, [&](hid_t id) {
    Handle type(Utf8StringType(), H5Tclose);
    impl_->Check(type.get(), "string type");
    const std::vector<const char*> pointers = Pointers(values);
    impl_->WriteAttributeData(id, name, type.get(), {values.size()}, pointers.data());
  });
}

void Hdf5File::WriteDoublesAttribute(const std::string& object, const std::string& name,
                                     std::span<const double> values) {
  impl_->WithObject(object, [&](hid_t id) {
    impl_->WriteAttributeData(id, name, H5T_NATIVE_DOUBLE, {values.size()}, values.data());
  });
}

Hdf5File::Rows Hdf5File::CreateRows(const std::string& name, std::size_t columns,
                                    const std::string& units, std::size_t chunk_rows,
                                    std::size_t expected_rows) {
  const Impl& s = *impl_;
  chunk_rows = std::max<std::size_t>(chunk_rows, 1);
  const int rank = columns == 0 ? 1 : 2;
  const hsize_t initial[2] = {expected_rows, columns};
  const hsize_t maximum[2] = {H5S_UNLIMITED, columns};
  const hsize_t chunk[2] = {chunk_rows, columns};
  Handle space(H5Screate_simple(rank, initial, maximum), H5Sclose);
  s.Check(space.get(), "space of " + name);
  Handle create(H5Pcopy(s.dataset_create), H5Pclose);
  s.Check(create.get(), "property list of " + name);
  s.Check(H5Pset_chunk(create.get(), rank, chunk), "chunks of " + name);
  const hid_t dataset = H5Dcreate2(s.file, name.c_str(), H5T_NATIVE_DOUBLE, space.get(),
                                   H5P_DEFAULT, create.get(), H5P_DEFAULT);
  s.Check(dataset, "dataset " + name);
  Rows rows(impl_.get(), dataset, name, columns, chunk_rows, expected_rows);
  if (!units.empty()) s.WriteStringAttribute(dataset, "units", units);
  return rows;
}

void Hdf5File::Commit() {
  Impl& s = *impl_;
  // Only the file itself may be open: an open dataset would keep the file from closing.
  // (The files themselves are not counted: a file whose close failed may linger freed among them.)
  constexpr unsigned kObjects = H5F_OBJ_DATASET | H5F_OBJ_GROUP | H5F_OBJ_DATATYPE | H5F_OBJ_ATTR;
  if (H5Fget_obj_count(s.file, kObjects | H5F_OBJ_LOCAL) > 0) {
    throw std::logic_error("objects still open at commit (a Rows outlived its writer)");
  }
  for (hid_t* plist : {&s.dataset_create, &s.group_create}) {
    H5Pclose(*plist);
    *plist = -1;
  }
  const herr_t status = H5Fclose(s.file);
  s.file = -1;
  s.Check(status, "closing (flushing) the file");
  s.output->Commit();
}

Hdf5File::Rows::Rows(const Hdf5File::Impl* file, std::int64_t dataset, std::string name,
                     std::size_t columns, std::size_t chunk_rows, std::size_t extent)
    : file_(file),
      dataset_(dataset),
      name_(std::move(name)),
      columns_(columns),
      chunk_rows_(chunk_rows),
      extent_(extent) {}

Hdf5File::Rows::Rows(Rows&& other) noexcept
    : file_(other.file_),
      dataset_(other.dataset_),
      name_(std::move(other.name_)),
      columns_(other.columns_),
      chunk_rows_(other.chunk_rows_),
      rows_(other.rows_),
      extent_(other.extent_) {
  other.dataset_ = -1;
}

Hdf5File::Rows::~Rows() {
  if (dataset_ >= 0) H5Dclose(dataset_);
}

void Hdf5File::Rows::Append(std::span<const double> values) {
  if (values.empty()) return;
  const std::size_t width = std::max<std::size_t>(columns_, 1);
  if (values.size() % width != 0) {
    throw std::logic_error(
        fmt::format("{}: {} values are not whole rows of {}", name_, values.size(), width));
  }
  const hsize_t added = values.size() / width;
  Extend(added);
  if (rows_ % chunk_rows_ == 0 && added % chunk_rows_ == 0) {
    const std::size_t chunk_values = chunk_rows_ * width;
    for (std::size_t k = 0; k < added / chunk_rows_; ++k) {
      WriteChunk(rows_ + k * chunk_rows_, values.subspan(k * chunk_values, chunk_values));
    }
    rows_ += added;
    return;
  }
  Handle file_space(H5Dget_space(dataset_), H5Sclose);
  file_->Check(file_space.get(), "space of " + name_);
  const hsize_t start[2] = {rows_, 0};
  const hsize_t count[2] = {added, columns_};
  file_->Check(
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
      "selecting rows of " + name_);
  const int rank = columns_ == 0 ? 1 : 2;
  Handle memory_space(H5Screate_simple(rank, count, nullptr), H5Sclose);
  file_->Check(memory_space.get(), "memory space of " + name_);
  file_->Check(H5Dwrite(dataset_, H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                        H5P_DEFAULT, values.data()),
               "writing " + name_);
  rows_ += added;
}

void Hdf5File::Rows::AppendLastChunk(std::span<const double> chunk, std::size_t rows) {
  const std::size_t width = std::max<std::size_t>(columns_, 1);
  if (rows_ % chunk_rows_ != 0 || chunk.size() != chunk_rows_ * width || rows > chunk_rows_) {
    throw std::logic_error(fmt::format("{}: {} rows of a chunk of {} values at row {}", name_, rows,
                                       chunk.size(), rows_));
  }
  if (rows == 0) return;
  Extend(rows);
  WriteChunk(rows_, chunk);
  rows_ += rows;
}

void Hdf5File::Rows::Extend(std::size_t added) {
  if (rows_ + added > extent_) SetExtent(rows_ + added);
}

void Hdf5File::Rows::SetExtent(std::size_t rows) {
  const hsize_t extent[2] = {rows, columns_};
  // The message is built only on failure: these calls come once a block per series.
  if (H5Dset_extent(dataset_, extent) < 0) file_->Fail("setting the extent of " + name_);
  extent_ = rows;
}

void Hdf5File::Rows::Close() {
  if (dataset_ < 0) return;
  if (extent_ != rows_) SetExtent(rows_);
  const herr_t status = H5Dclose(dataset_);
  dataset_ = -1;
  file_->Check(status, "closing " + name_);
}

// Native doubles without filters: the chunk's bytes are the file's.
void Hdf5File::Rows::WriteChunk(std::size_t first_row, std::span<const double> chunk) {
  const hsize_t offset[2] = {first_row, 0};
  if (H5Dwrite_chunk(dataset_, H5P_DEFAULT, 0, offset, chunk.size() * sizeof(double),
                     chunk.data()) < 0) {
    file_->Fail("writing " + name_);
  }
}

}  // namespace isolab::io
