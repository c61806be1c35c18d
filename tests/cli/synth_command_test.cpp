// `isolab synth` end to end: the bundled records come out byte for byte from their documented
// commands, a record whose tail needs three-digit exponents is read back by `isolab run`, and
// every option out of its range exits 2 naming it, with nothing written.
#include <gtest/gtest.h>

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
                             record.string() + " --dt 0.01 --json");
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
  };
  const auto output = isolab::testing::OwnTestFile("bad.at2");
  for (const auto& c : cases) {
    const auto run = RunIsolab("synth " + c.arguments + " -o " + output.string(), true);
    EXPECT_EQ(run.exit_code, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << c.arguments;
  }
}

}  // namespace
