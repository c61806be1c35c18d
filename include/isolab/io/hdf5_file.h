// isolab's one HDF5 writer: results of runs, spectra and study summaries all go through it, so
// every file reads the same way from Python (h5py) or any HDF5 tool:
//  * numbers as float64 or int64 datasets, each with a "units" attribute where it has units;
//  * text as UTF-8 strings (h5py returns str for attributes, and for datasets through
//    .asstr()): variable-length in attributes, fixed-length (null-padded to the longest) in
//    datasets;
//  * column names of a 2-D dataset as a "columns" attribute (an array of strings);
//  * numbers written whole (WriteDoubles: contiguous, the cheapest), or as chunked datasets whose
//    first dimension grows as rows are appended (Rows), so a run can stream its output instead
//    of holding it all in memory.
// Objects carry no creation or modification times: the same contents give the same bytes.
// The file is an AtomicFile (atomic_file.h): written under a unique temporary name beside the
// target and renamed by Commit(); destroyed without Commit, nothing is left. HDF5's own headers
// stay inside io.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace isolab::io {

class Hdf5File {
 public:
  class Rows;

  // Throws InputError when the path cannot be an output (atomic_file.h) or the file cannot be
  // created.
  explicit Hdf5File(std::string path);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  // Names are paths from the root ("mean/base_shear"); groups must be created before use.
  void CreateGroup(const std::string& name);

  // Row-major data with dimensions `dims` (product = data.size(); {} for a scalar). Empty units:
  // no "units" attribute.
  void WriteDoubles(const std::string& name, const std::vector<std::size_t>& dims,
                    std::span<const double> data, const std::string& units);
  void WriteIntegers(const std::string& name, const std::vector<std::size_t>& dims,
                     std::span<const std::int64_t> data, const std::string& units = "");
  void WriteStrings(const std::string& name, const std::vector<std::size_t>& dims,
                    std::span<const std::string> values);
  // A scalar string dataset, for text of any length (attributes stop near 64 KiB).
  void WriteText(const std::string& name, const std::string& value);

  // Attributes of `object` ("/" for the file, or a dataset or group name).
  void WriteAttribute(const std::string& object, const std::string& name, const std::string& value);
  void WriteAttribute(const std::string& object, const std::string& name, double value);
  void WriteIntegerAttribute(const std::string& object, const std::string& name,
                             std::int64_t value);
  void WriteStringsAttribute(const std::string& object, const std::string& name,
                             std::span<const std::string> values);
  void WriteDoublesAttribute(const std::string& object, const std::string& name,
                             std::span<const double> values);

  // A float64 dataset of `columns` columns (0: a vector) whose rows are appended, stored in chunks
  // of `chunk_rows` rows (at least one). Appending whole chunks at a chunk's start writes them
  // straight through: HDF5 neither fills a new chunk first nor reads one back. `expected_rows`,
  // where the writer knows them (a run's length), are the dataset's extent from the start, so
  // that appending within them changes no extent (each change costs HDF5 some 3,000
  // instructions); Rows::Close trims it to the rows appended.
  Rows CreateRows(const std::string& name, std::size_t columns, const std::string& units,
                  std::size_t chunk_rows, std::size_t expected_rows = 0);

  // Closes (flushes) the file and renames it to its path. Every Rows must be gone by then.
  // Throws InputError on failure.
  void Commit();

 private:
  struct Impl;  // HDF5 identifiers
  std::unique_ptr<Impl> impl_;
};

// An extendable dataset of rows; appending writes through to the file.
class Hdf5File::Rows {
 public:
  ~Rows();
  Rows(Rows&& other) noexcept;
  Rows(const Rows&) = delete;
  Rows& operator=(const Rows&) = delete;
  Rows& operator=(Rows&&) = delete;

  // Whole rows, row-major: values.size() is a multiple of the column count (1 for a vector).
  // Whole chunks go to the file as they are (HDF5's direct chunk write: no chunk cache, no
  // fill, no copy but the file's).
  void Append(std::span<const double> values);
  // A stream's last `rows` rows, at most a chunk's, at a chunk's start: `chunk` is a whole
  // chunk whose rows past `rows` are padding (zeros, from the caller). Written straight to the
  // file like a whole chunk, where Append would have HDF5 allocate, fill and copy a chunk of its
  // own (HDF5 stores an edge chunk whole either way).
  void AppendLastChunk(std::span<const double> chunk, std::size_t rows);
  std::size_t rows() const { return rows_; }
  // The dataset's extent made the rows appended (fewer than expected: a run that stopped early),
  // and the dataset closed. Throws InputError on failure. A Rows destroyed without Close keeps
  // the extent it had: for a file that will not be committed.
  void Close();

 private:
  friend class Hdf5File;
  Rows(const Hdf5File::Impl* file, std::int64_t dataset, std::string name, std::size_t columns,
       std::size_t chunk_rows, std::size_t extent);
  void Extend(std::size_t added);
  void SetExtent(std::size_t rows);
  void WriteChunk(std::size_t first_row, std::span<const double> chunk);

  const Hdf5File::Impl* file_;
  std::int64_t dataset_;  // an HDF5 hid_t
  std::string name_;
  std::size_t columns_;  // 0: a vector
  std::size_t chunk_rows_;
  std::size_t rows_ = 0;
  std::size_t extent_ = 0;  // the dataset's rows: rows_ or more
};

}  // namespace isolab::io
