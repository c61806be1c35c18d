#include "isolab/io/cyclic_test_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "csv_fields.h"
#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/core/text_file.h"
#include "isolab/io/atomic_file.h"
#include "units_line.h"

namespace isolab::io {
namespace {

using identification::CyclicTestData;

// "# specimen: one, in order" (or "independent").
void ReadSpecimenComment(const std::string& path, int line_number, const std::string& line,
                         bool* one_specimen) {
  const auto colon = line.find(':');
  if (Lower(line).find("specimen") == std::string::npos || colon == std::string::npos) return;
  const std::string value = Lower(Trim(line.substr(colon + 1)));
  if (value.rfind("one", 0) == 0) {
    *one_specimen = true;
  } else if (value.rfind("independent", 0) != 0) {
    throw InputError({path, line_number},
                     fmt::format("specimen: '{}' (expected 'one, in order' or 'independent')",
                                 Trim(line.substr(colon + 1))));
  }
}

void ReadFile(const std::string& path, const CyclicTestUnits& given, const UnitSystem& into,
              std::vector<CyclicTestData>* tests, bool* one_specimen, bool* has_units) {
  TextLines in(path);
  if (!in.is_open()) throw InputError({path}, "cannot open the test data");
  std::map<std::string, int> column;
  std::map<std::string, std::size_t> test_index;
  double force_factor = 1.0, length_factor = 1.0;
  UnitsLine declared;
  int line_number = 0, header_line = 0;
  const std::size_t tests_before = tests->size();
  for (std::string line; in.Next(&line);) {
    ++line_number;
    line = Trim(line);
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (column.empty()) {
        *has_units = ReadUnitsLine(line, line_number, &declared) || *has_units;
        ReadSpecimenComment(path, line_number, line, one_specimen);
      }
      continue;
    }
    const std::vector<std::string> fields = Split(line);
    if (column.empty()) {  // the header
      header_line = line_number;
      for (std::size_t k = 0; k < fields.size(); ++k)
        column[Lower(fields[k])] = static_cast<int>(k);
      for (const char* needed : {"time", "displacement", "force"}) {
        if (!column.count(needed)) {
          throw InputError({path, line_number},
                           fmt::format("missing column '{}' (expected test,time,displacement,"
                                       "force; test optional)",
                                       needed));
        }
      }
      const ResolvedUnits units =
          ResolveUnits(path, declared, given.force, given.length, "kN", "mm");
      try {
        force_factor = into.Convert(1.0, units.force, dimension::kForce);
        length_factor = into.Convert(1.0, units.length, dimension::kLength);
      } catch (const std::invalid_argument& error) {
        throw InputError({path, line_number}, fmt::format("units: {}", error.what()));
      }
      continue;
    }
    const auto field = [&](const char* name) -> const std::string& {
      const int k = column.at(name);
      if (k >= static_cast<int>(fields.size())) {
        throw InputError({path, line_number}, fmt::format("no value in column '{}'", name));
      }
      return fields[k];
    };
    const auto number = [&](const char* name) {
      std::string problem;
      const std::optional<double> value = ParseFiniteNumber(field(name), &problem);
      if (!value)
        throw InputError({path, line_number}, fmt::format("column '{}': {}", name, problem));
      return *value;
    };
    const std::string name =
        column.count("test") ? field("test") : std::filesystem::path(path).stem().string();
    auto [it, inserted] = test_index.try_emplace(name, tests->size());
    if (inserted) tests->push_back({name, {}, {}, {}, {}, {}});
    CyclicTestData& test = (*tests)[it->second];
    const double time = number("time");
    if (!test.time.empty() && !(time > test.time.back())) {
      throw InputError({path, line_number},
                       fmt::format("column 'time': {} does not increase from the previous sample "
                                   "of test '{}' ({}); two tests under one name?",
                                   time, name, test.time.back()));
    }
    test.time.push_back(time);
    test.displacement.push_back(number("displacement") * length_factor);
    test.force.push_back(number("force") * force_factor);
  }
  if (column.empty()) throw InputError({path}, "the file is empty (expected a header line)");
  if (tests->size() == tests_before) {
    throw InputError({path, header_line},
                     "a header and no samples: nothing to identify (expected rows of "
                     "test,time,displacement,force after it)");
  }
}

// The range a channel spans: a constant one carries nothing to identify.
double RangeOf(const std::vector<double>& values) {
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return *high - *low;
}

}  // namespace

CyclicTestSet ReadCyclicTests(const std::vector<std::string>& paths,
                              const CyclicTestUnits& file_units, const UnitSystem& into) {
  // A file given twice (another spelling, a link) would count its tests twice: in the fit's
  // weights and in the range the fitted model is said to hold over.
  for (std::size_t j = 1; j < paths.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      std::error_code error;
      if (std::filesystem::equivalent(paths[i], paths[j], error)) {
        throw InputError({paths[j]},
                         fmt::format("is '{}' given again: each data file is read once", paths[i]));
      }
    }
  }
  CyclicTestSet set;
  std::vector<CyclicTestData>& tests = set.tests;
  for (const std::string& path : paths) {
    const std::size_t first = tests.size();
    bool has_units = false;
    ReadFile(path, file_units, into, &tests, &set.one_specimen, &has_units);
    if (!has_units) set.without_units.push_back(path);
    set.source.resize(tests.size(), path);
    for (std::size_t i = first; i < tests.size(); ++i) {
      CyclicTestData& test = tests[i];
      if (RangeOf(test.force) == 0.0) {
        throw InputError({path}, fmt::format("test '{}': the force is {:g} throughout (a dead "
                                             "channel?): nothing to identify, and e^2 weighs each "
                                             "test by its force's variation",
                                             test.name, test.force.front()));
      }
      if (RangeOf(test.displacement) == 0.0) {
        throw InputError({path}, fmt::format("test '{}': the displacement is {:g} throughout: "
                                             "nothing to identify",
                                             test.name, test.displacement.front()));
      }
      identification::Segment(&test);
      if (test.half_cycles.empty()) {
        throw InputError(
            {path},
            fmt::format("test '{}': too short to identify anything: {} samples and no half-cycle "
                        "between two reversals (a reversal is a turn of the displacement by more "
                        "than {:g} % of its range)",
                        test.name, test.time.size(), 100 * identification::kReversalBand));
      }
    }
  }
  return set;
}

bool OneSpecimen(const std::string& option, bool from_files) {
  if (option.empty()) return from_files;
  if (option == "sequential") return true;
  if (option == "independent") return false;
  throw InputError({"command line"},
                   fmt::format("--specimen {} (expected sequential or independent)", option));
}

void WriteCyclicTests(const std::string& path, const std::vector<CyclicTestData>& tests,
                      const UnitSystem& units, bool one_specimen) {
  WriteTextFileAtomically(path, [&](std::ostream& out) {
    out << fmt::format("# units: force {}, length {}\n", units.force(), units.length());
    if (one_specimen) out << "# specimen: one, in order\n";
    out << "test,time,displacement,force\n";
    for (const CyclicTestData& test : tests) {
      for (std::size_t k = 0; k < test.time.size(); ++k) {
        out << fmt::format("{},{:.6f},{:.9g},{:.9g}\n", test.name, test.time[k],
                           test.displacement[k], test.force[k]);
      }
    }
  });
}

}  // namespace isolab::io
