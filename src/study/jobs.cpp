#include "isolab/study/jobs.h"

#include <fmt/format.h>

#include <filesystem>

namespace isolab::study {

std::vector<Job> ExpandJobs(std::size_t variants, std::size_t records, std::size_t scales) {
  std::vector<Job> jobs;
  jobs.reserve(variants * records * scales);
  for (std::size_t v = 0; v < variants; ++v) {
    for (std::size_t r = 0; r < records; ++r) {
      for (std::size_t s = 0; s < scales; ++s) jobs.push_back({jobs.size(), v, r, s});
    }
  }
  return jobs;
}

std::vector<Job> ExpandJobs(const model::StudyFile& study) {
  return ExpandJobs(study.variants.size(), study.records.size(), study.scales.size());
}

std::string ScaleName(double scale) { return fmt::format("{}", scale); }

std::string JobLabel(const model::StudyFile& study, const Job& job) {
  return fmt::format("{} / {} x{}", study.variants[job.variant].name,
                     study.records[job.record].name, ScaleName(study.scales[job.scale]));
}

std::string JobProgressLine(const model::StudyFile& study, const Job& job, const JobResult& result,
                            std::size_t done, std::size_t total) {
  const std::string label = JobLabel(study, job);
  if (result.completed)
    return fmt::format("[{}/{}] {} ... {:.3f} s", done, total, label, result.wall_seconds);
  return fmt::format("[{}/{}] {} ... failed: {}", done, total, label, result.message);
}

std::string RunFileName(const model::StudyFile& study, const Job& job) {
  return (std::filesystem::path("runs") / study.variants[job.variant].name /
          fmt::format("{}_x{}.h5", study.records[job.record].name,
                      ScaleName(study.scales[job.scale])))
      .string();
}

}  // namespace isolab::study
