// Every reader stops at its first overlong line: a file that is a header and then tens of
// megabytes of NUL bytes (one endless line) is refused at that line, exit 2, with the peak memory
// of the process no larger than for a small bad file (it was the file's size and more: 2.1 GB
// for `run --record` of a 1 GB file, 8 GB and exit 3 for `shaketable` of a 2 GB one). A YAML file
// over 64 MiB is refused before it is read. A UTF-8 byte-order mark at the start of a CSV or
// YAML file changes nothing (it turned a CSV's comment line into its header).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "own_test_file.h"

namespace {

namespace fs = std::filesystem;

const std::string kSource = ISOLAB_SOURCE_DIR;

struct Outcome {
  int exit_code = -1;
  long peak_memory_kib = 0;  // the child's maximum resident set
  std::string output;        // stdout and stderr
};

// Runs isolab with `arguments` in a child of its own, so that its peak memory is its own.
Outcome RunMeasured(const std::vector<std::string>& arguments) {
  const fs::path log = isolab::testing::OwnTestDirectory() / "output.txt";
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> argv{const_cast<char*>(ISOLAB_BINARY)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(ISOLAB_BINARY, argv.data());
    _exit(127);
  }
  Outcome outcome;
  int status = 0;
  struct rusage usage {};
  wait4(pid, &status, 0, &usage);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  outcome.peak_memory_kib = usage.ru_maxrss;
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  outcome.output = text.str();
  return outcome;
}

// `header`, then NUL bytes up to `size` bytes: a sparse file, so the test writes almost nothing.
std::string WithNulBytes(const std::string& name, const std::string& header, std::uintmax_t size) {
  const fs::path path = isolab::testing::OwnTestFile(name);
  std::ofstream(path, std::ios::binary) << header;
  fs::resize_file(path, size);
  return path.string();
}

std::string Write(const std::string& name, const std::string& text) {
  const fs::path path = isolab::testing::OwnTestFile(name);
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

constexpr std::uintmax_t kLarge = 48u << 20;  // 48 MiB of one line
constexpr long kAllowanceKib = 8 << 10;       // what a 64 KiB line limit may cost, generously

TEST(BoundedInput, AnEndlessLineIsRefusedAtItsLineWithoutReadingTheFile) {
  const std::string model = kSource + "/models/sdof/table7_thm1_hard.yaml";
  const std::string out = (isolab::testing::OwnTestDirectory() / "never.h5").string();
  const std::string at2_header =
      "PEER NGA STRONG MOTION DATABASE RECORD\nsynthetic\nACCELERATION TIME SERIES IN UNITS OF "
      "G\nNPTS=  100, DT= 0.01000 SEC\n";
  const std::string cyclic_header = "test,time,displacement,force\n";
  const std::string table_header = "time_s,table_acceleration_m_s2,a1_m_s2\n";
  struct Case {
    std::string what;
    std::vector<std::string> large, small;  // arguments for the large file and a small bad one
    std::string message;
  };
  const std::string spec = kSource + "/tests/cli/data/fit/three_laws_spec.yaml";
  const std::string building = kSource + "/models/bncs/bncs.yaml";
  const Case cases[] = {
      {"run --record",
       {"run", model, "-q", "-o", out, "--record", WithNulBytes("large.at2", at2_header, kLarge)},
       {"run", model, "-q", "-o", out, "--record", Write("small.at2", at2_header + "x\n")},
       "large.at2:5: a line of more than 65536 characters"},
      {"spectrum",
       {"spectrum", WithNulBytes("large_spectrum.at2", at2_header, kLarge), "-q"},
       {"spectrum", Write("small_spectrum.at2", at2_header + "x\n"), "-q"},
       "large_spectrum.at2:5: a line of more than 65536 characters"},
      {"fit",
       {"fit", WithNulBytes("large.csv", cyclic_header, kLarge), "--model", spec, "-q"},
       {"fit", Write("small.csv", cyclic_header + "a,0,0,x\n"), "--model", spec, "-q"},
       "large.csv:2: a line of more than 65536 characters"},
      {"shaketable",
       {"shaketable", WithNulBytes("large_table.csv", table_header, kLarge), "--model", building,
        "-q"},
       {"shaketable", Write("small_table.csv", table_header + "0,0,x\n"), "--model", building,
        "-q"},
       "large_table.csv:2: a line of more than 65536 characters"},
  };
  for (const Case& c : cases) {
    const Outcome small = RunMeasured(c.small);
    const Outcome large = RunMeasured(c.large);
    EXPECT_EQ(small.exit_code, 2) << c.what << "\n" << small.output;
    EXPECT_EQ(large.exit_code, 2) << c.what << "\n" << large.output;
    EXPECT_NE(large.output.find(c.message), std::string::npos) << c.what << "\n" << large.output;
    EXPECT_LT(large.peak_memory_kib, small.peak_memory_kib + kAllowanceKib)
        << c.what << ": " << large.peak_memory_kib << " KiB for a " << (kLarge >> 20)
        << " MiB line, " << small.peak_memory_kib << " KiB for a small file";
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(BoundedInput, AYamlFileOverItsLimitIsRefusedBeforeReading) {
  const std::string header = "units: {force: kN, length: mm, time: s}\n#";
  for (const char* command : {"run", "cyclic"}) {
    const std::string path = WithNulBytes("large.yaml", header, 65u << 20);
    const Outcome outcome = RunMeasured({command, path});
    // The same command on a small file that fails as early: what the executable itself takes
    // (cyclic's loads pagmo and MPI).
    const Outcome small = RunMeasured({command, Write("small.yaml", header + "\n")});
    EXPECT_EQ(outcome.exit_code, 2) << outcome.output;
    EXPECT_EQ(small.exit_code, 2) << small.output;
    EXPECT_NE(outcome.output.find("large.yaml"), std::string::npos) << outcome.output;
    // Far below the file's 65 MiB.
    EXPECT_LT(outcome.peak_memory_kib, small.peak_memory_kib + kAllowanceKib) << command;
  }
}

TEST(BoundedInput, AByteOrderMarkChangesNothing) {
  const std::string bom = "\xEF\xBB\xBF";
  // A comment line first: with the mark kept it was read as the header.
  const std::string cyclic =
      "# units: force kN, length mm\ntest,time,displacement,force\n"
      "a,0,0,0\na,0.1,1,x\n";
  for (const std::string& prefix : {std::string(), bom}) {
    const Outcome fit = RunMeasured({"fit", Write("bom.csv", prefix + cyclic), "--model",
                                     kSource + "/tests/cli/data/fit/three_laws_spec.yaml", "-q"});
    EXPECT_EQ(fit.exit_code, 2) << fit.output;
    EXPECT_NE(fit.output.find("bom.csv:4:"), std::string::npos) << fit.output;
    EXPECT_NE(fit.output.find("'x' is not a number"), std::string::npos) << fit.output;

    const Outcome table =
        RunMeasured({"shaketable", Write("bom_table.csv", prefix + "# BNCS\ntime_s,a1_g\n0,x\n"),
                     "--model", kSource + "/models/bncs/bncs.yaml", "-q"});
    EXPECT_EQ(table.exit_code, 2) << table.output;
    EXPECT_NE(table.output.find("bom_table.csv:3:2: column 'a1': 'x' is not a"), std::string::npos)
        << table.output;

    // A model whose error is located by line and column, the same with the mark.
    const Outcome model = RunMeasured(
        {"cyclic", Write("bom.yaml", prefix + "units: {force: kN, length: mm, time: s}\n"
                                              "isolation: {components: [{type: bhm2, k0: 1, "
                                              "k1: 2, uy: 1}]}\n")});
    EXPECT_EQ(model.exit_code, 2) << model.output;
    EXPECT_NE(model.output.find("bom.yaml:2:"), std::string::npos) << model.output;
    EXPECT_NE(model.output.find("k1 = 2 (must be < k0 = 1)"), std::string::npos) << model.output;
  }
  // A CSV record reads the same with the mark: its header names its units.
  const std::string record = "time (s),acceleration (g)\n0,0\n0.01,0.1\n0.02,-0.05\n0.03,0\n";
  const Outcome plain = RunMeasured(
      {"spectrum", Write("plain.csv", record), "--periods", "0.5:1:0.5", "--json", "-q"});
  const Outcome marked = RunMeasured(
      {"spectrum", Write("marked.csv", bom + record), "--periods", "0.5:1:0.5", "--json", "-q"});
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(marked.exit_code, 0) << marked.output;
  const auto numbers = [](std::string text) {  // the spectrum, up to the record's own name
    const std::size_t from = text.find("\"elastic\"");
    return text.substr(from, text.find("\"record\"") - from);
  };
  EXPECT_EQ(numbers(plain.output), numbers(marked.output));
  EXPECT_NE(numbers(plain.output).find("\"D\""), std::string::npos) << plain.output;
}

}  // namespace
