// docs/results.md promises that a Python user reads the results in three lines: its pandas
// snippet runs here, under Debian's /usr/bin/python3 (python3-h5py, python3-pandas), on fresh
// results of the README's model, and prints the numbers `isolab run` reports.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/run_isolab.h"
#include "own_test_file.h"

namespace {

std::string Source(const std::string& relative) {
  return std::string(ISOLAB_SOURCE_DIR) + "/" + relative;
}

// The python block between the markers of docs/results.md.
std::string Snippet() {
  std::ifstream in(Source("docs/results.md"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::size_t begin = doc.find("<!-- results-snippet:begin -->\n```python\n");
  const std::size_t end = doc.find("```\n<!-- results-snippet:end -->");
  if (begin == std::string::npos || end == std::string::npos) return "";
  const std::size_t start = doc.find('\n', doc.find("```python", begin)) + 1;
  return doc.substr(start, end - start);
}

TEST(ResultsDoc, PandasSnippetReadsTheResults) {
  const std::string snippet = Snippet();
  ASSERT_FALSE(snippet.empty()) << "no snippet between the markers in docs/results.md";
  const auto folder = isolab::testing::OwnTestDirectory();
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string model = Source("models/buildings/five_story_table9.yaml");
  const auto h5 = isolab::testing::RunIsolab("run " + model + " --json -o " +
                                             (folder / "five_story_table9.h5").string());
  ASSERT_EQ(h5.exit_code, 0);
  ASSERT_EQ(isolab::testing::RunIsolab("run " + model + " -o " +
                                       (folder / "five_story_table9.csv").string())
                .exit_code,
            0);
  { std::ofstream(folder / "snippet.py") << snippet; }
  const auto python =
      isolab::testing::RunShell("cd " + folder.string() + " && /usr/bin/python3 snippet.py", true);
  ASSERT_EQ(python.exit_code, 0) << python.output
                                 << "\n(Debian packages python3-h5py and python3-pandas)";
  const auto json = nlohmann::json::parse(h5.output);
  char peak[64];
  std::snprintf(peak, sizeof peak, "%.6g",
                json["peaks"]["isolator_displacement"]["value"].get<double>());
  EXPECT_NE(python.output.find(std::string("peak base displacement ") + peak + " mm"),
            std::string::npos)
      << python.output;
  EXPECT_NE(python.output.find(std::string("same peak from the CSV ") + peak + " mm"),
            std::string::npos)
      << python.output;
  EXPECT_NE(python.output.find("fwn_firm_seed1.at2 in g, PGA 0.21 g"), std::string::npos)
      << python.output;
}

}  // namespace
