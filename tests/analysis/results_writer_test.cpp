// Results streamed while the run advances (results_writer.h, solve.h's Solve)
// against the same run held in memory (ResponseHistory): the datasets equal bit for bit through
// buffer boundaries, every N-th row is the in-memory run's row N k, peaks with output every 10
// steps equal the full run's (and differ from peaks read off the thinned history), summary-only
// files hold the peaks and final energies alone, levels and quantities pick the columns, CSV
// follows the selection, and an abandoned writer leaves nothing behind.
#include "results_writer.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/result_series.h"
#include "isolab/analysis/results_file.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/model/model_file.h"
#include "leftover_temporaries.h"
#include "own_test_file.h"

namespace isolab::analysis {
namespace {

using integrators::ResponseHistory;

std::string Model(const std::string& relative) {
  return std::string(ISOLAB_SOURCE_DIR) + "/models/" + relative;
}

// Under a folder of the running test's own, since ctest runs the tests of this file in parallel.
std::filesystem::path TemporaryFile(const std::string& name) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string folder = std::string(test->test_suite_name()) + "." + test->name();
  std::replace(folder.begin(), folder.end(), '/', '_');
  const auto directory = isolab::testing::OwnTestDirectory() / folder;
  std::filesystem::create_directories(directory);
  const auto path = directory / name;
  std::filesystem::remove(path);
  return path;
}

// A dataset's values (row-major) and dimensions; empty dimensions and values when it is absent.
struct Dataset {
  std::vector<hsize_t> dims;
  std::vector<double> values;
};

Dataset Read(hid_t file, const std::string& name) {
  Dataset data;
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) return data;
  const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(dataset);
  data.dims.resize(H5Sget_simple_extent_ndims(space));
  H5Sget_simple_extent_dims(space, data.dims.data(), nullptr);
  data.values.resize(H5Sget_simple_extent_npoints(space));
  H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.values.data());
  H5Sclose(space);
  H5Dclose(dataset);
  return data;
}

long IntegerAttribute(hid_t file, const char* name) {
  long value = -1;
  const hid_t attribute = H5Aopen(file, name, H5P_DEFAULT);
  H5Aread(attribute, H5T_NATIVE_LONG, &value);
  H5Aclose(attribute);
  return value;
}

// The in-memory response, rows `stride` apart, one column per `columns` entry (every column
// when empty), row-major: what a thinned, column-selected dataset must hold.
std::vector<double> Expected(const integrators::RowMatrix& matrix, int rows, int stride,
                             std::vector<int> columns = {}) {
  if (columns.empty()) {
    for (int c = 0; c < matrix.cols(); ++c) columns.push_back(c);
  }
  std::vector<double> values;
  for (int r = 0; r < rows; r += stride) {
    for (const int c : columns) values.push_back(matrix(r, c));
  }
  return values;
}

template <typename Value>
std::vector<double> ExpectedVector(int rows, int stride, Value value) {
  std::vector<double> values;
  for (int r = 0; r < rows; r += stride) values.push_back(value(r));
  return values;
}

// A run kept whole in memory: its summary and peaks.
Summary RunInMemory(const model::AnalysisSection& analysis, const Problem& problem,
                    ResponseHistory* history) {
  integrators::HistoryRecorder recorder =
      integrators::RecordHistory(problem.structure, problem.grid, history);
  integrators::ResponseObserver* const also[] = {&recorder};
  SolveOptions options;
  options.analysis = analysis;
  options.output.summary_only = true;
  return Solve(options, problem, also);
}

// A run streamed to `path` (none when empty) as `selection` asks.
Summary RunAndRecord(const model::AnalysisSection& analysis, const Problem& problem,
                     const model::OutputSelection& selection, const std::string& path,
                     std::size_t buffer_rows = 0) {
  SolveOptions options;
  options.analysis = analysis;
  options.output = selection;
  options.results_path = path;
  options.version = "test";
  options.buffer_rows = buffer_rows;
  return Solve(options, problem);
}

// Bitwise: the same doubles, not merely close ones.
void ExpectBitwiseEqual(const std::vector<double>& actual, const std::vector<double>& expected,
                        const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  EXPECT_EQ(std::memcmp(actual.data(), expected.data(), actual.size() * sizeof(double)), 0) << what;
}

struct Case {
  const char* model;
  bool ida;
};

class StreamedAgainstInMemory : public ::testing::TestWithParam<Case> {};

// Every history of the file, streamed through a 7-row buffer (so that many flushes and a partial
// last one happen), equals the in-memory run's; with every 10 steps, its rows 0, 10, 20, ...
TEST_P(StreamedAgainstInMemory, DatasetsAreBitwiseEqual) {
  const model::ModelFile model = model::LoadModelFile(Model(GetParam().model));
  const Problem setup = Prepare(model, {});
  model::AnalysisSection analysis = model.analysis;
  if (GetParam().ida) analysis.integrator = model::AnalysisSection::Integrator::kIda;
  ResponseHistory history;
  const integrators::RunSummary in_memory = RunInMemory(analysis, setup, &history).run;
  ASSERT_TRUE(in_memory.ok());
  const int rows = history.rows_written;
  ASSERT_GT(rows, 100);

  for (const int every : {1, 10}) {
    SCOPED_TRACE(every);
    model::OutputSelection selection;
    selection.every = every;
    const auto path = TemporaryFile("streamed.h5");
    const Summary run = RunAndRecord(analysis, setup, selection, path.string(), /*buffer_rows=*/7);
    EXPECT_EQ(run.run.newton_iterations, in_memory.newton_iterations);
    EXPECT_EQ(run.run.energy_balance_error, in_memory.energy_balance_error);

    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_EQ(IntegerAttribute(file, "output_every"), every);
    const int expected_rows = (rows - 1) / every + 1;
    EXPECT_EQ(Read(file, "time").dims, std::vector<hsize_t>{hsize_t(expected_rows)});
    ExpectBitwiseEqual(Read(file, "time").values,
                       ExpectedVector(rows, every, [&](int r) { return history.time[r]; }), "time");
    ExpectBitwiseEqual(Read(file, "displacement").values,
                       Expected(history.displacement, rows, every), "displacement");
    ExpectBitwiseEqual(Read(file, "velocity").values, Expected(history.velocity, rows, every),
                       "velocity");
    ExpectBitwiseEqual(Read(file, "acceleration").values,
                       Expected(history.acceleration, rows, every), "acceleration");
    ExpectBitwiseEqual(Read(file, "absolute_acceleration").values,
                       Expected(history.absolute_acceleration, rows, every),
                       "absolute_acceleration");
    ExpectBitwiseEqual(Read(file, "connection_force").values,
                       Expected(history.connection_force, rows, every), "connection_force");
    if (setup.layout.isolated()) {
      const int isolation = setup.layout.isolators[0].slot;
      const int first = static_cast<int>(setup.structure.slot_law_offset(isolation));
      const int count =
          static_cast<int>(setup.structure.members()[isolation].assembly.components().size());
      std::vector<int> components;
      for (int l = first; l < first + count; ++l) components.push_back(l);
      ExpectBitwiseEqual(Read(file, "isolator/component_force").values,
                         Expected(history.law_force, rows, every, components),
                         "isolator/component_force");
    }
    ExpectBitwiseEqual(
        Read(file, "energy/hysteretic").values,
        ExpectedVector(rows, every, [&](int r) { return history.energies[r].hysteretic; }),
        "energy/hysteretic");
    ExpectBitwiseEqual(
        Read(file, "energy/input").values,
        ExpectedVector(rows, every, [&](int r) { return history.energies[r].input; }),
        "energy/input");
    H5Fclose(file);
    EXPECT_TRUE(testing::LeftoverTemporaries(path).empty());
  }
}

INSTANTIATE_TEST_SUITE_P(BundledModels, StreamedAgainstInMemory,
                         ::testing::Values(Case{"buildings/five_story_table9.yaml", false},
                                           Case{"chopra/case_e_five_story_frame.yaml", false},
                                           Case{"sdof/table7_thm1_hard.yaml", true}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name =
                               std::filesystem::path(info.param.model).stem().string();
                           return name + (info.param.ida ? "_ida" : "_newmark");
                         });

struct SelectionCase {
  const char* model;
  int every;
  std::vector<int> levels;  // empty: every level
  bool ida = false;
};

void PrintTo(const SelectionCase& c, std::ostream* out) {
  *out << c.model << ", every " << c.every << ", " << c.levels.size() << " levels"
       << (c.ida ? ", IDA" : "");
}

// The rows of a results CSV, as numbers.
std::vector<std::vector<double>> CsvRows(const std::filesystem::path& path, std::string* header) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::vector<double>> rows;
  header->clear();
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header->empty()) {
      *header = line;
      continue;
    }
    std::vector<double> row;
    std::size_t start = 0;
    while (start <= line.size()) {
      const std::size_t comma = std::min(line.find(',', start), line.size());
      row.push_back(std::stod(line.substr(start, comma - start)));
      start = comma + 1;
    }
    rows.push_back(row);
  }
  return rows;
}

// Bitwise, NaN (an axial load not given) equal to NaN.
bool SameBits(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}

class EveryHistory : public ::testing::TestWithParam<SelectionCase> {};

// Every history of a file is its series' fill of the in-memory run's rows, bit for bit: streamed
// through buffers of 7 rows to HDF5 and to CSV, and held (a study's files, every row). For
// structures of every kind (an SDOF, a fixed-base frame, a one-direction building, buildings in
// plan with coupled bearings, torsion and axial loads), both integrators, and selections whose
// arrays the writer stages whole, gathers columns from, or fills from the row (a roof level
// alone). The deformations, drift ratios and twists are also checked against the structure's own
// (Structure::SlotDeformation, MemberDeformation), computed apart from the series' description.
TEST_P(EveryHistory, IsItsSeriesFillOfTheRows) {
  const SelectionCase& param = GetParam();
  const model::ModelFile model = model::LoadModelFile(Model(param.model));
  Problem setup = Prepare(model, {});
  setup.grid.steps = std::min(setup.grid.steps, 400);
  model::AnalysisSection analysis = model.analysis;
  if (param.ida) analysis.integrator = model::AnalysisSection::Integrator::kIda;
  ResponseHistory history;
  const Summary in_memory = RunInMemory(analysis, setup, &history);
  const int rows = history.rows_written;
  ASSERT_GT(rows, 100);

  model::OutputSelection selection;
  selection.every = param.every;
  selection.levels = param.levels;
  const std::vector<Series> series = ResultSeries(setup, selection);
  ASSERT_FALSE(series.empty());
  // A series that is an array of the row whole (WholeArray: the writer stores it as that array's
  // rows, the Python module views the history's matrix) is that array, row by row. Every level
  // of a structure without rotations gives the displacements whole; a choice of levels, or a
  // plan's rotations (a series of their own), leave them not whole.
  for (const Series& s : series) {
    const std::optional<RowArray> whole = WholeArray(s, setup.structure);
    if (!whole) continue;
    EXPECT_NE(*whole, RowArray::kScalars) << s.name;
    std::vector<double> filled_row(s.width());
    for (int r = 0; r < rows; ++r) {
      const integrators::ResponseRow row = history.Row(r);
      s.fill(row, filled_row.data());
      const RowArrays arrays(row);
      ExpectBitwiseEqual(filled_row, {arrays[*whole], arrays[*whole] + s.width()},
                         s.name + " as its whole array, row " + std::to_string(r));
    }
  }
  const auto displacement = std::find_if(series.begin(), series.end(),
                                         [](const Series& s) { return s.name == "displacement"; });
  ASSERT_NE(displacement, series.end());
  EXPECT_EQ(WholeArray(*displacement, setup.structure).has_value(),
            param.levels.empty() && !setup.layout.rotations);
  // Each series' fill of every `every`-th row.
  const auto filled = [&](const Series& s, int every) {
    std::vector<double> values, row_values(s.width());
    for (int r = 0; r < rows; r += every) {
      std::fill(row_values.begin(), row_values.end(), -1.0);
      s.fill(history.Row(r), row_values.data());
      values.insert(values.end(), row_values.begin(), row_values.end());
    }
    return values;
  };

  const auto streamed = TemporaryFile("streamed.h5");
  const auto csv = TemporaryFile("streamed.csv");
  const auto held = TemporaryFile("held.h5");
  RunAndRecord(analysis, setup, selection, streamed.string(), /*buffer_rows=*/7);
  RunAndRecord(analysis, setup, selection, csv.string(), /*buffer_rows=*/7);
  WriteResultsFile(held.string(),
                   {&setup, &analysis, &in_memory.run, &in_memory.peaks, "test", selection},
                   history);
  const hid_t file = H5Fopen(streamed.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t held_file = H5Fopen(held.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(held_file, 0);
  std::vector<std::vector<double>> expected;  // per series
  for (const Series& s : series) {
    expected.push_back(filled(s, param.every));
    ExpectBitwiseEqual(Read(file, s.name).values, expected.back(), s.name);
    ExpectBitwiseEqual(Read(held_file, s.name).values, filled(s, 1), s.name + " (held)");
  }
  std::string header;
  const std::vector<std::vector<double>> csv_rows = CsvRows(csv, &header);
  ASSERT_EQ(csv_rows.size(), std::size_t((rows - 1) / param.every + 1));
  for (std::size_t r = 0; r < csv_rows.size(); ++r) {
    std::size_t column = 0;
    for (std::size_t k = 0; k < series.size(); ++k) {
      for (std::size_t c = 0; c < series[k].width(); ++c, ++column) {
        ASSERT_LT(column, csv_rows[r].size());
        EXPECT_TRUE(SameBits(csv_rows[r][column], expected[k][r * series[k].width() + c]))
            << series[k].name << " row " << r << " column " << c;
      }
    }
    EXPECT_EQ(column, csv_rows[r].size());
  }

  const structure::Structure& structure = setup.structure;
  const structure::Layout& layout = setup.layout;
  if (layout.isolated()) {
    std::vector<double> deformations;
    for (int r = 0; r < rows; r += param.every) {
      for (const structure::IsolatorLayout& isolator : layout.isolators) {
        const hysteresis::Vec2 u =
            structure.SlotDeformation(isolator.slot, history.Row(r).displacement);
        deformations.push_back(u.x);
        if (structure.slot_width(isolator.slot) == 2) deformations.push_back(u.y);
      }
    }
    ExpectBitwiseEqual(Read(file, "isolator/displacement").values, deformations,
                       "isolator/displacement against SlotDeformation");
  }
  if (param.levels.empty() && !layout.stories.empty()) {
    std::vector<double> drifts, ratios, twists;
    for (int r = 0; r < rows; r += param.every) {
      const std::span<const double> u = history.Row(r).displacement;
      for (const structure::StoryLayout& story : layout.stories) {
        for (int d = 0; d < layout.directions; ++d) {
          if (story.members[d] < 0) continue;
          const double drift = structure.MemberDeformation(story.members[d], u);
          drifts.push_back(drift);
          ratios.push_back(100.0 / story.height * drift);
        }
        if (story.members[structure::kRotation] >= 0) {
          twists.push_back(structure.MemberDeformation(story.members[structure::kRotation], u));
        }
      }
    }
    ExpectBitwiseEqual(Read(file, "story/drift").values, drifts,
                       "story/drift against MemberDeformation");
    if (layout.stories[0].height > 0.0) {
      ExpectBitwiseEqual(Read(file, "story/drift_ratio").values, ratios,
                         "story/drift_ratio against MemberDeformation");
    }
    if (!twists.empty()) {
      ExpectBitwiseEqual(Read(file, "story/twist").values, twists,
                         "story/twist against MemberDeformation");
    }
  }
  H5Fclose(held_file);
  H5Fclose(file);
}

INSTANTIATE_TEST_SUITE_P(
    Structures, EveryHistory,
    ::testing::Values(SelectionCase{"sdof/table7_thm1_hard.yaml", 1, {}},
                      SelectionCase{"sdof/table7_thm1_hard.yaml", 2, {}, /*ida=*/true},
                      SelectionCase{"chopra/case_e_five_story_frame.yaml", 1, {}},
                      SelectionCase{
                          "chopra/case_e_five_story_frame.yaml", 1, {1, model::kRoofLevel}},
                      SelectionCase{"buildings/five_story_table9.yaml", 1, {}},
                      SelectionCase{"buildings/five_story_table9.yaml", 3, {model::kRoofLevel}},
                      SelectionCase{"plan/five_story_fp_plan.yaml", 1, {}},
                      SelectionCase{"design/four_story_tfp_plan.yaml", 2, {}}),
    [](const ::testing::TestParamInfo<SelectionCase>& info) {
      std::string name = std::filesystem::path(info.param.model).stem().string() + "_every" +
                         std::to_string(info.param.every);
      if (!info.param.levels.empty()) name += "_levels";
      if (info.param.ida) name += "_ida";
      return name;
    });

// A streamed run longer than its buffer is written in chunks of equal size that tile its rows:
// the file's last chunk, stored whole by HDF5, holds fewer padding rows than there are chunks
// (chunks of the buffer's size would leave up to a whole chunk of them), and its padding is zeros
// (the file's bytes depend on nothing but the run).
TEST(ResultsWriter, StreamedChunksTileTheRun) {
  const model::ModelFile model = model::LoadModelFile(Model("buildings/five_story_table9.yaml"));
  const Problem setup = Prepare(model, {});
  constexpr std::size_t kBufferRows = 1000;
  const auto path = TemporaryFile("tiled.h5");
  const Summary run = RunAndRecord(model.analysis, setup, {}, path.string(), kBufferRows);
  ASSERT_TRUE(run.run.ok());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const Dataset displacement = Read(file, "displacement");
  ASSERT_EQ(displacement.dims.size(), 2u);
  const hsize_t rows = displacement.dims[0], columns = displacement.dims[1];
  ASSERT_GT(rows, 3 * kBufferRows);
  const hid_t dataset = H5Dopen2(file, "displacement", H5P_DEFAULT);
  const hid_t create = H5Dget_create_plist(dataset);
  hsize_t chunk[2] = {0, 0};
  ASSERT_EQ(H5Pget_chunk(create, 2, chunk), 2);
  EXPECT_LE(chunk[0], kBufferRows);
  const hsize_t chunks = (rows + chunk[0] - 1) / chunk[0];
  EXPECT_LT(chunks * chunk[0] - rows, chunks) << "rows " << rows << ", chunks of " << chunk[0];

  // The last chunk as the file stores it: the run's last rows, then zeros.
  std::vector<double> last(chunk[0] * columns, -1.0);
  const hsize_t offset[2] = {(chunks - 1) * chunk[0], 0};
  std::uint32_t filters = 0;
  ASSERT_GE(H5Dread_chunk(dataset, H5P_DEFAULT, offset, &filters, last.data()), 0);
  const std::size_t kept = (rows - offset[0]) * columns;
  EXPECT_TRUE(std::equal(last.begin(), last.begin() + static_cast<std::ptrdiff_t>(kept),
                         displacement.values.end() - static_cast<std::ptrdiff_t>(kept)));
  EXPECT_TRUE(std::all_of(last.begin() + static_cast<std::ptrdiff_t>(kept), last.end(),
                          [](double v) { return v == 0.0; }));
  H5Pclose(create);
  H5Dclose(dataset);
  H5Fclose(file);
}

void ExpectSamePeak(const Peak& a, const Peak& b, const char* what) {
  EXPECT_EQ(a.value, b.value) << what;
  EXPECT_EQ(a.time, b.time) << what;
  EXPECT_EQ(a.index, b.index) << what;
}

// Peaks, the residual and the energies see every step whatever is written: with every 10 steps
// they are the full run's, exactly; read off a history thinned to every 10th step they are not.
TEST(ResultsWriter, PeaksWithOutputEveryTenStepsEqualTheFullRuns) {
  const model::ModelFile model = model::LoadModelFile(Model("buildings/five_story_table9.yaml"));
  const Problem setup = Prepare(model, {});
  const Summary full = RunAndRecord(model.analysis, setup, {}, "");
  model::OutputSelection every_ten;
  every_ten.every = 10;
  const auto path = TemporaryFile("every_ten.h5");
  const Summary thinned = RunAndRecord(model.analysis, setup, every_ten, path.string());
  const ResponsePeaks &a = full.peaks, &b = thinned.peaks;
  ExpectSamePeak(a.isolator_displacement, b.isolator_displacement, "isolator displacement");
  ExpectSamePeak(a.isolator_force, b.isolator_force, "isolator force");
  ExpectSamePeak(a.base_shear, b.base_shear, "base shear");
  ExpectSamePeak(a.first_story_shear, b.first_story_shear, "first-story shear");
  ExpectSamePeak(a.roof_absolute_acceleration, b.roof_absolute_acceleration, "roof acceleration");
  ExpectSamePeak(a.story_drift, b.story_drift, "story drift");
  EXPECT_EQ(a.residual_isolator_displacement, b.residual_isolator_displacement);
  EXPECT_EQ(a.residual_oscillation, b.residual_oscillation);
  EXPECT_EQ(a.energies.input, b.energies.input);
  EXPECT_EQ(a.energies.hysteretic, b.energies.hysteretic);
  EXPECT_EQ(full.run.energy_balance_error, thinned.run.energy_balance_error);
  EXPECT_EQ(a.rows, setup.grid.steps + 1);

  // The full run's peaks are those of the in-memory history (the definition ComputePeaks keeps).
  ResponseHistory history;
  RunInMemory(model.analysis, setup, &history);
  const ResponsePeaks from_history = ComputePeaks(setup, history);
  ExpectSamePeak(a.isolator_displacement, from_history.isolator_displacement, "from history");
  ExpectSamePeak(a.roof_absolute_acceleration, from_history.roof_absolute_acceleration,
                 "from history");
  EXPECT_EQ(a.residual_isolator_displacement, from_history.residual_isolator_displacement);

  // What this guards against: peaks of the thinned history miss the true ones.
  Problem coarse = setup;
  coarse.grid.output_every = 10;
  ResponseHistory thinned_history;
  RunInMemory(model.analysis, coarse, &thinned_history);
  const ResponsePeaks missed = ComputePeaks(coarse, thinned_history);
  EXPECT_LT(missed.roof_absolute_acceleration.value, a.roof_absolute_acceleration.value);
  EXPECT_LT(missed.story_drift.value, a.story_drift.value);

  // And the file carries the full run's peaks.
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(Read(file, "peaks/roof_absolute_acceleration").values,
            std::vector<double>{a.roof_absolute_acceleration.value});
  H5Fclose(file);
}

TEST(ResultsWriter, SummaryOnlyHoldsPeaksAndFinalEnergiesWithoutHistories) {
  const model::ModelFile model = model::LoadModelFile(Model("buildings/five_story_table9.yaml"));
  const Problem setup = Prepare(model, {});
  model::OutputSelection summary_only;
  summary_only.summary_only = true;
  const auto path = TemporaryFile("summary_only.h5");
  const Summary run = RunAndRecord(model.analysis, setup, summary_only, path.string());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (const char* history : {"time", "ground_acceleration", "displacement", "connection_force",
                              "isolator/force", "story/drift", "energy/input"}) {
    EXPECT_TRUE(Read(file, history).dims.empty()) << history << " written";
  }
  EXPECT_EQ(IntegerAttribute(file, "summary_only"), 1);
  EXPECT_EQ(Read(file, "peaks/isolator_displacement").values,
            std::vector<double>{run.peaks.isolator_displacement.value});
  EXPECT_EQ(Read(file, "peaks/story_drift").values,
            std::vector<double>{run.peaks.story_drift.value});
  EXPECT_EQ(Read(file, "final_energy/input").values, std::vector<double>{run.peaks.energies.input});
  EXPECT_EQ(Read(file, "final_energy/hysteretic").values,
            std::vector<double>{run.peaks.energies.hysteretic});
  EXPECT_EQ(Read(file, "story/height").values.size(), 5u);
  H5Fclose(file);
  EXPECT_GT(run.peaks.isolator_displacement.value, 10.0);
}

TEST(ResultsWriter, LevelsAndQuantitiesChooseTheColumns) {
  const model::ModelFile model = model::LoadModelFile(Model("buildings/five_story_table9.yaml"));
  const Problem setup = Prepare(model, {});
  ResponseHistory history;
  RunInMemory(model.analysis, setup, &history);
  const int rows = history.rows_written;

  model::OutputSelection selection;
  selection.quantities = {"displacement", "connection_force", "story"};
  selection.levels = {model::kRoofLevel, 0};  // the base and floor 5
  const auto path = TemporaryFile("levels.h5");
  RunAndRecord(model.analysis, setup, selection, path.string());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(Read(file, "displacement").dims, (std::vector<hsize_t>{hsize_t(rows), 2}));
  ExpectBitwiseEqual(Read(file, "displacement").values,
                     Expected(history.displacement, rows, 1, {0, 5}), "displacement");
  // The isolation layer sits below the base, story 5 below floor 5.
  ExpectBitwiseEqual(Read(file, "connection_force").values,
                     Expected(history.connection_force, rows, 1, {0, 5}), "connection_force");
  ExpectBitwiseEqual(
      Read(file, "story/drift").values,
      ExpectedVector(
          rows, 1, [&](int r) { return history.displacement(r, 5) - history.displacement(r, 4); }),
      "story/drift");
  for (const char* absent :
       {"velocity", "acceleration", "absolute_acceleration", "isolator/force", "energy/input"}) {
    EXPECT_TRUE(Read(file, absent).dims.empty()) << absent << " written";
  }
  H5Fclose(file);

  // A fixed-base building has no level 0: its floors count from 1.
  const model::ModelFile frame = model::LoadModelFile(Model("chopra/case_e_five_story_frame.yaml"));
  const Problem frame_setup = Prepare(frame, {});
  model::OutputSelection level_zero;
  level_zero.levels = {0};
  EXPECT_THROW(SelectedLevels(level_zero, frame_setup.layout, "output.levels"), InputError);
  model::OutputSelection first_floor;
  first_floor.levels = {1, model::kRoofLevel};
  EXPECT_EQ(SelectedLevels(first_floor, frame_setup.layout, "output.levels"),
            (std::vector<int>{0, 4}));
}

TEST(ResultsWriter, CsvFollowsTheSelection) {
  const model::ModelFile model = model::LoadModelFile(Model("buildings/five_story_table9.yaml"));
  const Problem setup = Prepare(model, {});
  ResponseHistory history;
  RunInMemory(model.analysis, setup, &history);
  model::OutputSelection selection;
  selection.every = 10;
  selection.quantities = {"energy"};
  const auto path = TemporaryFile("energy.csv");
  RunAndRecord(model.analysis, setup, selection, path.string(), 7);
  std::string header;
  const std::vector<std::vector<double>> values = CsvRows(path, &header);
  EXPECT_EQ(header,
            "time [s],ground_acceleration [mm/s^2],energy/input [kN*mm],energy/kinetic [kN*mm],"
            "energy/damping [kN*mm],energy/elastic [kN*mm],energy/hysteretic [kN*mm]");
  ASSERT_EQ(values.size(), std::size_t((history.rows_written - 1) / 10 + 1));
  for (std::size_t k = 0; k < values.size(); ++k) {
    const int r = static_cast<int>(10 * k);
    ASSERT_EQ(values[k].size(), 7u);
    EXPECT_EQ(values[k][0], history.time[r]);
    EXPECT_EQ(values[k][2], history.energies[r].input);
    EXPECT_EQ(values[k][6], history.energies[r].hysteretic);
  }
}

TEST(ResultsWriter, AWriterAbandonedBeforeFinishLeavesNothing) {
  const model::ModelFile model = model::LoadModelFile(Model("buildings/five_story_table9.yaml"));
  const Problem setup = Prepare(model, {});
  ResponseHistory history;
  Problem short_run = setup;
  short_run.grid.steps = 50;
  RunInMemory(model.analysis, short_run, &history);
  for (const char* name : {"abandoned.h5", "abandoned.csv"}) {
    const auto path = TemporaryFile(name);
    {
      const RunDescription run{&setup, &model.analysis, nullptr, nullptr, "test", {}};
      ResultsWriter writer(path.string(), run, 7);
      for (int r = 0; r < history.rows_written; ++r) writer.Observe(history.Row(r));
      EXPECT_EQ(writer.rows(), history.rows_written);
    }
    EXPECT_FALSE(std::filesystem::exists(path)) << name;
    EXPECT_TRUE(testing::LeftoverTemporaries(path).empty()) << name;
  }
}

// A run that stops early (a blow-up) is written with the rows it reached: the datasets, whose
// extent is the grid's rows from the start, end at the last row written, padding and rows never
// reached left out, and equal the in-memory run's rows bit for bit.
TEST(ResultsWriter, ARunThatStopsEarlyEndsAtItsLastRow) {
  const model::ModelFile model = model::LoadModelFile(
      std::string(ISOLAB_SOURCE_DIR) + "/tests/cli/data/blow_up_negative_stiffness.yaml");
  const Problem setup = Prepare(model, {});
  ResponseHistory history;
  ASSERT_FALSE(RunInMemory(model.analysis, setup, &history).run.ok());
  const int rows = history.rows_written;
  const int grid_rows = setup.grid.steps + 1;
  ASSERT_GT(rows, 20);
  ASSERT_LT(rows, grid_rows - 10);

  const auto path = TemporaryFile("stopped.h5");
  const Summary run = RunAndRecord(model.analysis, setup, {}, path.string(), /*buffer_rows=*/7);
  EXPECT_FALSE(run.run.ok());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(Read(file, "time").dims, std::vector<hsize_t>{hsize_t(rows)});
  ExpectBitwiseEqual(Read(file, "time").values,
                     ExpectedVector(rows, 1, [&](int r) { return history.time[r]; }), "time");
  const Dataset displacement = Read(file, "displacement");
  ASSERT_EQ(displacement.dims.size(), 2u);
  EXPECT_EQ(displacement.dims[0], hsize_t(rows));
  ExpectBitwiseEqual(displacement.values, Expected(history.displacement, rows, 1), "displacement");
  H5Fclose(file);
}

}  // namespace
}  // namespace isolab::analysis
