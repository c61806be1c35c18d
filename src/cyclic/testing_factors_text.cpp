#include "isolab/cyclic/testing_factors_text.h"

#include <fmt/format.h>

namespace isolab::cyclic {
namespace {

std::string Pair(const identification::PropertyFactors& f) {
  return fmt::format("[{:.4g}, {:.4g}]", f.min, f.max);
}

}  // namespace

std::string TestingFactorsText(const identification::TestingFactors& factors,
                               const UnitSystem& units) {
  const std::string& L = units.length();
  const std::string& F = units.force();
  std::string text =
      "testing factors from the tests' first three cycles (ASCE 7-16 17.2.8.4; Qd = E / (4 D), "
      "Kd = k_eff - Qd / D):\n";
  if (factors.empty()) {
    return text + "  none: no test has three whole cycles\n";
  }
  text += fmt::format("{:<14} {:>5} {:>10} {:>12} {:>14} {:>10} {:>12}\n", "test", "cycle",
                      fmt::format("D [{}]", L), fmt::format("k_eff [{}/{}]", F, L),
                      fmt::format("E [{}*{}]", F, L), fmt::format("Qd [{}]", F),
                      fmt::format("Kd [{}/{}]", F, L));
  for (const identification::TestProperties& t : factors.tests) {
    for (std::size_t c = 0; c < t.cycles.size(); ++c) {
      const identification::CycleProperties& p = t.cycles[c];
      text +=
          fmt::format("{:<14} {:>5} {:>10.5g} {:>12.5g} {:>14.6g} {:>10.5g} {:>12.5g}\n", t.test,
                      c + 1, p.amplitude, p.effective_stiffness, p.dissipated, p.qd, p.kd);
    }
  }
  text += fmt::format(
      "lambda_test over the tests: Qd {}, Kd {} (each cycle's over the mean of "
      "its test's three: the nominal at that amplitude)\n",
      Pair(factors.qd), Pair(factors.kd));
  if (!factors.skipped.empty()) {
    text += fmt::format("  (not counted, fewer than three whole cycles: {})\n",
                        fmt::join(factors.skipped, ", "));
  }
  return text;
}

std::vector<std::string> TestingFactorsComment(const identification::TestingFactors& factors,
                                               const UnitSystem& units) {
  if (factors.empty()) return {};
  return {
      fmt::format("Testing factors of ASCE 7-16 17.2.8.4 from the tests' first three cycles, each "
                  "cycle's Qd and Kd over its test's mean (isolab fit prints them per cycle, in "
                  "{} and {}): Qd {}, Kd {}. For a bearing given by its Qd and Kd (lead_rubber: "
                  "qd, kd):",
                  units.force(), units.length(), Pair(factors.qd), Pair(factors.kd)),
      fmt::format("  modification: {{<component>: {{qd: {{testing: {}}}, kd: {{testing: {}}}}}}}",
                  Pair(factors.qd), Pair(factors.kd))};
}

nlohmann::json TestingFactorsJson(const identification::TestingFactors& factors) {
  nlohmann::json json;
  for (const identification::TestProperties& t : factors.tests) {
    for (std::size_t c = 0; c < t.cycles.size(); ++c) {
      const identification::CycleProperties& p = t.cycles[c];
      json["cycles"].push_back({{"test", t.test},
                                {"cycle", c + 1},
                                {"amplitude", p.amplitude},
                                {"effective_stiffness", p.effective_stiffness},
                                {"dissipated", p.dissipated},
                                {"qd", p.qd},
                                {"kd", p.kd}});
    }
  }
  for (const auto& [key, f] : {std::pair{"qd", factors.qd}, std::pair{"kd", factors.kd}}) {
    json[key] = {{"nominal", f.nominal}, {"min", f.min}, {"max", f.max}};
  }
  json["skipped"] = factors.skipped;
  return json;
}

}  // namespace isolab::cyclic
