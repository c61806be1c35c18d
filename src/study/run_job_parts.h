// The parts of a study's run (run_job.cpp) that the scheduler's tests reach too: the study's
// times in a variant model's unit, and where a run's results go.
#pragma once

#include <optional>
#include <string>

#include "isolab/model/study_file.h"
#include "isolab/study/job_result.h"
#include "isolab/study/jobs.h"

namespace isolab::study {

// `time` in the study's time unit (its building's), in the unit of `model_units`: a `model`
// variant may use another.
double InModelTime(const model::StudyFile& study, const UnitSystem& model_units, double time);

// What gives component `component` of a record, for messages: "study.yaml:12:5: records[2]",
// with ".h1"/".h2" for a pair's components.
std::string RecordEntryName(const model::StudyRecord& record, std::size_t component);

// The study's free vibration in the model's time unit; empty: the model's own.
std::optional<model::FreeVibration> StudyFreeVibration(const model::StudyFile& study,
                                                       const UnitSystem& model_units);

// <output_directory>/<RunFileName>, its folder made (a folder that cannot be made shows as the
// file's write error).
std::string PrepareRunFile(const model::StudyFile& study, const Job& job,
                           const std::string& output_directory);

}  // namespace isolab::study
