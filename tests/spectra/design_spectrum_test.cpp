// Code design spectra (design_spectrum.h) against values worked by hand from the codes'
// equations, written out beside each check: ASCE 7-16 Sec. 11.4.6 (Eqs. 11.4-5 to 11.4-7) and
// EN 1998-1:2004 Sec. 3.2.2.2 (Eqs. 3.2 to 3.6, Tables 3.2 and 3.3, copied here again from the
// standard so a slip in the source's table shows); continuity at every corner; the refusals.
#include "isolab/spectra/design_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "refused_key.h"

namespace isolab::spectra {
namespace {

constexpr double kTight = 1e-12;

using testing::RefusedKey;

// S_MS 1.5 g, S_M1 0.9 g, T_L 8 s: T_0 = 0.2 x 0.9 / 1.5 = 0.12 s, T_s = 0.9 / 1.5 = 0.6 s.
const Asce7Spectrum kAsce{1.5, 0.9, 8.0};

TEST(DesignSpectrum, Asce7OnEachBranch) {
  // T = 0: 1.5 x 0.4 = 0.6 g.
  EXPECT_NEAR(SpectralAcceleration(kAsce, 0.0), 0.6, kTight);
  // T = 0.06 s = T_0 / 2: 1.5 (0.4 + 0.6 x 0.5) = 1.05 g.
  EXPECT_NEAR(SpectralAcceleration(kAsce, 0.06), 1.05, kTight);
  // The plateau, 0.12 to 0.6 s: 1.5 g.
  EXPECT_NEAR(SpectralAcceleration(kAsce, 0.12), 1.5, kTight);
  EXPECT_NEAR(SpectralAcceleration(kAsce, 0.3), 1.5, kTight);
  EXPECT_NEAR(SpectralAcceleration(kAsce, 0.6), 1.5, kTight);
  // S_M1 / T: 0.9 / 1.5 = 0.6 g, 0.9 / 3 = 0.3 g, 0.9 / 8 = 0.1125 g.
  EXPECT_NEAR(SpectralAcceleration(kAsce, 1.5), 0.6, kTight);
  EXPECT_NEAR(SpectralAcceleration(kAsce, 3.0), 0.3, kTight);
  EXPECT_NEAR(SpectralAcceleration(kAsce, 8.0), 0.1125, kTight);
  // S_M1 T_L / T^2: 0.9 x 8 / 100 = 0.072 g at 10 s.
  EXPECT_NEAR(SpectralAcceleration(kAsce, 10.0), 0.072, kTight);
  // T_L = 4 s moves the last branch: 0.9 x 4 / 25 = 0.144 g at 5 s.
  EXPECT_NEAR(SpectralAcceleration(Asce7Spectrum{1.5, 0.9, 4.0}, 5.0), 0.144, kTight);
}

TEST(DesignSpectrum, Asce7CornersAndContinuity) {
  const std::vector<double> corners = CornerPeriods(kAsce);
  ASSERT_EQ(corners.size(), 3u);
  EXPECT_NEAR(corners[0], 0.12, kTight);
  EXPECT_NEAR(corners[1], 0.6, kTight);
  EXPECT_EQ(corners[2], 8.0);
  for (const double corner : corners) {
    const double below = SpectralAcceleration(kAsce, corner * (1 - 1e-10));
    const double above = SpectralAcceleration(kAsce, corner * (1 + 1e-10));
    EXPECT_NEAR(below, above, 1e-8 * above) << corner;
  }
}

// EN 1998-1 Table 3.2 (type 1) and Table 3.3 (type 2): S, T_B, T_C, T_D per ground type A to E.
struct Row {
  GroundType ground;
  int type;
  double soil, tb, tc, td;
};
const Row kTables[] = {
    {GroundType::kA, 1, 1.0, 0.15, 0.4, 2.0},   {GroundType::kB, 1, 1.2, 0.15, 0.5, 2.0},
    {GroundType::kC, 1, 1.15, 0.20, 0.6, 2.0},  {GroundType::kD, 1, 1.35, 0.20, 0.8, 2.0},
    {GroundType::kE, 1, 1.4, 0.15, 0.5, 2.0},   {GroundType::kA, 2, 1.0, 0.05, 0.25, 1.2},
    {GroundType::kB, 2, 1.35, 0.05, 0.25, 1.2}, {GroundType::kC, 2, 1.5, 0.10, 0.25, 1.2},
    {GroundType::kD, 2, 1.8, 0.10, 0.30, 1.2},  {GroundType::kE, 2, 1.6, 0.05, 0.25, 1.2}};

TEST(DesignSpectrum, Eurocode8TablesEveryGroundType) {
  for (const Row& row : kTables) {
    const Eurocode8Spectrum spectrum{0.2, row.ground, row.type, 1.0, 0.05};
    const std::vector<double> corners = CornerPeriods(spectrum);
    ASSERT_EQ(corners.size(), 3u);
    EXPECT_EQ(corners[0], row.tb);
    EXPECT_EQ(corners[1], row.tc);
    EXPECT_EQ(corners[2], row.td);
    const double ag_s = 0.2 * row.soil;  // eta = 1 at 5 %
    EXPECT_NEAR(SpectralAcceleration(spectrum, 0.0), ag_s, kTight);
    EXPECT_NEAR(SpectralAcceleration(spectrum, 0.5 * (row.tb + row.tc)), 2.5 * ag_s, kTight);
    EXPECT_NEAR(SpectralAcceleration(spectrum, 0.5 * (row.tc + row.td)),
                2.5 * ag_s * row.tc / (0.5 * (row.tc + row.td)), kTight);
    EXPECT_NEAR(SpectralAcceleration(spectrum, 3.0), 2.5 * ag_s * row.tc * row.td / 9.0, kTight);
    for (const double corner : corners) {
      const double below = SpectralAcceleration(spectrum, corner * (1 - 1e-10));
      const double above = SpectralAcceleration(spectrum, corner * (1 + 1e-10));
      EXPECT_NEAR(below, above, 1e-8 * above) << corner;
    }
  }
}

TEST(DesignSpectrum, Eurocode8OnEachBranch) {
  // Type 1, ground B, a_gR 0.3 g, 5 %: S 1.2, T_B 0.15, T_C 0.5, T_D 2; a_g S = 0.36 g, eta 1.
  const Eurocode8Spectrum b{0.3, GroundType::kB, 1, 1.0, 0.05};
  EXPECT_NEAR(SpectralAcceleration(b, 0.0), 0.36, kTight);
  // T = T_B / 2: 0.36 (1 + 0.5 x 1.5) = 0.63 g.
  EXPECT_NEAR(SpectralAcceleration(b, 0.075), 0.63, kTight);
  // Plateau 0.36 x 2.5 = 0.9 g.
  EXPECT_NEAR(SpectralAcceleration(b, 0.15), 0.9, kTight);
  EXPECT_NEAR(SpectralAcceleration(b, 0.3), 0.9, kTight);
  // 0.9 x 0.5 / 1 = 0.45 g; at T_D 0.9 x 0.5 / 2 = 0.225 g.
  EXPECT_NEAR(SpectralAcceleration(b, 1.0), 0.45, kTight);
  EXPECT_NEAR(SpectralAcceleration(b, 2.0), 0.225, kTight);
  // 0.9 x 0.5 x 2 / 9 = 0.1 g at 3 s; 0.9 / 16 = 0.05625 g at 4 s, the last period defined.
  EXPECT_NEAR(SpectralAcceleration(b, 3.0), 0.1, kTight);
  EXPECT_NEAR(SpectralAcceleration(b, 4.0), 0.05625, kTight);

  // Type 2, ground D, gamma_I 1.2 x a_gR 0.25 = a_g 0.3 g, 10 %: S 1.8, T_B 0.1, T_C 0.3,
  // T_D 1.2; eta = sqrt(10 / 15) = sqrt(2/3); a_g S = 0.54 g.
  const Eurocode8Spectrum d{0.25, GroundType::kD, 2, 1.2, 0.10};
  const double eta = std::sqrt(2.0 / 3.0);
  EXPECT_NEAR(SpectralAcceleration(d, 0.05), 0.54 * (1 + 0.5 * (2.5 * eta - 1)), kTight);
  EXPECT_NEAR(SpectralAcceleration(d, 0.2), 0.54 * 2.5 * eta, kTight);
  EXPECT_NEAR(SpectralAcceleration(d, 0.6), 0.54 * 2.5 * eta * 0.5, kTight);   // T_C / T = 0.5
  EXPECT_NEAR(SpectralAcceleration(d, 2.0), 0.54 * 2.5 * eta * 0.09, kTight);  // 0.36 / 4

  // eta's floor: 30 % gives sqrt(10 / 35) = 0.534 < 0.55, so 0.55; 0 % gives sqrt(2).
  Eurocode8Spectrum heavily_damped = b;
  heavily_damped.damping_ratio = 0.30;
  EXPECT_NEAR(SpectralAcceleration(heavily_damped, 0.3), 0.36 * 2.5 * 0.55, kTight);
  Eurocode8Spectrum undamped = b;
  undamped.damping_ratio = 0.0;
  EXPECT_NEAR(SpectralAcceleration(undamped, 0.3), 0.36 * 2.5 * std::sqrt(2.0), kTight);
  // T = 0 is a_g S whatever the damping.
  EXPECT_NEAR(SpectralAcceleration(heavily_damped, 0.0), 0.36, kTight);
}

TEST(DesignSpectrum, TableInterpolatesLinearlyBetweenItsPoints) {
  const TabulatedSpectrum table{{0.1, 0.5, 2.0}, {0.5, 1.0, 0.2}, "site.csv"};
  EXPECT_EQ(SpectralAcceleration(table, 0.1), 0.5);
  EXPECT_EQ(SpectralAcceleration(table, 0.5), 1.0);
  EXPECT_EQ(SpectralAcceleration(table, 2.0), 0.2);
  // Half-way from 0.1 to 0.5 s: 0.75 g; from 0.5 to 2 s, at 1.25 s: 1 - 0.5 x 0.8 = 0.6 g.
  EXPECT_NEAR(SpectralAcceleration(table, 0.3), 0.75, kTight);
  EXPECT_NEAR(SpectralAcceleration(table, 1.25), 0.6, kTight);
  EXPECT_EQ(CornerPeriods(table), (std::vector<double>{0.1, 0.5, 2.0}));
  EXPECT_EQ(RefusedKey([&] { SpectralAcceleration(table, 0.09); }), "period");
  EXPECT_EQ(RefusedKey([&] { SpectralAcceleration(table, 2.01); }), "period");
}

TEST(DesignSpectrum, DescribesEachInOneLine) {
  EXPECT_EQ(Describe(kAsce), "ASCE 7-16 MCE_R: S_MS 1.5 g, S_M1 0.9 g, T_L 8 s");
  EXPECT_EQ(Describe(Eurocode8Spectrum{0.3, GroundType::kB, 1, 1.0, 0.05}),
            "Eurocode 8 type 1, ground B: a_g 0.3 g (gamma_I 1 x a_gR 0.3 g), 5 % damping");
  EXPECT_EQ(Describe(Eurocode8Spectrum{0.25, GroundType::kE, 2, 1.2, 0.1}),
            "Eurocode 8 type 2, ground E: a_g 0.3 g (gamma_I 1.2 x a_gR 0.25 g), 10 % damping");
  EXPECT_EQ(Describe(TabulatedSpectrum{{0.01, 10.0}, {0.4, 0.05}, "site.csv"}),
            "table from site.csv, 0.01 to 10 s");
}

TEST(DesignSpectrum, RefusesEachBadFieldByName) {
  EXPECT_EQ(RefusedKey([] { Validate(Asce7Spectrum{0.0, 0.9, 8.0}); }), "sms");
  EXPECT_EQ(RefusedKey([] { Validate(Asce7Spectrum{1.5, -0.9, 8.0}); }), "sm1");
  EXPECT_EQ(RefusedKey([] { Validate(Asce7Spectrum{1.5, 0.9, 0.0}); }), "tl");
  EXPECT_EQ(RefusedKey([] { Validate(Asce7Spectrum{1.5, NAN, 8.0}); }), "sm1");
  // T_L below T_s = 0.6 s would make Sa jump at T_s.
  EXPECT_EQ(RefusedKey([] { Validate(Asce7Spectrum{1.5, 0.9, 0.5}); }), "tl");
  EXPECT_EQ(RefusedKey([] { Validate(Asce7Spectrum{1.5, 0.9, 0.6}); }), "");

  EXPECT_EQ(RefusedKey([] {
              Validate(Eurocode8Spectrum{0.0, GroundType::kB, 1, 1.0, 0.05});
            }),
            "agr");
  EXPECT_EQ(RefusedKey([] {
              Validate(Eurocode8Spectrum{0.3, GroundType::kB, 3, 1.0, 0.05});
            }),
            "type");
  EXPECT_EQ(RefusedKey([] {
              Validate(Eurocode8Spectrum{0.3, GroundType::kB, 0, 1.0, 0.05});
            }),
            "type");
  EXPECT_EQ(RefusedKey([] {
              Validate(Eurocode8Spectrum{0.3, GroundType::kB, 1, 0.0, 0.05});
            }),
            "importance");
  EXPECT_EQ(RefusedKey([] {
              Validate(Eurocode8Spectrum{0.3, GroundType::kB, 1, 1.0, -0.01});
            }),
            "damping_ratio");
  EXPECT_EQ(RefusedKey([] {
              Validate(Eurocode8Spectrum{0.3, GroundType::kB, 1, 1.0, 1.0});
            }),
            "damping_ratio");

  EXPECT_EQ(RefusedKey([] { Validate(TabulatedSpectrum{{0.1}, {0.5}, ""}); }), "periods");
  EXPECT_EQ(RefusedKey([] { Validate(TabulatedSpectrum{{0.1, 0.2}, {0.5}, ""}); }), "sa");
  EXPECT_EQ(RefusedKey([] {
              Validate(TabulatedSpectrum{{0.1, 0.1}, {0.5, 0.4}, ""});
            }),
            "periods[1]");
  EXPECT_EQ(RefusedKey([] {
              Validate(TabulatedSpectrum{{0.2, 0.1}, {0.5, 0.4}, ""});
            }),
            "periods[1]");
  EXPECT_EQ(RefusedKey([] {
              Validate(TabulatedSpectrum{{-0.1, 0.1}, {0.5, 0.4}, ""});
            }),
            "periods[0]");
  EXPECT_EQ(RefusedKey([] { Validate(TabulatedSpectrum{{0.0, 0.1}, {0.5, -0.4}, ""}); }), "sa[1]");
  EXPECT_EQ(RefusedKey([] { Validate(TabulatedSpectrum{{0.0, 0.1}, {0.5, 0.0}, ""}); }), "");

  // Periods: negative or not finite for any; beyond 4 s for Eurocode 8 (its Sec. 3.2.2.2 range).
  EXPECT_EQ(RefusedKey([] { SpectralAcceleration(kAsce, -0.1); }), "period");
  EXPECT_EQ(RefusedKey([] { SpectralAcceleration(kAsce, INFINITY); }), "period");
  const Eurocode8Spectrum b{0.3, GroundType::kB, 1, 1.0, 0.05};
  EXPECT_EQ(RefusedKey([&] { SpectralAcceleration(b, 4.01); }), "period");
  // An invalid spectrum is refused when asked for a value, naming the field.
  EXPECT_EQ(RefusedKey([] { SpectralAcceleration(Asce7Spectrum{}, 1.0); }), "sms");
}

}  // namespace
}  // namespace isolab::spectra
