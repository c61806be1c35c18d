// The one reader of numbers in isolab's inputs: model, study and fit files, records, test data
// and command-line options all read their numbers here, so none lets NaN or infinity through.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace isolab {

// The finite number the whole of `text` spells ("2", "-1.5e-3", "+4"), or nullopt when it is not
// one, with `*problem` (when given) saying why: "'abc' is not a number", "'nan' is not a finite
// number" (also inf, infinity and YAML's .nan/.inf in any case), "'1e999' is out of range".
std::optional<double> ParseFiniteNumber(std::string_view text, std::string* problem = nullptr);

// The plain finite number at the start of `text` (no '+', no NaN or infinity, in range) and the
// characters it took, or nullopt: what ParseFiniteNumber accepts, read without knowing where the
// token ends, for a reader that splits a line itself (a record's columns). A token this does not
// read whole goes to ParseFiniteNumber, which takes or refuses it and says why. Inline: a
// record's reader calls it once a number.
inline std::optional<double> ReadPlainFiniteNumber(std::string_view text, std::size_t* length) {
  double value = 0.0;
  const auto [last, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || !std::isfinite(value)) return std::nullopt;
  *length = static_cast<std::size_t>(last - text.data());
  return value;
}

}  // namespace isolab
