// The one HDF5 writer: UTF-8 strings h5py reads as str, int64 integers, and Rows, the chunked
// datasets a run will stream its histories into, read back through the HDF5 C API.
#include "isolab/io/hdf5_file.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "leftover_temporaries.h"
#include "own_test_file.h"

namespace isolab::io {
namespace {

std::filesystem::path FreshFile(const std::string& name) { return testing::OwnTestFile(name); }

std::vector<hsize_t> Dimensions(hid_t dataset) {
  const hid_t space = H5Dget_space(dataset);
  std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  return dims;
}

TEST(Hdf5File, RowsGrowAsTheyAreAppended) {
  const auto path = FreshFile("rows.h5");
  {
    Hdf5File file(path.string());
    file.CreateGroup("history");
    {
      Hdf5File::Rows matrix = file.CreateRows("history/matrix", 3, "mm", 2);
      Hdf5File::Rows vector = file.CreateRows("history/vector", 0, "s", 0);
      matrix.Append(std::vector<double>{1, 2, 3});
      matrix.Append(std::vector<double>{4, 5, 6, 7, 8, 9, 10, 11, 12});
      EXPECT_EQ(matrix.rows(), 4u);
      for (int k = 0; k < 5; ++k) vector.Append(std::vector<double>{0.5 * k});
      // Misuse by isolab's own code, not bad input: internal errors.
      EXPECT_THROW(matrix.Append(std::vector<double>{1, 2}), std::logic_error);  // not whole rows
      // Commit with a Rows still open would leave the file open: refused.
      EXPECT_THROW(file.Commit(), std::logic_error);
    }
  }
  EXPECT_FALSE(std::filesystem::exists(path));  // the failed commit wrote nothing
  EXPECT_TRUE(testing::LeftoverTemporaries(path).empty());

  {
    Hdf5File file(path.string());
    file.CreateGroup("history");
    {
      Hdf5File::Rows matrix = file.CreateRows("history/matrix", 3, "mm", 2);
      matrix.Append(std::vector<double>{1, 2, 3});
      matrix.Append(std::vector<double>{4, 5, 6, 7, 8, 9, 10, 11, 12});
    }
    file.Commit();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t dataset = H5Dopen2(file, "history/matrix", H5P_DEFAULT);
  EXPECT_EQ(Dimensions(dataset), (std::vector<hsize_t>{4, 3}));
  const hid_t create = H5Dget_create_plist(dataset);
  EXPECT_EQ(H5Pget_layout(create), H5D_CHUNKED);
  H5Pclose(create);
  std::vector<double> values(12);
  H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  EXPECT_EQ(values, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
  H5Dclose(dataset);
  H5Fclose(file);
}

// Rows expected from the start are the dataset's extent while it is written; Close trims it to the
// rows appended (fewer: a run that stopped early), and appending past it extends it.
TEST(Hdf5File, CloseTrimsTheExpectedRowsToTheRowsAppended) {
  const auto path = FreshFile("expected_rows.h5");
  const std::vector<double> values{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};  // 7 rows of 2
  {
    Hdf5File file(path.string());
    {
      Hdf5File::Rows fewer = file.CreateRows("fewer", 2, "mm", 3, /*expected_rows=*/12);
      fewer.Append(std::span<const double>(values).first(6));
      const std::vector<double> last{7, 8, 0, 0, 0, 0};  // 1 row and 2 of padding
      fewer.AppendLastChunk(last, 1);
      fewer.Close();
      fewer.Close();  // once closed, nothing more to do
      Hdf5File::Rows more = file.CreateRows("more", 2, "mm", 2, /*expected_rows=*/4);
      more.Append(std::span<const double>(values).first(8));
      more.Append(std::span<const double>(values).subspan(8, 4));
      more.Append(std::span<const double>(values).subspan(12, 2));
      more.Close();
      Hdf5File::Rows none = file.CreateRows("none", 0, "s", 5, /*expected_rows=*/10);
      none.Close();
    }
    file.Commit();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  // The dimensions, and the values as many as they hold.
  const auto read = [&](const char* name) {
    const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
    const std::vector<hsize_t> dims = Dimensions(dataset);
    std::vector<double> data(dims.empty() ? 0 : dims[0] * (dims.size() > 1 ? dims[1] : 1));
    if (!data.empty()) {
      H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
    }
    H5Dclose(dataset);
    return std::make_pair(dims, data);
  };
  const auto [fewer_dims, fewer] = read("fewer");
  EXPECT_EQ(fewer_dims, (std::vector<hsize_t>{4, 2}));
  EXPECT_EQ(fewer, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}));
  const auto [more_dims, more] = read("more");
  EXPECT_EQ(more_dims, (std::vector<hsize_t>{7, 2}));
  EXPECT_EQ(more, values);
  EXPECT_EQ(read("none").first, (std::vector<hsize_t>{0}));
  H5Fclose(file);
}

// A stream's last, part-filled chunk handed over whole with its padding: the dataset ends at
// the rows given, and reads the same as the rows appended one by one through HDF5's own path.
TEST(Hdf5File, TheLastChunkGoesWholeAndTheDatasetEndsAtItsRows) {
  const std::vector<double> rows{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};  // 5 rows of 2
  const auto whole = FreshFile("last_chunk.h5");
  const auto by_rows = FreshFile("by_rows.h5");
  {
    Hdf5File file(whole.string());
    {
      Hdf5File::Rows matrix = file.CreateRows("matrix", 2, "mm", 3);
      matrix.Append(std::span<const double>(rows).first(6));
      const std::vector<double> last{7, 8, 9, 10, 0, 0};  // 2 rows and 1 of padding
      // Misuse by isolab's own code: not a whole chunk, or more rows than it holds.
      EXPECT_THROW(matrix.AppendLastChunk(std::span<const double>(last).first(4), 2),
                   std::logic_error);
      EXPECT_THROW(matrix.AppendLastChunk(last, 4), std::logic_error);
      matrix.AppendLastChunk(last, 2);
      EXPECT_EQ(matrix.rows(), 5u);
      // Nothing follows the last chunk.
      EXPECT_THROW(matrix.AppendLastChunk(last, 1), std::logic_error);
    }
    file.Commit();
  }
  {
    Hdf5File file(by_rows.string());
    {
      Hdf5File::Rows matrix = file.CreateRows("matrix", 2, "mm", 3);
      for (std::size_t r = 0; r < 5; ++r)
        matrix.Append(std::span<const double>(rows).subspan(2 * r, 2));
    }
    file.Commit();
  }
  for (const auto& path : {whole, by_rows}) {
    SCOPED_TRACE(path.filename().string());
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    const hid_t dataset = H5Dopen2(file, "matrix", H5P_DEFAULT);
    EXPECT_EQ(Dimensions(dataset), (std::vector<hsize_t>{5, 2}));
    std::vector<double> values(10);
    H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    EXPECT_EQ(values, rows);
    H5Dclose(dataset);
    H5Fclose(file);
  }
}

TEST(Hdf5File, TextIsUtf8AndIntegersAreIntegers) {
  const auto path = FreshFile("types.h5");
  {
    Hdf5File file(path.string());
    const std::vector<std::string> names = {"base", "floor 1", "étage 2"};
    file.WriteStrings("names", {names.size()}, names);
    file.WriteIntegers("counts", {2}, std::vector<std::int64_t>{3, 5'000'000'000});
    file.WriteText("text", "units: {force: kN}\n");
    file.WriteAttribute("/", "record", "El Centro");
    file.WriteIntegerAttribute("/", "steps", 6000);
    file.WriteStringsAttribute("names", "columns", names);
    file.WriteStringsAttribute("/", "none", {});  // an empty list is written, not refused
    file.Commit();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  // A string array: fixed length, the longest's bytes ("étage 2" is 8), the shorter null-padded.
  const hid_t names = H5Dopen2(file, "names", H5P_DEFAULT);
  const hid_t type = H5Dget_type(names);
  EXPECT_EQ(H5Tis_variable_str(type), 0);
  EXPECT_EQ(H5Tget_cset(type), H5T_CSET_UTF8);
  EXPECT_EQ(H5Tget_strpad(type), H5T_STR_NULLPAD);
  ASSERT_EQ(H5Tget_size(type), 8u);
  std::string read(3 * 8, 'x');
  H5Dread(names, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, read.data());
  EXPECT_EQ(read, std::string("base\0\0\0\0floor 1\0étage 2", 24));
  H5Tclose(type);
  H5Dclose(names);

  const hid_t counts = H5Dopen2(file, "counts", H5P_DEFAULT);
  const hid_t count_type = H5Dget_type(counts);
  EXPECT_EQ(H5Tget_class(count_type), H5T_INTEGER);
  EXPECT_EQ(H5Tget_size(count_type), 8u);
  std::int64_t values[2];
  H5Dread(counts, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values);
  EXPECT_EQ(values[1], 5'000'000'000);
  H5Tclose(count_type);
  H5Dclose(counts);

  const hid_t text = H5Dopen2(file, "text", H5P_DEFAULT);
  const hid_t text_type = H5Dget_type(text);
  EXPECT_EQ(H5Tget_cset(text_type), H5T_CSET_UTF8);
  std::string value(H5Tget_size(text_type), '\0');
  H5Dread(text, text_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.data());
  EXPECT_EQ(value, "units: {force: kN}\n");
  H5Tclose(text_type);
  H5Dclose(text);

  const hid_t steps = H5Aopen(file, "steps", H5P_DEFAULT);
  const hid_t steps_type = H5Aget_type(steps);
  EXPECT_EQ(H5Tget_class(steps_type), H5T_INTEGER);
  H5Tclose(steps_type);
  H5Aclose(steps);
  const hid_t record = H5Aopen(file, "record", H5P_DEFAULT);
  const hid_t record_type = H5Aget_type(record);
  EXPECT_GT(H5Tis_variable_str(record_type), 0);
  EXPECT_EQ(H5Tget_cset(record_type), H5T_CSET_UTF8);
  H5Tclose(record_type);
  H5Aclose(record);
  H5Fclose(file);
}

}  // namespace
}  // namespace isolab::io
