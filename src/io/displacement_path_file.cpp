#include "isolab/io/displacement_path_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "csv_fields.h"
#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/core/text_file.h"
#include "units_line.h"

namespace isolab::io {
namespace {

// The first of `names` that is a column, or -1.
int Column(const std::map<std::string, int>& columns, std::initializer_list<const char*> names) {
  for (const char* name : names) {
    if (const auto it = columns.find(name); it != columns.end()) return it->second;
  }
  return -1;
}

void ReadFile(const std::string& path, const std::string& given_force,
              const std::string& given_length, const UnitSystem& into, DisplacementPathSet* set) {
  TextLines in(path);
  if (!in.is_open()) {
    throw InputError({path},
                     fmt::format("cannot open the displacement path ({})", std::strerror(errno)));
  }
  std::map<std::string, int> columns;
  int time = -1, test = -1, ux = -1, uy = -1, fx = -1, fy = -1;
  double force_factor = 1.0, length_factor = 1.0;
  bool has_units = false, header = false;
  UnitsLine declared;
  std::map<std::string, std::size_t> index;
  const std::size_t first = set->paths.size();
  for (std::string line; in.Next(&line);) {
    const int line_number = in.line_number();
    line = Trim(line);
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (!header && ReadUnitsLine(line, line_number, &declared)) has_units = true;
      continue;
    }
    const std::vector<std::string> fields = Split(line);
    if (!header) {
      header = true;
      for (std::size_t k = 0; k < fields.size(); ++k) columns[Lower(fields[k])] = int(k);
      time = Column(columns, {"time"});
      test = Column(columns, {"test"});
      ux = Column(columns, {"displacement_x", "ux"});
      uy = Column(columns, {"displacement_y", "uy"});
      fx = Column(columns, {"force_x", "fx"});
      fy = Column(columns, {"force_y", "fy"});
      const bool two = ux >= 0 || uy >= 0;
      if (!two) {
        ux = Column(columns, {"displacement", "u"});
        fx = Column(columns, {"force"});
      }
      if (time < 0 || ux < 0 || (two && uy < 0)) {
        throw InputError({path, line_number},
                         "expected columns time and displacement (one direction) or "
                         "displacement_x and displacement_y (two), force or force_x and force_y "
                         "optional, test optional");
      }
      if (uy >= 0 && (fx >= 0) != (fy >= 0)) {
        throw InputError({path, line_number}, "force_x and force_y go together");
      }
      const ResolvedUnits units =
          ResolveUnits(path, declared, given_force, given_length, into.force(), into.length());
      try {
        force_factor = into.Convert(1.0, units.force, dimension::kForce);
        length_factor = into.Convert(1.0, units.length, dimension::kLength);
      } catch (const std::invalid_argument& error) {
        throw InputError({path, line_number}, fmt::format("units: {}", error.what()));
      }
      continue;
    }
    const auto number = [&](int column) {
      if (column >= static_cast<int>(fields.size())) {
        throw InputError({path, line_number},
                         fmt::format("no value in column {} (of {})", column + 1, fields.size()));
      }
      std::string problem;
      const std::optional<double> value = ParseFiniteNumber(fields[column], &problem);
      if (!value) {
        throw InputError({path, line_number}, fmt::format("column {}: {}", column + 1, problem));
      }
      return *value;
    };
    const std::string name = test >= 0 && test < static_cast<int>(fields.size())
                                 ? fields[test]
                                 : std::filesystem::path(path).stem().string();
    auto [it, inserted] = index.try_emplace(name, set->paths.size());
    if (inserted) set->paths.push_back({name, {}, {}, {}, uy >= 0});
    DisplacementPath& p = set->paths[it->second];
    const double t = number(time);
    if (!p.time.empty() && !(t > p.time.back())) {
      throw InputError({path, line_number},
                       fmt::format("time {} does not increase from the previous sample of '{}' "
                                   "({})",
                                   t, name, p.time.back()));
    }
    p.time.push_back(t);
    p.displacement.push_back(
        {length_factor * number(ux), uy >= 0 ? length_factor * number(uy) : 0.0});
    if (fx >= 0) {
      p.force.push_back({force_factor * number(fx), fy >= 0 ? force_factor * number(fy) : 0.0});
    }
  }
  if (!header) throw InputError({path}, "the file is empty (expected a header line)");
  if (set->paths.size() == first) {
    throw InputError({path}, "a header and no samples: no path to follow");
  }
  for (std::size_t i = first; i < set->paths.size(); ++i) {
    if (set->paths[i].time.size() < 2) {
      throw InputError({path}, fmt::format("'{}': one sample is no path", set->paths[i].name));
    }
  }
  if (!has_units) set->without_units.push_back(path);
}

}  // namespace

DisplacementPathSet ReadDisplacementPaths(const std::vector<std::string>& files,
                                          const std::string& force_unit,
                                          const std::string& length_unit, const UnitSystem& into) {
  DisplacementPathSet set;
  for (const std::string& file : files) ReadFile(file, force_unit, length_unit, into, &set);
  return set;
}

}  // namespace isolab::io
