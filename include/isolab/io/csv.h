// Writing CSV that reads back exactly: fields quoted where they must be, numbers as the shortest
// decimal that reads back as the same double.
#pragma once

#include <string>
#include <vector>

namespace isolab::io {

// `text` as a CSV field: quoted (with doubled quotes) when it holds a comma, quote or line break.
std::string CsvField(const std::string& text);

// Shortest decimal that reads back as the same double; empty for NaN and infinities.
std::string ExactNumber(double value);

// One line of fields, comma-separated, each through CsvField, ending in '\n'.
std::string CsvLine(const std::vector<std::string>& fields);

}  // namespace isolab::io
