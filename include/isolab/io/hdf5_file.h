// A small writer of HDF5 files for tables and summaries: datasets of doubles, integers and
// strings with a "units" attribute, groups, attributes. The file appears whole or not at all: it
// is written under "<path>.tmp" and renamed by Commit(); destroyed without Commit, the temporary
// file is removed. HDF5's own headers stay inside io.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace isolab::io {

class Hdf5File {
 public:
  // `reproducible`: objects carry no creation or modification times, so the same contents give
  // the same bytes (a summary can then be compared file to file). Throws InputError when the
  // file cannot be created.
  Hdf5File(std::string path, bool reproducible);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  // Names are paths from the root ("mean/base_shear"); groups must be created before use.
  void CreateGroup(const std::string& name);
  // Row-major data with dimensions `dims` (product = data.size()); empty units: no attribute.
  void WriteDoubles(const std::string& name, std::span<const std::size_t> dims,
                    std::span<const double> data, const std::string& units);
  void WriteIntegers(const std::string& name, std::span<const std::size_t> dims,
                     std::span<const std::int32_t> data);
  // Fixed-length strings, as long as the longest value.
  void WriteStrings(const std::string& name, std::span<const std::size_t> dims,
                    std::span<const std::string> values);
  // Attributes of the object `object` ("/" for the file, or a dataset or group name).
  void WriteAttribute(const std::string& object, const std::string& name, const std::string& value);
  void WriteAttribute(const std::string& object, const std::string& name, double value);

  // Closes (flushes) the file and renames it to its final path. Throws InputError on failure.
  void Commit();

 private:
  struct Impl;  // HDF5 identifiers
  std::unique_ptr<Impl> impl_;
};

}  // namespace isolab::io
