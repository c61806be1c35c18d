#include "isolab/study/summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isolab::study {
namespace {

// What a statistic or ratio is when it has no value (a ratio to zero, the mean of no record).
constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

double Ratio(double value, double reference) {
  if (!std::isfinite(value) || !std::isfinite(reference) || reference == 0.0) return kNoValue;
  return value / reference;
}

QuantityValues Ratios(const QuantityValues& values, const QuantityValues& reference) {
  QuantityValues ratios;
  for (std::size_t q = 0; q < kQuantityCount; ++q) ratios[q] = Ratio(values[q], reference[q]);
  return ratios;
}

}  // namespace

StudyShape ShapeOf(const model::StudyFile& study) {
  StudyShape shape;
  for (const model::StudyVariant& variant : study.variants) shape.variants.push_back(variant.name);
  for (const model::StudyRecord& record : study.records) {
    shape.records.push_back(record.name);
    const auto& c = record.components;
    shape.record_files.push_back(
        c.size() > 1 ? fmt::format("{} + {} at {:g} degrees", c[0].file, c[1].file, record.angle)
                     : c[0].file);
  }
  shape.quantities = StudyQuantities(study.rotations);
  shape.scales = study.scales;
  shape.reference = study.reference;
  for (const QuantityInfo& info : Quantities()) {
    shape.units.push_back(QuantityUnit(info.quantity, study.units));
  }
  return shape;
}

std::size_t Summary::failed() const {
  return static_cast<std::size_t>(
      std::count_if(runs.begin(), runs.end(), [](const JobResult& r) { return !r.completed; }));
}

Summary BuildSummary(StudyShape shape, std::vector<JobResult> runs) {
  const std::size_t V = shape.variants.size(), R = shape.records.size(), S = shape.scales.size();
  if (runs.size() != V * R * S || shape.reference >= V) {
    throw std::invalid_argument(fmt::format("{} results for {} x {} x {} jobs (reference {})",
                                            runs.size(), V, R, S, shape.reference));
  }
  std::sort(runs.begin(), runs.end(),
            [](const JobResult& a, const JobResult& b) { return a.job < b.job; });
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (runs[k].job != k) throw std::invalid_argument(fmt::format("no result for job {}", k));
  }
  Summary summary;
  summary.shape = std::move(shape);
  summary.runs = std::move(runs);
  const auto job = [&](std::size_t v, std::size_t r, std::size_t s) { return (v * R + r) * S + s; };
  const std::size_t ref = summary.shape.reference;

  summary.ratios.resize(summary.runs.size());
  for (std::size_t v = 0; v < V; ++v) {
    for (std::size_t r = 0; r < R; ++r) {
      for (std::size_t s = 0; s < S; ++s) {
        summary.ratios[job(v, r, s)] =
            Ratios(summary.runs[job(v, r, s)].values, summary.runs[job(ref, r, s)].values);
      }
    }
  }

  summary.statistics.resize(V * S);
  for (std::size_t v = 0; v < V; ++v) {
    for (std::size_t s = 0; s < S; ++s) {
      Statistic& statistic = summary.statistics[v * S + s];
      for (std::size_t q = 0; q < kQuantityCount; ++q) {
        double sum = 0.0, max = kNoValue;
        std::size_t count = 0;
        for (std::size_t r = 0; r < R; ++r) {
          const JobResult& run = summary.runs[job(v, r, s)];
          const double value = run.values[q];
          if (!run.completed || !std::isfinite(value)) continue;
          sum += value;
          max = std::isnan(max) ? value : std::max(max, value);
          ++count;
        }
        statistic.mean[q] = count > 0 ? sum / static_cast<double>(count) : kNoValue;
        statistic.max[q] = max;
      }
      for (std::size_t r = 0; r < R; ++r)
        statistic.completed += summary.runs[job(v, r, s)].completed;
    }
  }
  for (std::size_t v = 0; v < V; ++v) {
    for (std::size_t s = 0; s < S; ++s) {
      Statistic& statistic = summary.statistics[v * S + s];
      const Statistic& reference = summary.statistics[ref * S + s];
      statistic.mean_ratio = Ratios(statistic.mean, reference.mean);
      statistic.max_ratio = Ratios(statistic.max, reference.max);
    }
  }
  return summary;
}

}  // namespace isolab::study
