// The README's model file runs exactly as the README shows it: the YAML and the command between
// its markers, in a folder of their own beside the bundled records. The model summary's period at
// 100 mm is checked against the closed form of a bilinear bearing, computed from the README's own
// numbers; the peak it quotes against a second integrator (IDA, tightly toleranced) on the same
// model; and the printed lines the README quotes must be what isolab prints, so that the README
// cannot drift from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include "cli/run_isolab.h"
#include "own_test_file.h"

namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text between `<!-- name:begin -->` and `<!-- name:end -->`.
std::string Between(const std::string& page, const std::string& name) {
  const std::string begin = "<!-- " + name + ":begin -->", end = "<!-- " + name + ":end -->";
  const std::size_t from = page.find(begin), to = page.find(end);
  if (from == std::string::npos || to == std::string::npos || to < from) return "";
  return page.substr(from + begin.size(), to - from - begin.size());
}

// The body of the first fenced block of `language` ("" for a bare fence) in `text`.
std::string Fenced(const std::string& text, const std::string& language) {
  const std::string open = "```" + language + "\n";
  const std::size_t from = text.find(open);
  if (from == std::string::npos) return "";
  const std::size_t to = text.find("```", from + open.size());
  return text.substr(from + open.size(), to - from - open.size());
}

double Number(const std::string& text, const std::string& key) {
  std::smatch match;
  const std::regex pattern(key + R"(:\s*([0-9.eE+-]+))");
  return std::regex_search(text, match, pattern) ? std::stod(match[1]) : NAN;
}

TEST(Readme, TheModelFileRunsAsShown) {
  const std::string readme = Read(fs::path(ISOLAB_SOURCE_DIR) / "README.md");
  const std::string section = Between(readme, "readme-model");
  const std::string model = Fenced(section, "yaml");
  const std::string command = Fenced(section, "sh");
  ASSERT_FALSE(model.empty()) << "no ```yaml block between the README's readme-model markers";
  ASSERT_EQ(command.rfind("build/isolab run lrb_sdof.yaml", 0), 0u) << command;
  const std::size_t lines = std::count(model.begin(), model.end(), '\n');
  EXPECT_LE(lines, 16u) << "the README's model is meant to be the shortest complete one";

  const fs::path folder = isolab::testing::FreshTestDirectory();
  std::ofstream(folder / "lrb_sdof.yaml") << model;
  fs::create_directory_symlink(fs::path(ISOLAB_SOURCE_DIR) / "ground_motions",
                               folder / "ground_motions");
  const auto run = isolab::testing::RunCommandLine(
      "cd " + folder.string() + " && " + ISOLAB_BINARY +
      command.substr(std::string("build/isolab").size(), command.find('\n') - 12) + " 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(folder / "lrb_sdof.h5"));

  // Closed form: a bilinear bearing past its yield displacement Qd / (Ku - Kd) has the secant
  // stiffness Kd + Qd / D at D; T = 2 pi sqrt(m / K), m = 150 t = 0.15 kN s^2/mm.
  const double qd = Number(model, "qd"), kd = Number(model, "kd"), ku = Number(model, "ku");
  ASSERT_LT(qd / (ku - kd), 100.0);
  const double mass = 0.15, secant = kd + qd / 100.0;
  const double period = 2.0 * std::numbers::pi * std::sqrt(mass / secant);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(run.output, match, std::regex(R"(period ([0-9.]+) s at 100 mm)")))
      << run.output;
  EXPECT_NEAR(std::stod(match[1]), period, 5e-4 * period);  // printed to four digits

  // Regression check of the page: each line it quotes is printed as it stands.
  std::istringstream quoted(Fenced(Between(readme, "readme-model-output"), ""));
  int count = 0;
  for (std::string line; std::getline(quoted, line); ++count) {
    EXPECT_NE(run.output.find(line), std::string::npos)
        << "the README quotes\n  " << line << "\nisolab printed\n"
        << run.output;
  }
  EXPECT_GE(count, 3);

  // The peak the README quotes, against a second integrator: IDA (variable order and step, its
  // error controlled to 1e-8) on the same model. Newmark's average acceleration at dt = 0.005 s
  // lengthens a 2.2 s period by (pi dt / T)^2 / 3, 2e-5; the lead's yield and unloading within a
  // step add more: 3e-4 apart on this record, so 1e-3.
  std::smatch quoted_peak;
  const std::string output_section = Between(readme, "readme-model-output");
  ASSERT_TRUE(std::regex_search(output_section, quoted_peak,
                                std::regex(R"(peak isolator displacement\s+([0-9.]+) mm)")))
      << output_section;
  const auto ida = isolab::testing::RunCommandLine(
      "cd " + folder.string() + " && " + ISOLAB_BINARY +
      " run lrb_sdof.yaml --integrator ida --rtol 1e-8 --atol 1e-10 -o ida.h5 -q --json");
  ASSERT_EQ(ida.exit_code, 0) << ida.output;
  std::smatch ida_peak;
  ASSERT_TRUE(std::regex_search(
      ida.output, ida_peak,
      std::regex(R"("isolator_displacement":\s*\{[^}]*"value":\s*([0-9.eE+-]+))")))
      << ida.output;
  EXPECT_NEAR(std::stod(quoted_peak[1]), std::stod(ida_peak[1]), 1e-3 * std::stod(ida_peak[1]));
}

}  // namespace
