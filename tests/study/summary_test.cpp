// Summary statistics on a hand-made set of results: means and maxima over the records whose
// runs completed, ratios to the reference per run and per statistic, NaN where a value is
// missing; and the CSV that carries them.
#include "isolab/study/summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "isolab/study/summary_file.h"
#include "isolab/study/summary_table.h"
#include "leftover_temporaries.h"
#include "own_test_file.h"

namespace isolab::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

JobResult Completed(std::size_t job, QuantityValues values) {
  JobResult result;
  result.job = job;
  result.completed = true;
  result.values = values;
  result.file = "runs/x.h5";
  return result;
}

JobResult Failed(std::size_t job, const std::string& message) {
  JobResult result;
  result.job = job;
  result.message = message;
  return result;
}

StudyShape Shape() {
  return {{"ref", "other", "fixed"}, {"r1", "r2"}, {}, {1.0}, 0, {"mm", "kN", "%", "g", "mm"}};
}

// 3 variants x 2 records x 1 scale; jobs (v, r) = 2 v + r. "other" fails on r2; "fixed" has no
// isolator values.
std::vector<JobResult> Results() {
  return {
      Completed(0, {100, 200, 0.1, 0.2, 4}),
      Completed(1, {300, 400, 0.3, 0.4, 0}),
      Completed(2, {150, 100, 0.2, 0.1, 2}),
      Failed(3, "Newton did not converge at t = 1 s, \"step\" 100"),
      Completed(4, {kNaN, 500, 0.5, 0.8, kNaN}),
      Completed(5, {kNaN, 600, 0.9, 1.2, kNaN}),
  };
}

TEST(Summary, MeanMaxAndRatiosOverCompletedRuns) {
  std::vector<JobResult> results = Results();
  std::swap(results[0], results[5]);  // finishing order does not matter
  const Summary summary = BuildSummary(Shape(), results);
  EXPECT_EQ(summary.failed(), 1u);
  ASSERT_EQ(summary.runs.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(summary.runs[k].job, k);

  const Statistic& ref = summary.At(0, 0);
  EXPECT_EQ(ref.completed, 2u);
  EXPECT_DOUBLE_EQ(ref.mean[0], 200.0);
  EXPECT_DOUBLE_EQ(ref.max[0], 300.0);
  EXPECT_DOUBLE_EQ(ref.mean[1], 300.0);
  EXPECT_DOUBLE_EQ(ref.mean[4], 2.0);
  EXPECT_DOUBLE_EQ(ref.max[4], 4.0);
  for (const Quantity q : StudyQuantities(false)) {
    EXPECT_EQ(ref.mean_ratio[static_cast<std::size_t>(q)], 1.0);
  }

  const Statistic& other = summary.At(1, 0);  // r1 only
  EXPECT_EQ(other.completed, 1u);
  EXPECT_DOUBLE_EQ(other.mean[0], 150.0);
  EXPECT_DOUBLE_EQ(other.max[1], 100.0);
  EXPECT_DOUBLE_EQ(other.mean_ratio[0], 150.0 / 200.0);
  EXPECT_DOUBLE_EQ(other.max_ratio[1], 100.0 / 400.0);

  const Statistic& fixed = summary.At(2, 0);
  EXPECT_TRUE(std::isnan(fixed.mean[0]));
  EXPECT_TRUE(std::isnan(fixed.mean_ratio[0]));
  EXPECT_DOUBLE_EQ(fixed.mean[1], 550.0);
  EXPECT_DOUBLE_EQ(fixed.mean_ratio[1], 550.0 / 300.0);
  EXPECT_DOUBLE_EQ(fixed.max[3], 1.2);
  EXPECT_DOUBLE_EQ(fixed.max_ratio[3], 1.2 / 0.4);

  // Per run: against the reference's run on the same record; a zero reference has no ratio.
  EXPECT_DOUBLE_EQ(summary.ratios[2][0], 1.5);
  EXPECT_DOUBLE_EQ(summary.ratios[5][2], 3.0);
  EXPECT_TRUE(std::isnan(summary.ratios[3][0]));  // failed
  EXPECT_TRUE(std::isnan(summary.ratios[5][0]));  // no isolator
  EXPECT_TRUE(std::isnan(summary.ratios[1][4]));  // the reference's residual is 0
}

TEST(Summary, RejectsAMissingOrDuplicatedJob) {
  std::vector<JobResult> results = Results();
  results.pop_back();
  EXPECT_THROW(BuildSummary(Shape(), results), std::invalid_argument);
  results.push_back(Completed(4, {}));
  EXPECT_THROW(BuildSummary(Shape(), results), std::invalid_argument);
}

std::string ReadText(const std::filesystem::path& path) {
  std::ifstream stream(path);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

TEST(SummaryFile, CsvHoldsExactValuesStatusAndQuotedMessages) {
  std::vector<JobResult> results = Results();
  results[2].record_units = "cm/s^2";
  results[2].pga = 0.35;
  results[2].warnings = {"PGA, check units", "too long"};
  const Summary summary = BuildSummary(Shape(), results);
  const auto path = isolab::testing::OwnTestDirectory() / "summary.csv";
  WriteSummaryCsv(path.string(), summary);
  const std::string csv = ReadText(path);
  std::istringstream lines(csv);
  std::string header, line;
  std::getline(lines, header);
  EXPECT_EQ(header,
            "variant,record,scale,status,isolator_displacement [mm],base_shear [kN],"
            "story_drift_ratio [%],floor_acceleration [g],residual_isolator_displacement [mm],"
            "ratio isolator_displacement,ratio base_shear,ratio story_drift_ratio,"
            "ratio floor_acceleration,ratio residual_isolator_displacement,message,file,"
            "record_units,pga_g,warnings");
  std::vector<std::string> rows;
  while (std::getline(lines, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 6u + 3u * 2u);
  EXPECT_EQ(rows[0], "ref,r1,1,completed,100,200,0.1,0.2,4,1,1,1,1,1,,runs/x.h5,,,");
  EXPECT_EQ(rows[2],
            "other,r1,1,completed,150,100,0.2,0.1,2,1.5,0.5,2,0.5,0.5,,runs/x.h5,cm/s^2,0.35,"
            "\"PGA, check units; too long\"");
  EXPECT_EQ(rows[3],
            "other,r2,1,failed,,,,,,,,,,,\"Newton did not converge at t = 1 s, \"\"step\"\" "
            "100\",,,,");
  EXPECT_EQ(rows[6], "ref,mean,1,completed,200,300,0.2,0.30000000000000004,2,1,1,1,1,1,,,,,");
  EXPECT_EQ(rows[9],
            "other,max,1,partial,150,100,0.2,0.1,2,0.5,0.25,0.6666666666666667,0.25,0.5,"
            "over the 1 of 2 records whose runs completed,,,,");
  EXPECT_EQ(rows[10].rfind("fixed,mean,1,completed,,550,0.7,1,,,", 0), 0u) << rows[10];
  EXPECT_TRUE(isolab::testing::LeftoverTemporaries(path).empty());
}

TEST(SummaryTable, PrintsRunsStatisticsAndFailures) {
  const Summary summary = BuildSummary(Shape(), Results());
  std::ostringstream out;
  PrintSummaryTable(summary, out);
  const std::string table = out.str();
  EXPECT_NE(table.find("scale 1 (ratios to ref)"), std::string::npos) << table;
  EXPECT_NE(table.find("isolator [mm]"), std::string::npos) << table;
  EXPECT_NE(table.find("failed: Newton did not converge"), std::string::npos) << table;
  EXPECT_NE(table.find("mean (1 of 2)"), std::string::npos) << table;
  EXPECT_NE(table.find("1.833"), std::string::npos) << table;  // fixed: 550 / 300
}

}  // namespace
}  // namespace isolab::study
