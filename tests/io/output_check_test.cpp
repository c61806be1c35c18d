// Outputs against inputs by file identity, not by spelling: the same name, another spelling of
// it, a hard link and a path through a linked folder are all refused; distinct files pass.
#include "isolab/io/output_check.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab::io {
namespace {

namespace fs = std::filesystem;

fs::path FreshFolder() { return testing::FreshTestDirectory(); }

fs::path Touch(const fs::path& path) {
  std::ofstream(path) << "units: {force: kN, length: mm, time: s}\n";
  return path;
}

std::string ErrorOf(const std::vector<std::string>& inputs,
                    const std::vector<std::string>& outputs) {
  try {
    CheckOutputs(inputs, outputs);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(CheckOutputs, RefusesAnInputByItsOwnName) {
  const fs::path model = Touch(FreshFolder() / "m.yaml");
  const std::string error = ErrorOf({model.string()}, {model.string()});
  EXPECT_NE(error.find("is an input of this command"), std::string::npos) << error;
  EXPECT_EQ(error.rfind(model.string(), 0), 0u) << "the error starts with the output: " << error;
}

TEST(CheckOutputs, RefusesAnotherSpellingOfAnInput) {
  const fs::path folder = FreshFolder();
  const fs::path model = Touch(folder / "m.yaml");
  const std::string dotted = (folder / "." / "m.yaml").string();
  const std::string error = ErrorOf({model.string()}, {dotted});
  EXPECT_NE(error.find("is the input file '" + model.string() + "' under another name"),
            std::string::npos)
      << error;
  // Relative to the working folder, as a user types it.
  const fs::path before = fs::current_path();
  fs::current_path(folder);
  const std::string relative = ErrorOf({"m.yaml"}, {"./m.yaml"});
  fs::current_path(before);
  EXPECT_NE(relative.find("under another name"), std::string::npos) << relative;
}

TEST(CheckOutputs, RefusesAHardLinkAndAPathThroughALinkedFolder) {
  const fs::path folder = FreshFolder();
  const fs::path record = Touch(folder / "record.csv");
  fs::create_hard_link(record, folder / "same_record.csv");
  EXPECT_NE(ErrorOf({record.string()}, {(folder / "same_record.csv").string()}).find("destroy"),
            std::string::npos);
  fs::create_directory_symlink(folder, folder.parent_path() / (folder.filename().string() + "_l"));
  const std::string through =
      (folder.parent_path() / (folder.filename().string() + "_l") / "record.csv").string();
  EXPECT_NE(ErrorOf({record.string()}, {through}).find("destroy"), std::string::npos);
  fs::remove(folder.parent_path() / (folder.filename().string() + "_l"));
}

TEST(CheckOutputs, RefusesOneFileNamedAsTwoOutputs) {
  const fs::path folder = FreshFolder();
  fs::create_directory(folder / "x");
  // Neither exists yet: compared by their normalised paths.
  const std::string error =
      ErrorOf({}, {(folder / "out.csv").string(), (folder / "x" / ".." / "out.csv").string()});
  EXPECT_NE(error.find("is also the output"), std::string::npos) << error;
}

TEST(CheckOutputs, AcceptsDistinctFilesAndIgnoresMissingInputs) {
  const fs::path folder = FreshFolder();
  const fs::path model = Touch(folder / "m.yaml");
  const fs::path old_results = Touch(folder / "m.h5");  // an earlier output is replaced
  EXPECT_EQ(ErrorOf({model.string(), (folder / "absent.at2").string()},
                    {old_results.string(), (folder / "m.csv").string()}),
            "");
}

TEST(CheckOutputs, StillRefusesWhatCheckOutputPathRefuses) {
  const fs::path folder = FreshFolder();
  EXPECT_NE(ErrorOf({}, {(folder / "missing" / "out.h5").string()}).find("does not exist"),
            std::string::npos);
  EXPECT_NE(ErrorOf({}, {"/dev/null"}).find("character device"), std::string::npos);
}

}  // namespace
}  // namespace isolab::io
