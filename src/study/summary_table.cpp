#include "isolab/study/summary_table.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace isolab::study {
namespace {

// Four significant digits without an exponent: 1234, 123.4, 12.34, 0.1234, down to 0.00001234
// (a floor's rotation in rad).
std::string Value(double value) {
  if (!std::isfinite(value)) return "-";
  const double magnitude = std::abs(value);
  const int digits = magnitude > 0.0 ? static_cast<int>(std::floor(std::log10(magnitude))) : 0;
  return fmt::format("{:.{}f}", value, std::clamp(3 - digits, 0, 8));
}

std::string Ratio(double ratio) {
  return std::isfinite(ratio) ? fmt::format("{:.3f}", ratio) : "-";
}

}  // namespace

void PrintSummaryTable(const Summary& summary, std::ostream& out) {
  const StudyShape& shape = summary.shape;
  const std::size_t R = shape.records.size(), S = shape.scales.size();
  std::size_t variant_width = 7, record_width = 10;  // "variant", "mean / ref"
  for (const std::string& v : shape.variants) variant_width = std::max(variant_width, v.size());
  for (const std::string& r : shape.records) record_width = std::max(record_width, r.size());
  if (summary.failed() > 0) {
    record_width = std::max(record_width, fmt::format("mean ({} of {})", R, R).size());
  }
  std::vector<std::string> headings;
  for (const Quantity q : shape.quantities) {
    headings.push_back(
        fmt::format("{} [{}]", InfoOf(q).label, shape.units[static_cast<std::size_t>(q)]));
  }

  const auto row = [&](const std::string& variant, const std::string& record,
                       const std::vector<std::string>& cells) {
    fmt::print(out, "{:<{}}  {:<{}}", variant, variant_width, record, record_width);
    for (std::size_t q = 0; q < cells.size(); ++q) {
      fmt::print(out, "  {:>{}}", cells[q], std::max<std::size_t>(headings[q].size(), 8));
    }
    fmt::print(out, "\n");
  };
  const auto values = [&shape](const QuantityValues& v, std::string (*format)(double)) {
    std::vector<std::string> cells;
    for (const Quantity q : shape.quantities) {
      cells.push_back(format(v[static_cast<std::size_t>(q)]));
    }
    return cells;
  };

  for (std::size_t s = 0; s < S; ++s) {
    fmt::print(out, "{}scale {} (ratios to {})\n", s > 0 ? "\n" : "", shape.scales[s],
               shape.variants[shape.reference]);
    row("variant", "record", headings);
    for (std::size_t v = 0; v < shape.variants.size(); ++v) {
      for (std::size_t r = 0; r < R; ++r) {
        const JobResult& run = summary.runs[(v * R + r) * S + s];
        const std::string variant = r == 0 ? shape.variants[v] : "";
        if (run.completed) {
          row(variant, shape.records[r], values(run.values, Value));
        } else {
          fmt::print(out, "{:<{}}  {:<{}}  failed: {}\n", variant, variant_width, shape.records[r],
                     record_width, run.message);
        }
      }
      const Statistic& statistic = summary.At(v, s);
      const std::string over =
          statistic.completed == R ? "" : fmt::format(" ({} of {})", statistic.completed, R);
      row("", "mean" + over, values(statistic.mean, Value));
      row("", "max" + over, values(statistic.max, Value));
      row("", "mean / ref", values(statistic.mean_ratio, Ratio));
    }
  }
}

}  // namespace isolab::study
