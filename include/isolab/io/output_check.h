// Every command checks all of its outputs against all of its inputs before it does any work, so
// that a long analysis is never wasted on an output it cannot write, and no output ever replaces
// a file the command reads (`run m.yaml -o ./m.yaml`, a hard link to the record, `fit -o
// data.csv`, ...). Files are compared by identity (device and inode), not by spelling.
#pragma once

#include <string>
#include <vector>

namespace isolab::io {

// Throws InputError({input}, ...) for an input that exists and is not a regular file (after
// symbolic links): /dev/zero or a pipe would be read without end. Inputs that do not exist are
// left to their readers, which say so.
void CheckInputFiles(const std::vector<std::string>& inputs);

// CheckInputFiles, then throws InputError({output}, ...) naming the input when an output is the
// same file as an input, or the same file as another output; and for any output CheckOutputPath
// refuses (a missing folder, a device, a folder, a link).
void CheckOutputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

}  // namespace isolab::io
