// Runs a plot script of scripts/ for a command's --plot: `isolab run` (plot_result.py),
// `isolab spectrum` (plot_spectrum.py), and any other command that writes a file a script reads.
//
// The scripts are found relative to the isolab executable, never through the source tree, so an
// installed isolab works without it: <bin>/../share/isolab/scripts (cmake --install), else
// <bin>/scripts (the build tree, where CMake copies them). They run under $ISOLAB_PYTHON, a
// path or a name looked up on PATH (python3.11), or else /usr/bin/python3: Debian's interpreter,
// which has the python3-matplotlib and python3-h5py packages scripts/setup.sh installs; a
// python3 earlier on PATH (pyenv's, a virtualenv's) may lack them.
#pragma once

#include <string>
#include <vector>

namespace isolab::cli {

// The script's path beside the executable (the first candidate that exists; else the first).
std::string PlotScriptPath(const std::string& script_name);

// The directory for a --plot[=DIR]: DIR when given, else the one holding `output_file` ("." for
// a bare file name).
std::string PlotDirectory(const std::string& requested, const std::string& output_file);

// Fails before a long analysis rather than after it: throws InputError({"--plot"}, ...) saying
// what to install when the script is missing, the interpreter cannot be run, or it cannot import
// what the script needs (the script's --check).
void CheckPlotScript(const std::string& script_name);

// Runs `python scripts/<script_name> arguments...`. Its standard output goes to isolab's standard
// error (to nothing with `quiet`), so isolab's own output (--json) stays clean. Throws
// InputError({"--plot"}, ...) with the script's error output when it cannot run or fails.
void RunPlotScript(const std::string& script_name, const std::vector<std::string>& arguments,
                   bool quiet);

}  // namespace isolab::cli
