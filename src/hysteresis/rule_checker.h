// Checks a law's parameter rules in the order written and throws InvalidParameter at the first
// one broken, naming the key as the user wrote it. Private to the hysteresis library.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <string_view>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"

namespace isolab::hysteresis {

using ParameterArray = std::array<double, kMaxLawParameters>;
using Keys = std::span<const std::string_view>;

class RuleChecker {
 public:
  RuleChecker(Keys keys, const ParameterArray& values) : keys_(keys), values_(values) {}

  double operator()(std::string_view key) const { return values_[Index(key)]; }

  void Greater(std::string_view key, double bound, std::string_view bound_text = {}) const {
    Check(key, (*this)(key) > bound, ">", bound, bound_text);
  }
  void AtLeast(std::string_view key, double bound, std::string_view bound_text = {}) const {
    Check(key, (*this)(key) >= bound, ">=", bound, bound_text);
  }
  void Less(std::string_view key, double bound, std::string_view bound_text = {}) const {
    Check(key, (*this)(key) < bound, "<", bound, bound_text);
  }
  // A rule on a combination: "ke + kh2 > 0".
  void Holds(std::string_view key, bool ok, std::string rule) const {
    if (!ok) throw InvalidParameter({std::string(key), (*this)(key), std::move(rule)});
  }

 private:
  std::size_t Index(std::string_view key) const {
    return static_cast<std::size_t>(std::find(keys_.begin(), keys_.end(), key) - keys_.begin());
  }
  void Check(std::string_view key, bool ok, std::string_view op, double bound,
             std::string_view bound_text) const {
    if (ok) return;
    const std::string rule = bound_text.empty()
                                 ? fmt::format("must be {} {:g}", op, bound)
                                 : fmt::format("must be {} {} = {:g}", op, bound_text, bound);
    throw InvalidParameter({std::string(key), (*this)(key), rule});
  }

  Keys keys_;
  const ParameterArray& values_;
};

}  // namespace isolab::hysteresis
