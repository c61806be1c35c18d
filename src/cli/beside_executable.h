// Files isolab finds relative to its own executable, never through the source tree, so that an
// installed isolab works without it: <bin>/../<installed> after cmake --install, else
// <bin>/<build_tree> in the build tree (where CMake puts them). <bin> is the folder of the
// `isolab` the user ran, also in isolab-commands, which it starts from elsewhere (main.cpp).
#pragma once

#include <string>

namespace isolab::cli {

// Where the front tells isolab-commands its folder.
inline constexpr const char* kFrontDirectoryVariable = "ISOLAB_FRONT_DIRECTORY";

// The folder of the running executable ("." when /proc/self/exe cannot be read).
std::string ExecutableDirectory();

// The first of the two candidates that exists; else the installed one.
std::string BesideExecutable(const std::string& installed, const std::string& build_tree);

}  // namespace isolab::cli
