// One run of a study: prepare the variant's model under the job's record and scale, integrate
// it, write its HDF5 results (also those of a run that stopped early, flagged as the run command
// does) and measure the compared quantities. Nothing escapes: a record that cannot be read, a
// run that does not converge or a file that cannot be written becomes a failed result with the
// message, so one bad job never stops the others.
#pragma once

#include <string>

#include "isolab/model/study_file.h"
#include "isolab/study/job_result.h"
#include "isolab/study/jobs.h"

namespace isolab::study {

// `version` is written into the results file.
JobResult RunJob(const model::StudyFile& study, const Job& job, const std::string& output_directory,
                 const std::string& version);

}  // namespace isolab::study
