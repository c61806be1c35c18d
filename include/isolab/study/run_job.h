// One run of a study: prepare the variant's model under the job's record and scale, integrate
// it, hand its HDF5 results to the study's writer as the study's output.runs asks (also those of
// a run that stopped early, flagged as the run command does; run_files.h) and measure the
// compared quantities. Nothing escapes: a record that cannot be read, a
// run that does not converge or a file that cannot be written becomes a failed result with the
// message, so one bad job never stops the others.
#pragma once

#include <string>

#include "isolab/model/study_file.h"
#include "isolab/study/job_result.h"
#include "isolab/study/jobs.h"
#include "isolab/study/run_files.h"
#include "isolab/study/scheduler.h"
#include "isolab/study/study_records.h"

namespace isolab::study {

// `version` is written into the results file. `files`: who writes it (null: this thread, at
// once). `records`: the study's records read once (null: the job reads its own).
JobResult RunJob(const model::StudyFile& study, const Job& job, const std::string& output_directory,
                 const std::string& version, RunFileWriter* files = nullptr,
                 const StudyRecords* records = nullptr);

// Every job of `study` on `scheduler`, the per-run files written by `writer_threads` threads
// (several local threads: as many), or with none by each job after its run (one thread, MPI
// ranks). A file that could not be written fails its job (its message says why). On the
// coordinator, `writing_seconds` is the time spent writing files there.
ScheduleOutcome RunStudy(const model::StudyFile& study, const std::vector<Job>& jobs,
                         const std::string& output_directory, const std::string& version,
                         Scheduler& scheduler, int writer_threads, const ProgressFunction& progress,
                         double* writing_seconds = nullptr);

}  // namespace isolab::study
