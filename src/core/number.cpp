#include "isolab/core/number.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace isolab {
namespace {

// NaN and infinity in the spellings from_chars, strtod and YAML accept, without the sign.
bool SpellsNonFinite(std::string_view text) {
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.remove_prefix(1);
  if (!text.empty() && text.front() == '.') text.remove_prefix(1);
  // Every such spelling starts with an n or an i; a number never does.
  if (text.empty() ||
      !(text.front() == 'n' || text.front() == 'N' || text.front() == 'i' || text.front() == 'I')) {
    return false;
  }
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower == "nan" || lower.rfind("nan(", 0) == 0 || lower == "inf" || lower == "infinity";
}

}  // namespace

std::optional<double> ParseFiniteNumber(std::string_view text, std::string* problem) {
  const auto fail = [&](const char* why) -> std::optional<double> {
    if (problem != nullptr) *problem = fmt::format("'{}' {}", text, why);
    return std::nullopt;
  };
  if (SpellsNonFinite(text)) return fail("is not a finite number");
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  // from_chars takes no '+'; a second sign after it ("+-1") is still refused below.
  if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-') ++begin;
  double value = 0.0;
  const auto [last, error] = std::from_chars(begin, end, value);
  if (error == std::errc::result_out_of_range && last == end) return fail("is out of range");
  if (text.empty() || error != std::errc() || last != end) return fail("is not a number");
  if (!std::isfinite(value)) return fail("is not a finite number");
  return value;
}

}  // namespace isolab
