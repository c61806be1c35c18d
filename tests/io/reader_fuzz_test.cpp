// Fuzzing isolab's readers with seeded mutants (input_mutator.h) of the files bundled with it:
// model YAML (and plan models), records, cyclic test CSV, study files, fit specifications and
// shake-table data. Every mutant must end in success or an InputError, never a crash, another
// exception or a hang (a mutant that takes over a second counts as a finding). A finding is saved
// beside its message in this test's temporary directory.
//
// Under ctest each target runs for at most 2 s (or 3000 mutants) from seed 1. For long runs:
//   ISOLAB_FUZZ_SECONDS=600 ISOLAB_FUZZ_SEED=7 build/tests/reader_fuzz_test
// (per target; ISOLAB_FUZZ_RUNS caps the mutants, default 3000, 0 for no cap).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "input_mutator.h"
#include "isolab/core/errors.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/record.h"
#include "isolab/io/shake_table_file.h"
#include "isolab/model/fit_spec_file.h"
#include "isolab/model/model_file.h"
#include "isolab/model/study_file.h"
#include "own_test_file.h"

namespace isolab::io {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = ISOLAB_SOURCE_DIR;

double EnvironmentNumber(const char* name, double fallback) {
  const char* value = std::getenv(name);
  return value != nullptr ? std::atof(value) : fallback;
}

std::string Contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Bundled files under `folders` (relative to the source) whose name ends in `suffix` and whose
// text passes `accept`; large ones are cut to their first 300 lines, to keep mutants quick.
struct Seed {
  fs::path relative;
  std::string text;
};
std::vector<Seed> Corpus(const std::vector<std::string>& folders, const std::string& suffix,
                         const std::function<bool(const std::string&)>& accept) {
  std::vector<Seed> corpus;
  for (const std::string& folder : folders) {
    for (const auto& entry : fs::recursive_directory_iterator(kSource / folder)) {
      const std::string name = entry.path().filename().string();
      if (!entry.is_regular_file() || !name.ends_with(suffix)) continue;
      std::string text = Contents(entry.path());
      if (!accept(text)) continue;
      if (text.size() > 64 * 1024) {
        std::size_t end = 0;
        for (int line = 0; line < 300 && end != std::string::npos; ++line) {
          end = text.find('\n', end + 1);
        }
        if (end != std::string::npos) text.resize(end + 1);
      }
      corpus.push_back({fs::relative(entry.path(), kSource), std::move(text)});
    }
  }
  std::sort(corpus.begin(), corpus.end(),
            [](const Seed& a, const Seed& b) { return a.relative < b.relative; });
  return corpus;
}

bool HasTopLevelKey(const std::string& text, const std::string& key) {
  return text.rfind(key + ":", 0) == 0 || text.find("\n" + key + ":") != std::string::npos;
}

// A copy of the source tree's layout under `root` in which `folder` and its parents are real
// directories and everything else links back to the source, so that a mutant written into
// `folder` finds the files its original names relative to itself (records, building models,
// isolation files). A link made for an earlier folder is replaced by a directory when a later
// folder lies under it: a mutant must never be written through a link into the source.
void Mirror(const fs::path& root, const fs::path& folder) {
  fs::path level;
  fs::create_directories(root);
  for (auto part = folder.begin();; ++part) {
    for (const auto& entry : fs::directory_iterator(kSource / level)) {
      const fs::path link = root / level / entry.path().filename();
      if (!fs::exists(fs::symlink_status(link))) fs::create_symlink(entry.path(), link);
    }
    if (part == folder.end()) break;
    level /= *part;
    if (fs::is_symlink(root / level)) fs::remove(root / level);
    fs::create_directory(root / level);
  }
}

// The folder of `root` that a mutant of `relative` is written into, made real first.
fs::path RealFolder(const fs::path& root, const fs::path& relative) {
  const fs::path folder = root / relative.parent_path();
  if (!fs::exists(folder) ||
      fs::canonical(folder) != fs::canonical(root) / relative.parent_path()) {
    Mirror(root, relative.parent_path());
  }
  return folder;
}

std::string DescribeFinding(const Seed& original, const std::string& edits,
                            const std::string& problem, const fs::path& saved) {
  return original.relative.string() + " mutated by [" + edits + "]: " + problem +
         " (the mutant is saved as " + saved.string() + ")";
}

struct FuzzOutcome {
  long runs = 0, accepted = 0, refused = 0;
  std::vector<std::string> findings;
};

// Mutants of the corpus through `read` until the time or run budget is spent.
FuzzOutcome Fuzz(const std::vector<Seed>& corpus, const std::string& target,
                 const std::function<void(const std::string& path)>& read) {
  const double seconds = EnvironmentNumber("ISOLAB_FUZZ_SECONDS", 2.0);
  const long max_runs = static_cast<long>(EnvironmentNumber("ISOLAB_FUZZ_RUNS", 3000));
  const auto seed = static_cast<std::uint64_t>(EnvironmentNumber("ISOLAB_FUZZ_SEED", 1));
  const fs::path root = testing::OwnTestDirectory() / target;
  fs::remove_all(root);
  testing::InputMutator mutator(seed);
  FuzzOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  while (elapsed() < seconds && (max_runs == 0 || outcome.runs < max_runs)) {
    const Seed& original = corpus[outcome.runs % corpus.size()];
    std::string edits;
    const std::string mutant = mutator.Mutate(original.text, &edits);
    const fs::path path = RealFolder(root, original.relative) /
                          ("fuzz_input" + original.relative.extension().string());
    if (fs::canonical(path.parent_path()).string().rfind(fs::canonical(root).string(), 0) != 0) {
      ADD_FAILURE() << path << " leads out of " << root << ": not written";  // into the source
      return outcome;
    }
    std::ofstream(path, std::ios::binary) << mutant;
    std::string problem;
    const auto began = std::chrono::steady_clock::now();
    try {
      read(path.string());
      ++outcome.accepted;
    } catch (const InputError&) {
      ++outcome.refused;
    } catch (const std::exception& error) {
      problem = std::string("an exception other than InputError: ") + error.what();
    } catch (...) {
      problem = "an exception of no std::exception type";
    }
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (problem.empty() && took > 1.0) problem = "took " + std::to_string(took) + " s";
    ++outcome.runs;
    if (!problem.empty()) {
      const fs::path saved = root / ("finding_" + std::to_string(outcome.findings.size()) +
                                     original.relative.extension().string());
      fs::copy_file(path, saved, fs::copy_options::overwrite_existing);
      outcome.findings.push_back(DescribeFinding(original, edits, problem, saved));
    }
  }
  std::printf(
      "%s: %ld mutants of %zu files in %.1f s (seed %llu): %ld read, %ld refused with "
      "an InputError, %zu findings\n",
      target.c_str(), outcome.runs, corpus.size(), elapsed(), static_cast<unsigned long long>(seed),
      outcome.accepted, outcome.refused, outcome.findings.size());
  return outcome;
}

void ExpectNoFindings(const FuzzOutcome& outcome) {
  EXPECT_GT(outcome.runs, 0);
  for (std::size_t k = 0; k < std::min<std::size_t>(outcome.findings.size(), 10); ++k) {
    ADD_FAILURE() << outcome.findings[k];
  }
}

const auto kAny = [](const std::string&) { return true; };

TEST(ReaderFuzz, ModelFiles) {
  const auto is_model = [](const std::string& text) {
    return (HasTopLevelKey(text, "isolation") || HasTopLevelKey(text, "structure")) &&
           !HasTopLevelKey(text, "plan");
  };
  const auto corpus = Corpus({"models", "tests/io/data", "tests/cli/data"}, ".yaml", is_model);
  ASSERT_GE(corpus.size(), 20u);
  ExpectNoFindings(
      Fuzz(corpus, "model", [](const std::string& path) { model::LoadModelFile(path); }));
}

TEST(ReaderFuzz, PlanModelFiles) {
  const auto is_plan = [](const std::string& text) { return HasTopLevelKey(text, "plan"); };
  const auto corpus = Corpus({"models", "tests"}, ".yaml", is_plan);
  ASSERT_GE(corpus.size(), 1u);
  ExpectNoFindings(
      Fuzz(corpus, "plan_model", [](const std::string& path) { model::LoadModelFile(path); }));
}

TEST(ReaderFuzz, Records) {
  std::vector<Seed> corpus = Corpus({"ground_motions", "tests"}, ".at2", kAny);
  for (const char* suffix : {".txt", ".csv"}) {
    const auto is_record = [](const std::string& text) {
      return text.rfind("time,acc", 0) == 0 || text.find(',') == std::string::npos;
    };
    for (Seed& seed : Corpus({"tests/io/data"}, suffix, is_record)) corpus.push_back(seed);
  }
  ASSERT_GE(corpus.size(), 15u);
  ExpectNoFindings(Fuzz(corpus, "record", [](const std::string& path) {
    // Half the time with units and a step given, which the single columns need.
    static int call = 0;
    ReadRecord(path, ++call % 2 == 0 ? RecordOptions{} : RecordOptions{"g", 0.01});
  }));
}

TEST(ReaderFuzz, CyclicTestFiles) {
  const auto is_cyclic = [](const std::string& text) {
    return text.find("time,displacement,force") != std::string::npos;
  };
  std::vector<Seed> corpus = Corpus({"tests/cli/data/fit"}, ".csv", is_cyclic);
  // The optional header lines too, which no bundled file has both of.
  std::string headed =
      "# units: force kN, length mm\n# specimen: one, in order\n"
      "test,time,displacement,force\n";
  for (int k = 0; k <= 40; ++k) {
    const double u = 50.0 * std::sin(0.314159 * k);
    headed += "u=50," + std::to_string(0.05 * k) + "," + std::to_string(u) + "," +
              std::to_string(0.5 * u + (k % 4 < 2 ? 5.0 : -5.0)) + "\n";
  }
  corpus.push_back({"tests/cli/data/fit/headed.csv", headed});
  ASSERT_GE(corpus.size(), 5u);
  const UnitSystem units("kN", "mm", "s");
  ExpectNoFindings(Fuzz(corpus, "cyclic_tests",
                        [&](const std::string& path) { ReadCyclicTests({path}, {}, units); }));
}

TEST(ReaderFuzz, StudyFiles) {
  const auto is_study = [](const std::string& text) { return HasTopLevelKey(text, "variants"); };
  const auto corpus = Corpus({"models", "tests"}, ".yaml", is_study);
  ASSERT_GE(corpus.size(), 5u);
  ExpectNoFindings(
      Fuzz(corpus, "study", [](const std::string& path) { model::LoadStudyFile(path); }));
}

TEST(ReaderFuzz, FitSpecifications) {
  const auto is_spec = [](const std::string& text) { return HasTopLevelKey(text, "components"); };
  const auto corpus = Corpus({"models", "tests"}, ".yaml", is_spec);
  ASSERT_GE(corpus.size(), 4u);
  ExpectNoFindings(
      Fuzz(corpus, "fit_spec", [](const std::string& path) { model::LoadFitSpec(path); }));
}

TEST(ReaderFuzz, ShakeTableData) {
  const auto is_shake_table = [](const std::string& text) {
    return text.find("table_acceleration") != std::string::npos;
  };
  const auto corpus = Corpus({"tests"}, ".csv", is_shake_table);
  ASSERT_GE(corpus.size(), 1u);
  ExpectNoFindings(
      Fuzz(corpus, "shake_table", [](const std::string& path) { ShakeTableData::Read(path); }));
}

}  // namespace
}  // namespace isolab::io
