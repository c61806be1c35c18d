// The summary of a study: every run's quantities in job order, each as a ratio to the reference
// variant's run on the same record and scale, and per variant and scale the mean and the max
// over the records whose runs completed, with their ratios to the reference's mean and max.
// Sums run in record order, so the summary depends only on the results, never on who ran them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "isolab/model/study_file.h"
#include "isolab/study/job_result.h"

namespace isolab::study {

struct StudyShape {
  std::vector<std::string> variants;
  std::vector<std::string> records;
  std::vector<std::string> record_files;  // may be empty
  std::vector<double> scales;
  std::size_t reference = 0;
  std::vector<std::string> units;  // per quantity, QuantityUnit
  // The quantities summaries show, in order (StudyQuantities).
  std::vector<Quantity> quantities = StudyQuantities(false);
};

StudyShape ShapeOf(const model::StudyFile& study);

struct Statistic {
  std::size_t completed = 0;  // runs over which mean and max are taken
  QuantityValues mean = NoValues(), max = NoValues();
  QuantityValues mean_ratio = NoValues(), max_ratio = NoValues();  // to the reference's
};

struct Summary {
  StudyShape shape;
  std::vector<JobResult> runs;         // in job order
  std::vector<QuantityValues> ratios;  // per run; NaN where either value is missing or 0
  std::vector<Statistic> statistics;   // per variant and scale: variant * scales + scale

  std::size_t failed() const;
  const Statistic& At(std::size_t variant, std::size_t scale) const {
    return statistics[variant * shape.scales.size() + scale];
  }
};

// `runs` holds one result per job, in any order; throws std::invalid_argument otherwise.
Summary BuildSummary(StudyShape shape, std::vector<JobResult> runs);

}  // namespace isolab::study
