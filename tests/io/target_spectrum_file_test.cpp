// The CSV of a tabulated target spectrum (target_spectrum_file.h): the values read back exactly
// as written, comments and blank lines skipped, and each malformed file refused at its line with
// what was expected. Files are written into the test's own directory (own_test_file.h).
#include "isolab/io/target_spectrum_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab::io {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  const auto path = isolab::testing::OwnTestDirectory() / name;
  std::ofstream(path) << text;
  return path.string();
}

// The InputError reading `text` gives: its line (0 when none is named) and message.
struct Refusal {
  int line = -1;
  std::string message;
};
Refusal Refused(const std::string& text) {
  const std::string path = Write("bad.csv", text);
  try {
    ReadTargetSpectrumCsv(path);
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().file, path);
    return {error.location().line, error.what()};
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

TEST(TargetSpectrumFile, ReadsPointsSkippingCommentsAndBlankLines) {
  const std::string path = Write("site.csv",
                                 "# site-specific MCE_R, 5 %\n"
                                 "\n"
                                 "period_s,sa_g\n"
                                 "0.0, 0.6\n"
                                 "# the plateau\n"
                                 "0.2,1.5\n"
                                 "\n"
                                 " 1.0 ,0.9\r\n"
                                 "4,2.25e-1\n");
  const spectra::TabulatedSpectrum table = ReadTargetSpectrumCsv(path);
  EXPECT_EQ(table.periods, (std::vector<double>{0.0, 0.2, 1.0, 4.0}));
  EXPECT_EQ(table.sa, (std::vector<double>{0.6, 1.5, 0.9, 0.225}));
  EXPECT_EQ(table.source, path);
  // Linear between points: half-way from 1 to 4 s, (0.9 + 0.225) / 2 = 0.5625 g.
  EXPECT_NEAR(spectra::SpectralAcceleration(table, 2.5), 0.5625, 1e-12);
  EXPECT_EQ(spectra::Describe(table), "table from " + path + ", 0 to 4 s");
}

TEST(TargetSpectrumFile, HeaderIsCaseBlind) {
  const spectra::TabulatedSpectrum table =
      ReadTargetSpectrumCsv(Write("upper.csv", "Period_s, SA_g\n0.1,0.5\n1,0.4\n"));
  EXPECT_EQ(table.periods, (std::vector<double>{0.1, 1.0}));
}

TEST(TargetSpectrumFile, RefusesMalformedFilesAtTheirLine) {
  Refusal r = Refused("# only a comment\nperiod,sa\n0.1,0.5\n1,0.4\n");
  EXPECT_EQ(r.line, 2);
  EXPECT_NE(r.message.find("expected period_s,sa_g"), std::string::npos) << r.message;

  r = Refused("period_s,sa_g,extra\n0.1,0.5,1\n");
  EXPECT_EQ(r.line, 1);

  r = Refused("period_s,sa_g\n0.1,0.5\n0.5,abc\n");
  EXPECT_EQ(r.line, 3);
  EXPECT_NE(r.message.find("sa_g: 'abc' is not a number"), std::string::npos) << r.message;

  r = Refused("period_s,sa_g\n0.1,0.5\nnan,0.4\n");
  EXPECT_EQ(r.line, 3);
  EXPECT_NE(r.message.find("period_s"), std::string::npos) << r.message;

  r = Refused("period_s,sa_g\n0.1,0.5\n0.5\n");
  EXPECT_EQ(r.line, 3);
  EXPECT_NE(r.message.find("expected 2"), std::string::npos) << r.message;

  r = Refused("period_s,sa_g\n0.5,0.5\n\n0.5,0.4\n");
  EXPECT_EQ(r.line, 4);
  EXPECT_NE(r.message.find("strictly increasing"), std::string::npos) << r.message;

  r = Refused("period_s,sa_g\n0.5,0.5\n0.4,0.4\n");
  EXPECT_EQ(r.line, 3);

  r = Refused("period_s,sa_g\n-0.1,0.5\n0.4,0.4\n");
  EXPECT_EQ(r.line, 2);
  EXPECT_NE(r.message.find("expected >= 0"), std::string::npos) << r.message;

  r = Refused("period_s,sa_g\n0.1,0.5\n0.4,-0.4\n");
  EXPECT_EQ(r.line, 3);
  EXPECT_NE(r.message.find("sa_g -0.4 (expected >= 0)"), std::string::npos) << r.message;

  // Whole-file problems name no line.
  r = Refused("period_s,sa_g\n0.1,0.5\n");
  EXPECT_EQ(r.line, 0);
  EXPECT_NE(r.message.find("expected at least 2"), std::string::npos) << r.message;
  r = Refused("# nothing\n\n");
  EXPECT_EQ(r.line, 0);
  EXPECT_NE(r.message.find("no header"), std::string::npos) << r.message;
}

TEST(TargetSpectrumFile, RefusesAMissingFileAndADirectory) {
  const std::string missing = (isolab::testing::FreshTestDirectory() / "none.csv").string();
  EXPECT_THROW(ReadTargetSpectrumCsv(missing), InputError);
  EXPECT_THROW(ReadTargetSpectrumCsv(isolab::testing::OwnTestDirectory().string()), InputError);
}

}  // namespace
}  // namespace isolab::io
