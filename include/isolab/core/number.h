// The one reader of numbers in isolab's inputs: model, study and fit files, records, test data
// and command-line options all read their numbers here, so none lets NaN or infinity through.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace isolab {

// The finite number the whole of `text` spells ("2", "-1.5e-3", "+4"), or nullopt when it is not
// one, with `*problem` (when given) saying why: "'abc' is not a number", "'nan' is not a finite
// number" (also inf, infinity and YAML's .nan/.inf in any case), "'1e999' is out of range".
std::optional<double> ParseFiniteNumber(std::string_view text, std::string* problem = nullptr);

}  // namespace isolab
