// Where a study writes its runs and summary (`isolab compare -o`, the Python module's output),
// and what it may replace there: only the files an earlier compare wrote, which its manifest
// (kCompareManifest, written last) lists.
#pragma once

#include <string>

#include "isolab/model/study_file.h"

namespace isolab::study {

inline constexpr const char* kCompareManifest = "compare_manifest.txt";

// `requested` when given, else the study's output.directory, else the study file's stem; made
// with its parents when missing. Throws InputError naming the folder when it cannot be made, when
// it is a file, when it holds a file the study would write that its manifest does not list
// (someone else's), or a file where the study writes a folder. Every MPI process calls it
// (workers write their runs there too), so each refuses alike, before any run.
std::string PrepareOutputFolder(const std::string& requested, const std::string& study_path,
                                const model::StudyFile& study);

// Lists in the folder's manifest the files the compare writes there (the summary and the runs'
// files, written before the runs so that a compare cut short may be run again) and the plots
// drawn so far, which a later compare of the folder may then replace.
void WriteCompareManifest(const std::string& folder, const model::StudyFile& study);

}  // namespace isolab::study
