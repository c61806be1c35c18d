// Each record file of a study read once, before its jobs run, and handed to every job that runs
// under it: a job used to parse its record's file again, 4 % of a five-story study's
// instructions. A file that cannot be read keeps its error, and each job under it fails with that
// message, as reading it in the job did; a job whose variant would read it differently (another
// time unit, so another step in seconds) reads it itself.
#pragma once

#include <exception>
#include <optional>
#include <vector>

#include "isolab/io/record.h"
#include "isolab/model/study_file.h"

namespace isolab::study {

class StudyRecords {
 public:
  // Reads every component of every record of `study` as a job under its building would.
  explicit StudyRecords(const model::StudyFile& study);

  // Component `component` of record `record`, read with the step `dt_seconds` (0: from the
  // file): the record, null when it was read with another step, or throws the read's error.
  const io::Record* Find(std::size_t record, std::size_t component, double dt_seconds) const;

 private:
  struct Read {
    double dt_seconds = 0.0;
    std::optional<io::Record> record;
    std::exception_ptr error;
  };
  std::vector<std::vector<Read>> reads_;  // per record, per component
};

}  // namespace isolab::study
