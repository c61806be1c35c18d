// `isolab synth` end to end: the bundled records come out byte for byte from their documented
// commands, a record whose tail needs three-digit exponents is read back by `isolab run`, and
// every option out of its range exits 2 naming it, with nothing written. With --pairs: a suite
// matched to a target table is written as numbered AT2 files whose RotD100, measured by
// `isolab spectrum`, is within the tolerance; a pair that cannot converge exits 1 naming it; bad
// options and tables exit 2 naming them, with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/run_isolab.h"
#include "own_test_file.h"

namespace {

using isolab::testing::RunIsolab;

const std::string kSource = ISOLAB_SOURCE_DIR;

std::string Contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SynthCommand, RegeneratesTheBundledRecordsByteForByte) {
  // The commands ground_motions/README.md gives for them: the separator added for three-digit
  // exponents leaves PEER's 15 columns of the usual values unchanged.
  const struct {
    std::string file, arguments;
  } bundled[] = {
      {"fwn_firm_seed1.at2", "noise --seed 1 --pga 0.35 --site-frequency 2.5 --site-damping 0.6"},
      {"pulse_tp2.at2", "pulse --pulse-period 2.0 --pgv 0.8 --oscillations 2"},
  };
  for (const auto& record : bundled) {
    const auto output = isolab::testing::OwnTestFile(record.file);
    const auto run = RunIsolab("synth " + record.arguments + " -o " + output.string());
    ASSERT_EQ(run.exit_code, 0) << record.file;
    EXPECT_EQ(Contents(output), Contents(kSource + "/ground_motions/" + record.file))
        << record.file;
  }
}

TEST(SynthCommand, ThreeDigitExponentsAreReadBackByRun) {
  // 1000 s of noise: the envelope's decay exp(-0.25 (t - 12)) takes the tail below 1e-99 g, whose
  // exponents ran into the value before them ("-7.0912242E-99-4.6249845E-100") and made the file
  // unreadable to isolab itself.
  const auto record = isolab::testing::OwnTestFile("long_tail.at2");
  const auto synth =
      RunIsolab("synth noise --seed 4 --pga 0.3 --duration 1000 -o " + record.string());
  ASSERT_EQ(synth.exit_code, 0);
  EXPECT_NE(Contents(record).find("E-1"), std::string::npos) << "no three-digit exponent";
  const auto run = RunIsolab("run " + kSource + "/models/sdof/table7_thm1_soft.yaml --record " +
                             record.string() + " --dt 0.01 --json --summary-only -o " +
                             isolab::testing::OwnTestFile("long_tail.h5").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output);
  // The PGA asked for (written to 8 digits) and the duration: 100001 samples at 0.01 s.
  EXPECT_NEAR(json["pga_g"].get<double>(), 0.3, 1e-7);
  EXPECT_DOUBLE_EQ(json["excitation_end"].get<double>(), 1000.0);
}

TEST(SynthCommand, OptionsOutOfRangeExitTwoAndWriteNothing) {
  // --duration 0 and --pulse-period 0 wrote NaN samples; --pga 0 and -1 wrote records of zeros
  // or of the wrong sign, all with exit 0.
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"noise --duration 0",
       "--duration: 0 (must be at least 0.1 s (10 samples) and at most "
       "100000 s)"},
      // One sample at t = 0, where the envelope is 0: scaled to the PGA it was written as -NAN.
      {"noise --duration 0.001", "--duration: 0.001 (must be at least 0.1 s (10 samples)"},
      {"noise --duration 1e9",
       "--duration: 1e+09 (must be at least 0.1 s (10 samples) and at "
       "most 100000 s)"},
      {"noise --pga 0", "--pga: 0 (must be > 0 and at most 10 g)"},
      {"noise --pga -1", "--pga: -1 (must be > 0 and at most 10 g)"},
      {"noise --pga 1e308", "--pga: 1e+308 (must be > 0 and at most 10 g)"},
      {"noise --pga nan", "--pga"},
      {"noise --site-frequency 0", "--site-frequency: 0 (must be > 0 and at most 25 Hz)"},
      {"noise --site-frequency 60", "--site-frequency: 60 (must be > 0 and at most 25 Hz)"},
      {"noise --site-damping 0", "--site-damping: 0 (must be in (0, 1])"},
      {"noise --strong-end 1", "--strong-end: 1 (must be >= the envelope's rise time, 2 s)"},
      {"pulse --pulse-period 0",
       "--pulse-period: 0 (must be >= 0.1 s, ten samples, and at most "
       "60 s)"},
      {"pulse --pulse-period 1e300", "--pulse-period: 1e+300 (must be >= 0.1 s"},
      {"pulse --pgv 0", "--pgv: 0 (must be > 0 and at most 30 m/s)"},
      // Its accelerations overflowed and were written as INF.
      {"pulse --pgv 1e308", "--pgv: 1e+308 (must be > 0 and at most 30 m/s)"},
      {"pulse --oscillations 1", "--oscillations: 1 (must be > 1 and at most 100)"},
      {"pulse --oscillations 1e300", "--oscillations: 1e+300 (must be > 1 and at most 100)"},
      // An option of the other kind was ignored: the record was the default one, exit 0.
      {"noise --phase 1.3", "--phase: shapes a pulse: give kind pulse"},
      {"noise --pulse-period 2", "--pulse-period: shapes a pulse"},
      {"pulse --pga 0.3", "--pga: scales noise: a pulse is given by its --pgv"},
      {"pulse --seed 5", "--seed: shapes noise (and pairs): not a pulse"},
      {"pulse --site-frequency 3", "--site-frequency: shapes noise"},
      // Seeds are read in decimal: "010" was octal 8, "-1" wrapped to 2^64 - 1 and a seed past
      // 64 bits was saturated to it, so three different seeds gave one record.
      {"noise --seed 010", "--seed: '010' is not a whole number in decimal digits"},
      {"noise --seed 0x10", "--seed: '0x10' is not a whole number in decimal digits"},
      {"noise --seed -1", "--seed: -1 (must be a whole number >= 0)"},
      {"noise --seed 18446744073709551616", "--seed: 18446744073709551616 (too large"},
  };
  const auto output = isolab::testing::OwnTestFile("bad.at2");
  for (const auto& c : cases) {
    const auto run = RunIsolab("synth " + c.arguments + " -o " + output.string(), true);
    EXPECT_EQ(run.exit_code, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << c.arguments;
  }
}

// ASCE 7-16's shape with S_MS = 1.5 g, S_M1 = 0.9 g (T_S = 0.6 s), tabulated every 0.05 s from
// 0.05 s to 6 s, the corner included: linear interpolation between rows is exact on the plateau
// and within 0.2 % on the 1/T branch.
double Asce7(double period) { return period <= 0.6 ? 1.5 : 0.9 / period; }

std::filesystem::path WriteTargetTable(const std::filesystem::path& folder) {
  const auto path = folder / "design.csv";
  std::ofstream out(path);
  out << "# ASCE 7-16, S_MS 1.5 g, S_M1 0.9 g\nperiod_s,sa_g\n";
  for (int i = 1; i <= 120; ++i) out << 0.05 * i << "," << Asce7(0.05 * i) << "\n";
  return path;
}

TEST(SynthCommand, PairsMatchATargetTable) {
  const auto folder = isolab::testing::FreshTestDirectory();
  const auto table = WriteTargetTable(folder);
  const auto run = RunIsolab("synth --pairs 2 --target " + table.string() +
                             " --periods 0.5,4 --tolerance 0.1 --seed 7 --duration 30 --dt 0.01 "
                             "-o " +
                             folder.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* pair : {"pair 1: misfit 0.", "pair 2: misfit 0."}) {
    EXPECT_NE(run.output.find(pair), std::string::npos) << run.output;
  }
  EXPECT_EQ(run.output.find("NOT CONVERGED"), std::string::npos) << run.output;
  for (const char* file : {"pair1_h1.at2", "pair1_h2.at2", "pair2_h1.at2", "pair2_h2.at2"}) {
    EXPECT_TRUE(std::filesystem::exists(folder / file)) << file;
  }
  EXPECT_NE(Contents(folder / "pair1_h1.at2").find("NPTS=    3001, DT=   0.01000 SEC"),
            std::string::npos);
  // RotD100 of pair 2 as `isolab spectrum` measures it, against the shape.
  const auto spectrum =
      RunIsolab("spectrum " + (folder / "pair2_h1.at2").string() + " " +
                (folder / "pair2_h2.at2").string() + " --periods 0.5:4:0.05 --damping 0.05 --json");
  ASSERT_EQ(spectrum.exit_code, 0) << spectrum.output;
  const auto json = nlohmann::json::parse(spectrum.output);
  const auto periods = json["periods"].get<std::vector<double>>();
  const auto rotd100 = json["pair"][0]["rotd100"]["A_g"].get<std::vector<double>>();
  ASSERT_EQ(periods.size(), rotd100.size());
  double misfit = 0.0;
  for (std::size_t p = 0; p < periods.size(); ++p) {
    misfit = std::max(misfit, std::abs(rotd100[p] / Asce7(periods[p]) - 1.0));
  }
  EXPECT_LE(misfit, 0.1 + 0.003);  // the table's interpolation on the 1/T branch
}

TEST(SynthCommand, PairsAreNumberedToTheCountsWidth) {
  const auto folder = isolab::testing::FreshTestDirectory();
  const auto table = WriteTargetTable(folder);
  const auto run =
      RunIsolab("synth --pairs 10 --target " + table.string() +
                " --periods 0.2,2 --tolerance 0.5 --duration 10 -o " + folder.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("pair 01: misfit"), std::string::npos) << run.output;
  EXPECT_TRUE(std::filesystem::exists(folder / "pair01_h1.at2"));
  EXPECT_TRUE(std::filesystem::exists(folder / "pair10_h2.at2"));
}

TEST(SynthCommand, APairNotWithinTheToleranceExitsOneNamingIt) {
  const auto folder = isolab::testing::FreshTestDirectory();
  const auto table = WriteTargetTable(folder);
  // stdout and stderr together: the pair's line, then why the exit code is 1.
  const auto run = isolab::testing::RunCommandLine(
      std::string(ISOLAB_BINARY) + " synth --pairs 1 --target " + table.string() +
      " --periods 0.2,2 --tolerance 0.0001 --duration 10 -o " + folder.string() + " 2>&1");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("pair 1 did not converge"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("NOT CONVERGED"), std::string::npos) << run.output;
  EXPECT_TRUE(std::filesystem::exists(folder / "pair1_h1.at2"));
}

TEST(SynthCommand, BadPairOptionsAndTablesExitTwoNamingThemAndWriteNothing) {
  const auto folder = isolab::testing::FreshTestDirectory();
  const auto table = WriteTargetTable(folder).string();
  const auto write = [&](const char* name, const char* text) {
    std::ofstream(folder / name) << text;
    return (folder / name).string();
  };
  const auto no_header = write("no_header.csv", "0.1,1\n1,1\n");
  const auto decreasing = write("decreasing.csv", "period_s,sa_g\n1,1\n0.5,1\n");
  const auto negative = write("negative.csv", "period_s,sa_g\n0.1,1\n1,-1\n");
  const auto one_row = write("one_row.csv", "period_s,sa_g\n0.1,1\n");
  const auto words = write("words.csv", "period_s,sa_g\n0.1,one\n");
  const std::string out = " -o " + (folder / "out").string();
  std::filesystem::create_directories(folder / "out");
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"--pairs 0 --target " + table + out, "--pairs: 0 (must be at least 1 and at most 1000)"},
      {"--pairs 2" + out, "--pairs: needs --target"},
      {"pulse --pairs 2 --target " + table + out, "--pairs: matches pairs of filtered noise"},
      {"--pairs 2 --pga 0.3 --target " + table + out, "--pga: the pairs are scaled to --target"},
      {"noise --target " + table + " -o x.at2", "--target: matches pairs to a target spectrum"},
      {"noise --periods 0.5,4 -o x.at2", "--periods: matches pairs to a target spectrum"},
      {"pulse --dt 0.005 -o x.at2", "--dt: sets noise's step: not a pulse's"},
      {"pulse --duration 20 -o x.at2", "--duration: sets noise's length: not a pulse's"},
      {"--pairs 2 --periods 4,0.5 --target " + table + out, "--periods: 0.5 (must be > "},
      {"--pairs 2 --periods 0.5 --target " + table + out, "--periods: 1 value(s): give LO,HI"},
      {"--pairs 2 --periods 0.01,4 --target " + table + out, "--periods: 0.01 (must be >= 5"},
      // A quarter of the 30 s duration is 7.5 s; the table ends at 6 s.
      {"--pairs 2 --periods 0.5,8 --target " + table + out, "--periods: 8 (must be at most"},
      {"--pairs 2 --periods 0.5,7 --target " + table + out,
       "--periods: 0.5,7 s is not inside the periods of"},
      {"--pairs 2 --tolerance 0 --target " + table + out, "--tolerance: 0 (must be > 0)"},
      {"--pairs 2 --dt 0 --target " + table + out, "--dt: 0 (must be at least 0.001 s"},
      {"--pairs 2 --duration 1000 --target " + table + out,
       "--duration: 1000 (must be at most 600 s with --pairs)"},
      {"--pairs 2 --target " + table + " -o " + table, "is not a folder"},
      {"--pairs 2 --target " + no_header + out,
       "no_header.csv:1: header '0.1,1' (expected period_s,sa_g"},
      {"--pairs 2 --target " + decreasing + out,
       "decreasing.csv:3: period_s 0.5 does not increase from the previous row's 1"},
      {"--pairs 2 --target " + negative + out, "negative.csv:3: sa_g -1 (expected >= 0)"},
      {"--pairs 2 --target " + one_row + out, "one_row.csv: 1 row(s)"},
      {"--pairs 2 --target " + words + out, "words.csv:2: sa_g: 'one' is not a number"},
      {"--pairs 2 --target " + (folder / "missing.csv").string() + out,
       "missing.csv: cannot open the target spectrum"},
  };
  for (const auto& c : cases) {
    const auto run = RunIsolab("synth " + c.arguments, true);
    EXPECT_EQ(run.exit_code, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_TRUE(std::filesystem::is_empty(folder / "out")) << c.arguments;
  }
}

}  // namespace
