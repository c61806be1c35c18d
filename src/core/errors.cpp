#include "isolab/core/errors.h"

#include <fmt/format.h>

#include <cmath>

namespace isolab {

std::string ParameterViolation::Describe() const {
  if (std::isnan(value)) return fmt::format("{} ({})", key, rule);
  return fmt::format("{} = {:g} ({})", key, value, rule);
}

InvalidParameter::InvalidParameter(ParameterViolation violation)
    : std::invalid_argument(violation.Describe()), violation_(std::move(violation)) {}

std::string SourceLocation::Describe() const {
  if (line <= 0) return file;
  if (column <= 0) return fmt::format("{}:{}", file, line);
  return fmt::format("{}:{}:{}", file, line, column);
}

InputError::InputError(SourceLocation location, const std::string& what)
    : std::runtime_error(fmt::format("{}: {}", location.Describe(), what)),
      location_(std::move(location)) {}

ResourceError::ResourceError(const std::string& where, const std::string& what)
    : std::runtime_error(fmt::format("{}: {}", where, what)) {}

}  // namespace isolab
