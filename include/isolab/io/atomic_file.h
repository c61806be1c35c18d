// Result files appear whole or not at all: written under a temporary name beside the target and
// renamed over it only after the writer finished, so an interrupted or failed run never leaves
// a partial file under the final name.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace isolab::io {

// Calls `write` on a stream to "<path>.tmp", then renames it to `path`. Throws InputError when
// the file cannot be created or written; the temporary file is removed on any failure.
void WriteTextFileAtomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write);

}  // namespace isolab::io
