#include "isolab/study/study_records.h"

#include <string>

#include "run_job_parts.h"

namespace isolab::study {

StudyRecords::StudyRecords(const model::StudyFile& study) {
  for (const model::StudyRecord& entry : study.records) {
    std::vector<Read>& reads = reads_.emplace_back();
    const bool pair = entry.components.size() > 1;
    for (std::size_t c = 0; c < entry.components.size(); ++c) {
      const model::GroundMotionSection& component = entry.components[c];
      Read& read = reads.emplace_back();
      // The step in seconds exactly as a job under the building computes it (ApplyRecord).
      if (component.dt > 0.0) {
        read.dt_seconds =
            InModelTime(study, study.units, component.dt) * study.units.SiFactor(dimension::kTime);
      }
      const std::string given_by = pair ? RecordEntryName(entry, c) : entry.entry;
      try {
        read.record = io::ReadRecord(component.file, {component.units, read.dt_seconds,
                                                      given_by + ".units", given_by + ".dt"});
      } catch (...) {
        read.error = std::current_exception();
      }
    }
  }
}

const io::Record* StudyRecords::Find(std::size_t record, std::size_t component,
                                     double dt_seconds) const {
  const Read& read = reads_.at(record).at(component);
  if (read.dt_seconds != dt_seconds) return nullptr;
  if (read.error) std::rethrow_exception(read.error);
  return &*read.record;
}

}  // namespace isolab::study
