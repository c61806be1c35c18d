// Error values shared by every area: a broken parameter rule, and bad input with its location.
#pragma once

#include <stdexcept>
#include <string>

namespace isolab {

// One parameter that breaks one rule, e.g. key "k1", value 1.3, rule "must be < k0 = 1".
// Laws report these without knowing where the value came from; readers add the location.
struct ParameterViolation {
  std::string key;
  double value = 0.0;
  std::string rule;

  // "k1 = 1.3 (must be < k0 = 1)"; a missing key reads "k1 (is required)".
  std::string Describe() const;
};

// Thrown by parameter constructors (never inside a time step) when a rule is broken.
class InvalidParameter : public std::invalid_argument {
 public:
  explicit InvalidParameter(ParameterViolation violation);
  const ParameterViolation& violation() const { return violation_; }

 private:
  ParameterViolation violation_;
};

// Where in an input file something was found. Lines and columns count from 1; 0 means unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;

  // "models/lrb.yaml:14:5", or just the file name when the line is unknown.
  std::string Describe() const;
};

// Bad user input (file, record, option): the message says where, what and what was allowed.
// The command line turns it into exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation location, const std::string& what);
  const SourceLocation& location() const { return location_; }

 private:
  SourceLocation location_;
};

// The input is fine but the machine ran out of something while working: disk space (a write
// failed) or memory. The command line turns it into exit code 3. (isolab's own work limits, such
// as the number of steps, are checked before the work and are bad input: InputError, exit 2.)
class ResourceError : public std::runtime_error {
 public:
  ResourceError(const std::string& where, const std::string& what);
};

}  // namespace isolab
