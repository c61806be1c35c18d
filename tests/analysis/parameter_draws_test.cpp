// The parameter draws of a prediction band (analysis/parameter_draws.h) against moments computed
// in the test: with a model form, the draws' covariance in ln p is the fit's covariance plus the
// mean outer product of the model-form fits' offsets from the fit to every motion, and the draws
// are centred on the model's own values. Beyond the identified range the offsets widen by the
// stated factor. The model form is read with its errors located.
#include "isolab/analysis/parameter_draws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/three_story_building.h"
#include "isolab/analysis/building_parameters.h"
#include "isolab/core/errors.h"

namespace isolab::analysis {
namespace {

using testing::BuildingText;
using testing::kBilinear;
using testing::Model;

const char* const kUncertainty =
    "uncertainty:\n"
    "  parameters: [{name: isolation.iso.k1, value: 1.5, log: true},\n"
    "               {name: stories.stiffness, value: 60, log: true}]\n"
    "  covariance: [[0.0004, 0.0001], [0.0001, 0.0009]]\n";

TEST(ParameterDraws, TheModelFormAddsTheFitsSpreadToTheCovarianceAboutTheModelsValues) {
  const model::ModelFile model = Model(BuildingText(kBilinear) + kUncertainty +
                                       "  model_form:\n"
                                       "    - {fitted_on: [weak], values: [1.8, 54]}\n"
                                       "    - {fitted_on: [strong], values: [1.2, 63]}\n");
  ASSERT_EQ(model.uncertainty->model_form.size(), 2u);
  // The covariance the draws must have, in (ln k1, ln k): the fit's plus (d1 d1^T + d2 d2^T) / 2.
  const double d[2][2] = {{std::log(1.8 / 1.5), std::log(54.0 / 60.0)},
                          {std::log(1.2 / 1.5), std::log(63.0 / 60.0)}};
  const double fit[2][2] = {{0.0004, 0.0001}, {0.0001, 0.0009}};
  double expected[2][2];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      expected[i][j] = fit[i][j] + 0.5 * (d[0][i] * d[0][j] + d[1][i] * d[1][j]);
    }
  }
  const Eigen::MatrixXd drawn = DrawnCovariance(*model.uncertainty);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(drawn(i, j), expected[i][j], 1e-15);
  }
  // The draws themselves: 40,000 sets, their sample moments within a few standard errors (a
  // variance's relative standard error is sqrt(2 / n) = 0.7 %; 3 % allows four of them).
  ParameterDraws draws(model, 5);
  const int n = 40000;
  double sum[2] = {0, 0}, square[2][2] = {{0, 0}, {0, 0}};
  for (int s = 0; s < n; ++s) {
    const model::ModelFile drawn_model = draws.Next();
    const double x[2] = {std::log(ParameterValue(drawn_model, "isolation.iso.k1")),
                         std::log(ParameterValue(drawn_model, "stories.stiffness"))};
    for (int i = 0; i < 2; ++i) {
      sum[i] += x[i];
      for (int j = 0; j < 2; ++j) square[i][j] += x[i] * x[j];
    }
  }
  const double centre[2] = {std::log(1.5), std::log(60.0)};
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(sum[i] / n, centre[i], 4 * std::sqrt(expected[i][i] / n)) << i;
    for (int j = 0; j < 2; ++j) {
      const double covariance = square[i][j] / n - (sum[i] / n) * (sum[j] / n);
      const double scale = std::sqrt(expected[i][i] * expected[j][j]);
      EXPECT_NEAR(covariance, expected[i][j], 0.03 * scale) << i << "," << j;
    }
  }
  EXPECT_EQ(BandContents(model),
            "the parameters' uncertainty and the spread of 2 fits to subsets of the motions "
            "(model form, weighted alike)");
}

// Beyond the identified range the draws' offsets are multiplied by how far the run goes past it
// (the larger of the displacement and velocity ratios), once that passes the 1.1 margin; within
// it, and for a model without an identified range, they are not. With the same seed a widened
// draw is the model's values plus exactly that multiple of the unwidened draw's offset.
// Three motions whose own fits would give m_1, m_2, m_3 (in ln p), a fit that averages them (as a
// linear least-squares fit of equally weighted motions does): the fit to every motion is their
// mean and each held-out fit the mean of the other two. The model form must then add the spread of
// the three motions' own values about their mean, (1/3) sum (m_j - mean)^2, which the held-out
// fits alone, each two thirds of the way back to the mean, would understate fourfold.
TEST(ParameterDraws, WithThreeMotionsTheModelFormIsTheSpreadOfWhatEachMotionAloneGives) {
  const double m[3][2] = {{std::log(1.2), std::log(50.0)},
                          {std::log(1.5), std::log(66.0)},
                          {std::log(2.1), std::log(58.0)}};
  double mean[2] = {0, 0};
  for (const auto& motion : m) mean[0] += motion[0] / 3, mean[1] += motion[1] / 3;
  const auto held_out = [&](int j, int p) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) sum += k == j ? 0.0 : m[k][p] / 2;
    return std::exp(sum);
  };
  std::string text =
      BuildingText(kBilinear) + "uncertainty:\n  parameters: [" +
      "{name: isolation.iso.k1, value: " + std::to_string(std::exp(mean[0])) +
      ", log: true}, {name: stories.stiffness, value: " + std::to_string(std::exp(mean[1])) +
      ", log: true}]\n" + "  covariance: [[0, 0], [0, 0]]\n  model_form:\n";
  for (int j = 0; j < 3; ++j) {
    text += "    - {fitted_on: [m" + std::to_string(j) + "], values: [" +
            std::to_string(held_out(j, 0)) + ", " + std::to_string(held_out(j, 1)) + "]}\n";
  }
  const model::ModelFile model = Model(text);
  const Eigen::MatrixXd drawn = DrawnCovariance(*model.uncertainty);
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      double spread = 0.0;
      for (const auto& motion : m) spread += (motion[a] - mean[a]) * (motion[b] - mean[b]) / 3;
      // std::to_string's six decimals of the values written above: 1e-6 relative in ln p.
      EXPECT_NEAR(drawn(a, b), spread, 2e-5 * std::abs(spread) + 1e-9) << a << "," << b;
    }
  }
}

TEST(ParameterDraws, BeyondTheIdentifiedRangeTheOffsetsGrowByHowFarTheRunGoes) {
  model::ModelFile model = Model(BuildingText(kBilinear) + kUncertainty);
  EXPECT_EQ(BandWidening(model, 500.0, 5000.0), 1.0);  // no identified range
  model.identified_range = identification::IdentifiedRange{100.0, 300.0, 5.0, {"m"}};
  EXPECT_EQ(BandWidening(model, 109.0, 320.0), 1.0);  // within 1.1 times both
  EXPECT_DOUBLE_EQ(BandWidening(model, 230.0, 200.0), 2.3);
  EXPECT_DOUBLE_EQ(BandWidening(model, 50.0, 400.0), 4.0 / 3.0);
  ParameterDraws plain(model, 9), widened(model, 9, 2.3);
  for (int s = 0; s < 5; ++s) {
    const model::ModelFile a = plain.Next(), b = widened.Next();
    for (const char* name : {"isolation.iso.k1", "stories.stiffness"}) {
      const double centre = std::log(ParameterValue(model, name));
      EXPECT_NEAR(std::log(ParameterValue(b, name)) - centre,
                  2.3 * (std::log(ParameterValue(a, name)) - centre), 1e-12)
          << name;
    }
  }
  EXPECT_EQ(BandContents(model, 2.3),
            "the parameters' uncertainty, widened 2.30 times beyond the identified range (a "
            "stated rule: past the last measured cycle the laws are assumed, not measured)");
}

// A prior (a parameter given, not fitted) is drawn independently, log-normally with its sigma
// about the model's own value (an edited 7 here, not the prior's 6), unwidened, from a stream of
// its own; a prior naming a fitted parameter is refused where it is.
TEST(ParameterDraws, APriorIsDrawnWithItsSigmaAboutTheModelsValue) {
  const std::string prior =
      "  priors: [{name: isolation.iso.uy, value: 6, sigma: 0.2, source: design data}]\n";
  model::ModelFile model = Model(BuildingText(kBilinear) + kUncertainty + prior);
  SetParameters(&model, std::vector<std::string>{"isolation.iso.uy"}, std::vector<double>{7.0});
  ParameterDraws draws(model, 11, 3.0);
  const int n = 20000;
  double sum = 0.0, square = 0.0;
  for (int s = 0; s < n; ++s) {
    const double x = std::log(ParameterValue(draws.Next(), "isolation.iso.uy"));
    sum += x, square += x * x;
  }
  const double mean = sum / n, sd = std::sqrt(square / n - mean * mean);
  EXPECT_NEAR(mean, std::log(7.0), 4 * 0.2 / std::sqrt(double(n)));
  EXPECT_NEAR(sd, 0.2, 0.03 * 0.2);  // sqrt(1 / (2 n)) = 0.5 % relative; 3 % allows six
  EXPECT_EQ(BandContents(model),
            "the parameters' uncertainty, with 1 parameter from a prior (isolation.iso.uy: "
            "design data)");
  // The prior draws from its own stream: the fitted parameters' draws are those without it.
  model::ModelFile without = model;
  without.uncertainty->priors.clear();
  ParameterDraws a(model, 4), b(without, 4);
  for (int s = 0; s < 3; ++s) {
    EXPECT_EQ(ParameterValue(a.Next(), "isolation.iso.k1"),
              ParameterValue(b.Next(), "isolation.iso.k1"));
  }
  try {
    Model(BuildingText(kBilinear) + kUncertainty +
          "  priors: [{name: isolation.iso.k1, value: 2, sigma: 0.2, source: x}]\n");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("uncertainty.priors[0].name: 'isolation.iso.k1' is fitted: a prior gives"),
              std::string::npos)
        << error.what();
  }
}

TEST(ParameterDraws, AModelFormWithTheWrongCountOrANonPositiveLogValueIsRefusedWhereItIs) {
  const auto error = [](const std::string& model_form) {
    try {
      Model(BuildingText(kBilinear) + kUncertainty + "  model_form:\n" + model_form);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(error("    - {fitted_on: [a], values: [1.8]}\n    - {fitted_on: [b], values: [1, 2]}\n")
                .find("uncertainty.model_form[0].values: expected 2 numbers, one per parameter"),
            std::string::npos);
  EXPECT_NE(error("    - {fitted_on: [a], values: [1.8, 60]}\n"
                  "    - {fitted_on: [b], values: [-1, 60]}\n")
                .find("uncertainty.model_form[1].values[0]: must be > 0"),
            std::string::npos);
  EXPECT_NE(
      error("    - {fitted_on: [a], value: [1.8, 60]}\n    - {fitted_on: [b], values: [1, 2]}\n")
          .find("model_form[0]"),
      std::string::npos);
  EXPECT_NE(error("    - {fitted_on: [a], values: [1.8, 60]}\n")
                .find("uncertainty.model_form: expected at least two fits"),
            std::string::npos);
}

}  // namespace
}  // namespace isolab::analysis
