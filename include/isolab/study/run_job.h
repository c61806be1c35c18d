// One run of a study: prepare the variant's model under the job's record and scale, integrate
// it, write its HDF5 results as the study's output.runs asks (also those of a run that stopped
// early, flagged as the run command does) and measure the compared quantities. Nothing escapes: a
// record that cannot be read, a run that does not converge or a file that cannot be written becomes
// a failed result with the message, so one bad job never stops the others.
#pragma once

#include <string>

#include "isolab/model/study_file.h"
#include "isolab/study/job_result.h"
#include "isolab/study/jobs.h"
#include "isolab/study/scheduler.h"
#include "isolab/study/study_records.h"

namespace isolab::study {

// `version` is written into the results file, once the run is over (the run itself makes no
// HDF5 call). `records`: the study's records read once (null: the job reads its own).
JobResult RunJob(const model::StudyFile& study, const Job& job, const std::string& output_directory,
                 const std::string& version, const StudyRecords* records = nullptr);

// Every job of `study` on `scheduler`, the study's records read once before. A file that could
// not be written fails its job (its message says why).
ScheduleOutcome RunStudy(const model::StudyFile& study, const std::vector<Job>& jobs,
                         const std::string& output_directory, const std::string& version,
                         Scheduler& scheduler, const ProgressFunction& progress);

}  // namespace isolab::study
