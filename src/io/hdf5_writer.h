// Small RAII and writing helpers over the HDF5 C API, private to io: the results file and the
// spectrum file both write numeric datasets with a "units" attribute, string attributes and
// datasets, under a temporary name renamed into place.
#pragma once

#include <hdf5.h>

#include <functional>
#include <string>
#include <vector>

namespace isolab::io::hdf5 {

// Owns an HDF5 identifier and closes it with the matching call.
class Handle {
 public:
  // Throws std::runtime_error("HDF5: " + what) when id < 0.
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what);
  ~Handle();
  // Closes now and reports failure (a file's close flushes it: the status matters).
  void Close(const std::string& what);
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Throws std::runtime_error("HDF5: " + what) when status < 0.
void Check(herr_t status, const std::string& what);

Handle CreateGroup(hid_t location, const std::string& name);
void WriteStringAttribute(hid_t object, const std::string& name, const std::string& value);
// Text of any length (attributes stop near 64 KiB): a scalar fixed-length string dataset.
void WriteStringDataset(hid_t location, const std::string& name, const std::string& value);
void WriteNumberAttribute(hid_t object, const std::string& name, double value);
// A row-major array of the given dimensions (one entry for a vector), with a "units" attribute.
void WriteDataset(hid_t location, const std::string& name, const double* data,
                  const std::vector<hsize_t>& dimensions, const std::string& units);

// Creates "<path>.tmp", calls `write` with the open file, closes (flushes) it and renames it to
// `path`. HDF5's own error printing is off meanwhile. On any failure the temporary file is removed
// and InputError({path}, "cannot write <what> (<reason>)") thrown.
void WriteFileAtomically(const std::string& path, const std::string& what,
                         const std::function<void(hid_t file)>& write);

}  // namespace isolab::io::hdf5
