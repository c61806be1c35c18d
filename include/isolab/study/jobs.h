// The runs of a study: every variant x record x scale, variant first, then record, then scale,
// so job k is always the same run whatever schedules it. Records keep the study's order (each
// glob sorted by name).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "isolab/model/study_file.h"
#include "isolab/study/job_result.h"

namespace isolab::study {

struct Job {
  std::size_t index = 0;  // (variant * records + record) * scales + scale
  std::size_t variant = 0, record = 0, scale = 0;
};

std::vector<Job> ExpandJobs(std::size_t variants, std::size_t records, std::size_t scales);
std::vector<Job> ExpandJobs(const model::StudyFile& study);

// "1.5": a scale as it appears in labels and file names (shortest exact decimal).
std::string ScaleName(double scale);

// "thm1 / fwn_firm_seed1 x1.5", for progress lines.
std::string JobLabel(const model::StudyFile& study, const Job& job);

// "[3/12] thm1 / fwn_firm_seed1 x1.5 ... 0.412 s" or "... failed: <message>": the progress line
// of a finished job, `done` of `total`.
std::string JobProgressLine(const model::StudyFile& study, const Job& job, const JobResult& result,
                            std::size_t done, std::size_t total);

// "runs/<variant>/<record>_x<scale>.h5": where the run's results go, relative to the output
// folder (summaries name it so, and stay valid when the folder moves).
std::string RunFileName(const model::StudyFile& study, const Job& job);

}  // namespace isolab::study
