// Where a study writes its runs and summary (`isolab compare -o`, the Python module's output).
#pragma once

#include <string>

#include "isolab/model/study_file.h"

namespace isolab::study {

// `requested` when given, else the study's output.directory, else the study file's stem; made
// with its parents when missing. Throws InputError naming the folder when it cannot be made.
// Every MPI process calls it (workers write their runs there too), so a folder that cannot be
// made is bad input on every rank alike.
std::string PrepareOutputFolder(const std::string& requested, const std::string& study_path,
                                const model::StudyFile& study);

}  // namespace isolab::study
