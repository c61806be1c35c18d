// The building fit's JSON, one function for `isolab fit --building --json` and Python: the 95 %
// interval is a factor exp(+-1.96 sigma) on a log parameter and +-1.96 sigma on a linear one, and
// the object carries what both fronts promise.
#include "isolab/building/building_fit_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace isolab::building {
namespace {

TEST(BuildingFitReport, IntervalsAndTheJsonBothFrontsReturn) {
  BuildingFitResult result;
  result.parameters.push_back({"isolation.iso.k1", 0.6, 0.4, 0.1, 2.0, true, 0.05, false});
  result.parameters.push_back({"damping.ratio", 0.02, 0.03, 0.0, 0.2, false, 0.01, true});
  result.channels.push_back({"ica50", "d1", 0.5, 0.01});
  result.objective_start = 0.25;
  result.objective = 1e-4;
  result.refinement.stop = identification::RefinementStop::kConverged;
  const auto [low, high] = Interval95(result.parameters[0]);
  EXPECT_NEAR(low, 0.4 * std::exp(-1.96 * 0.05), 1e-15);
  EXPECT_NEAR(high, 0.4 * std::exp(1.96 * 0.05), 1e-15);
  const auto [linear_low, linear_high] = Interval95(result.parameters[1]);
  EXPECT_NEAR(linear_low, 0.03 - 1.96 * 0.01, 1e-15);
  EXPECT_NEAR(linear_high, 0.03 + 1.96 * 0.01, 1e-15);

  const auto json = nlohmann::json::parse(BuildingFitJson(result, true, "fitted.yaml"));
  EXPECT_EQ(json["parameters"][1]["at_bound"], true);
  EXPECT_NEAR(json["parameters"][0]["interval_95"][1].get<double>(), high, 1e-15);
  EXPECT_EQ(json["channels"][0]["channel"], "d1");
  EXPECT_EQ(json["stop"], "converged");
  EXPECT_EQ(json["sequential"], true);
  EXPECT_EQ(json["output"], "fitted.yaml");
  EXPECT_FALSE(json.contains("identified_range"));  // none in the fitted model
  EXPECT_FALSE(json.contains("not_separated"));
  EXPECT_TRUE(json["priors"].empty());  // no uncertainty, so nothing given
}

}  // namespace
}  // namespace isolab::building
