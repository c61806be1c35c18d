#include "isolab/building/shake_table_measurements.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "isolab/core/errors.h"
#include "isolab/io/shake_table_file.h"

namespace isolab::building {
namespace {

double LevelRms(const Signal& x) {
  double square = 0.0;
  for (const double v : x) square += v * v;
  return std::sqrt(square / x.size());
}

double Correlation(const Signal& x, const Signal& y, std::size_t skip) {
  double xy = 0, xx = 0, yy = 0, mx = 0, my = 0;
  const std::size_t n = x.size() - 2 * skip;
  for (std::size_t k = skip; k + skip < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  for (std::size_t k = skip; k + skip < x.size(); ++k) {
    xy += (x[k] - mx) * (y[k] - my);
    xx += (x[k] - mx) * (x[k] - mx);
    yy += (y[k] - my) * (y[k] - my);
  }
  return xx > 0 && yy > 0 ? xy / std::sqrt(xx * yy) : 0.0;
}

// Second derivative by central differences (ends copied from their neighbours).
Signal SecondDerivative(const Signal& u, const Signal& t) {
  Signal a(u.size(), 0.0);
  for (std::size_t k = 1; k + 1 < u.size(); ++k) {
    const double h1 = t[k] - t[k - 1], h2 = t[k + 1] - t[k];
    a[k] = 2.0 * (h1 * u[k + 1] - (h1 + h2) * u[k] + h2 * u[k - 1]) / (h1 * h2 * (h1 + h2));
  }
  if (a.size() > 2) a.front() = a[1], a.back() = a[a.size() - 2];
  return a;
}

std::vector<int> ParseLevels(const std::string& text) {
  std::vector<int> channels;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    try {
      std::size_t used = 0;
      channels.push_back(std::stoi(item, &used));
      if (used != item.size() || channels.back() < 1) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError({"command line"},
                       fmt::format("--levels {}: '{}' is not a channel number (expected e.g. "
                                   "6,5,4,3,2,1 from the isolation slab up, or auto)",
                                   text, item));
    }
    // One channel for two levels would count its floor's inertia twice in the base shear.
    const auto first = std::find(channels.begin(), channels.end() - 1, channels.back());
    if (first != channels.end() - 1) {
      throw InputError(
          {"command line"},
          fmt::format("--levels {}: channel {} is given twice (levels {} and {}); "
                      "each level has its own channel",
                      text, channels.back(), first - channels.begin() + 1, channels.size()));
    }
  }
  return channels;
}

// The model's levels as the messages name them.
std::string ModelLevels(std::size_t levels) {
  return levels == 1
             ? "1 level (an SDOF's mass)"
             : fmt::format("{} levels (the isolation slab and {} floors)", levels, levels - 1);
}

}  // namespace

LevelMeasurements ReadShakeTableMeasurements(const std::string& path,
                                             const ShakeTableChannels& options,
                                             const UnitSystem& units, std::size_t levels) {
  const io::ShakeTableData data = io::ShakeTableData::Read(path);
  LevelMeasurements m;
  m.time = data.time();
  // Sensor offsets: before the table moves the building is at rest, so what an accelerometer
  // reads then is its offset. The pre-event window ends where the table acceleration first
  // exceeds 5 % of its peak; --offsets none keeps the channels as recorded.
  std::size_t quiet = 0;
  if (options.offsets == "pre-event") {
    const Signal table = data.Channel(options.table_acceleration, dimension::kAcceleration, units);
    double peak = 0.0;
    for (const double v : table) peak = std::max(peak, std::abs(v));
    while (quiet < table.size() && std::abs(table[quiet]) <= 0.05 * peak) ++quiet;
    if (quiet < 10) quiet = 0;  // no quiet start: nothing to read an offset from
  }
  const auto acceleration = [&](const std::string& name) {
    Signal a = data.Channel(name, dimension::kAcceleration, units);
    if (quiet > 0) {
      const double offset = std::accumulate(a.begin(), a.begin() + quiet, 0.0) / quiet;
      for (double& v : a) v -= offset;
    }
    return a;
  };
  m.table_acceleration = acceleration(options.table_acceleration);
  std::vector<int> channels;
  if (options.levels == "auto") {
    // Every level channel of the file, which the model's levels must match: the first of a
    // larger building's channels would be its upper floors, read as the slab and the floors above.
    std::size_t in_file = 0;
    while (data.Has(fmt::format("{}{}", options.acceleration_prefix, in_file + 1))) ++in_file;
    if (in_file != levels) {
      const std::string& a = options.acceleration_prefix;
      const std::string found =
          in_file == 0   ? fmt::format("no level channel ({}1)", a)
          : in_file == 1 ? fmt::format("1 level channel ({}1)", a)
                         : fmt::format("{} level channels ({}1 to {}{})", in_file, a, a, in_file);
      throw InputError({path}, fmt::format("--levels auto: the file has {} and the model {}; give "
                                           "--levels with the {} channels to use, slab first, or "
                                           "a model of the file's levels",
                                           found, ModelLevels(levels), levels));
    }
    for (std::size_t k = 1; k <= levels; ++k) channels.push_back(static_cast<int>(k));
  } else {
    channels = ParseLevels(options.levels);
    if (channels.size() != levels) {
      throw InputError({"command line"}, fmt::format("--levels names {} channels; the model has {}",
                                                     channels.size(), ModelLevels(levels)));
    }
  }
  std::vector<Signal> a, u;
  for (const int c : channels) {
    a.push_back(acceleration(fmt::format("{}{}", options.acceleration_prefix, c)));
    u.push_back(data.Channel(fmt::format("{}{}", options.displacement_prefix, c),
                             dimension::kLength, units));
  }
  // Relative or absolute: the displacement's second derivative follows the acceleration
  // relative to the table (a - a_table) if it is relative, a itself if absolute.
  bool relative = options.displacements == "relative";
  if (options.displacements == "auto") {
    double to_relative = 0.0, to_absolute = 0.0;
    const std::size_t skip = std::min<std::size_t>(200, m.time.size() / 10);
    for (std::size_t l = 0; l < a.size(); ++l) {
      Signal rel(a[l].size());
      for (std::size_t k = 0; k < rel.size(); ++k) rel[k] = a[l][k] - m.table_acceleration[k];
      const Signal ddu = SecondDerivative(u[l], m.time);
      to_relative += Correlation(ddu, rel, skip) / a.size();
      to_absolute += Correlation(ddu, a[l], skip) / a.size();
    }
    relative = to_relative >= to_absolute;
    m.reference_note = fmt::format(
        "displacements taken as {} the table: their second derivative correlates {:.3f} with "
        "the acceleration relative to the table and {:.3f} with the absolute one (mean over "
        "levels)",
        relative ? "relative to" : "absolute, less", to_relative, to_absolute);
  } else {
    m.reference_note =
        fmt::format("displacements {} (as given)", relative ? "relative to the table" : "absolute");
  }
  if (!relative) {  // only then is the table's displacement needed
    const Signal table_u = data.Channel(options.table_displacement, dimension::kLength, units);
    for (Signal& s : u) {
      for (std::size_t k = 0; k < s.size(); ++k) s[k] -= table_u[k];
    }
  }
  if (options.levels == "auto") {
    // In an isolated building the slab moves least relative to the table and the roof most.
    std::vector<std::size_t> order(channels.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return LevelRms(u[x]) < LevelRms(u[y]); });
    for (const std::size_t i : order) {
      m.channels.push_back(channels[i]);
      m.acceleration.push_back(a[i]);
      m.displacement.push_back(u[i]);
    }
  } else {
    m.channels = channels;
    m.acceleration = std::move(a);
    m.displacement = std::move(u);
  }
  return m;
}

}  // namespace isolab::building
