// isolab: time-history analysis of base-isolated structures. Exit codes: 0 success, 1 a failure
// of the run or inside isolab, 2 bad input (file, option, parameter), 3 a resource exhausted (a
// full disk, memory, a work limit), with a message saying where and why.
//
// Three executables from this file. `isolab`, the front, runs the commands that need no more
// than the solver and its files (run, spectrum, bounds): it starts without MPI, pagmo and their
// dependencies, and builds from the solver's libraries alone, so that the README's first run
// waits for no more. The others replace the front (execv: same process, arguments and
// environment, so mpirun's ranks stay ranks) for their commands (heavy_commands.h):
// `isolab-search` (ISOLAB_SEARCH_COMMANDS) runs `fit` and `diagnose`, which need pagmo (and MPI,
// for a fit on mpirun's ranks), and `cyclic` and `shaketable`, which share their libraries;
// `isolab-studies` (ISOLAB_STUDY_COMMANDS) runs `compare`, `design` and `synth`, which need the
// study and design libraries, and MPI but not pagmo, whose libraries take about 20 ms to load
// (static data copied in at start-up): a study's start-up is time its worker processes wait
// (libexec/isolab/ beside bin/, or in the build tree).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string_view>
#include <utility>

#include "command_table.h"
#include "finite_options.h"
#include "isolab/core/errors.h"
#ifdef ISOLAB_STUDY_COMMANDS
#include "compare_command.h"
#include "design_command.h"
#include "synth_command.h"
#endif
#ifdef ISOLAB_SEARCH_COMMANDS
#include "cyclic_command.h"
#include "diagnose_command.h"
#include "fit_command.h"
#include "shaketable_command.h"
#endif
#if !defined(ISOLAB_STUDY_COMMANDS) && !defined(ISOLAB_SEARCH_COMMANDS)
#define ISOLAB_FRONT
#include "beside_executable.h"
#include "bounds_command.h"
#include "heap_thresholds.h"
#include "heavy_commands.h"
#include "run_command.h"
#include "spectrum_command.h"
#endif

namespace {

#ifdef ISOLAB_FRONT
// Runs the command's executable in place of this process when argv names a heavy command;
// returns only when it does not, or when the executable cannot be started (exit code 1 then).
void HandOverHeavyCommand(int argc, char** argv) {
  if (argc < 2) return;
  for (const isolab::cli::HeavyCommand& command : isolab::cli::kHeavyCommands) {
    if (argv[1] != command.name) continue;
    const std::string relative = "libexec/isolab/" + std::string(command.executable);
    const std::string path = isolab::cli::BesideExecutable(relative, relative);
    // Its plot scripts are found from the front's folder, not from libexec (beside_executable.h).
    setenv(isolab::cli::kFrontDirectoryVariable, isolab::cli::ExecutableDirectory().c_str(), 1);
    execv(path.c_str(), argv);
    const int error = errno;
    const std::string front = isolab::cli::ExecutableDirectory();
    if (error == ENOENT && access((front + "/CMakeCache.txt").c_str(), F_OK) == 0) {
      // A build tree where scripts/setup.sh built the front alone: say how to build the rest.
      std::string target(command.executable);
      std::replace(target.begin(), target.end(), '-', '_');
      std::cerr << "isolab: '" << command.name << "' is not built yet (" << front << "/" << relative
                << "): build it with `cmake --build " << front << " --target " << target
                << "`, or every command with `scripts/setup.sh --all`\n";
      std::exit(1);
    }
    std::cerr << "isolab: internal error: cannot start " << path << " for '" << command.name
              << "' (" << std::strerror(error) << "); reinstall isolab\n";
    std::exit(1);
  }
}
#endif

}  // namespace

int main(int argc, char** argv) {
#ifdef ISOLAB_FRONT
  HandOverHeavyCommand(argc, argv);
  isolab::cli::KeepLargeBuffersInTheHeap();
#endif
  CLI::App app{"isolab: time-history solver for base-isolated structures"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("isolab ") + ISOLAB_VERSION);

  namespace cli = isolab::cli;
  cli::CommandTable commands;
#ifdef ISOLAB_FRONT
  commands.Add(app, cli::RegisterRunCommand, cli::RunRunCommand);
  // Listed by --help; never parsed here (HandOverHeavyCommand took them).
  for (const cli::HeavyCommand& command : cli::kHeavyCommands) {
    app.add_subcommand(std::string(command.name), std::string(command.help))->allow_extras();
  }
  commands.Add(app, cli::RegisterSpectrumCommand, cli::RunSpectrumCommand);
  commands.Add(app, cli::RegisterBoundsCommand, cli::RunBoundsCommand);
#endif
#ifdef ISOLAB_SEARCH_COMMANDS
  commands.Add(app, cli::RegisterCyclicCommand, cli::RunCyclicCommand);
  commands.Add(app, cli::RegisterFitCommand, cli::RunFitCommand);
  commands.Add(app, cli::RegisterDiagnoseCommand, cli::RunDiagnoseCommand);
  commands.Add(app, cli::RegisterShakeTableCommand, cli::RunShakeTableCommand);
#endif
#ifdef ISOLAB_STUDY_COMMANDS
  commands.Add(app, cli::RegisterSynthCommand, cli::RunSynthCommand);
  commands.Add(app, cli::RegisterCompareCommand, cli::RunCompareCommand);
  commands.Add(app, cli::RegisterDesignCommand, cli::RunDesignCommand);
#endif
  isolab::cli::RequireFiniteNumbers(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }

  try {
    return commands.RunParsed(std::cout);
  } catch (const isolab::InputError& error) {
    std::cerr << "isolab: " << error.what() << "\n";
    return 2;
  } catch (const isolab::ResourceError& error) {
    std::cerr << "isolab: " << error.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "isolab: out of memory (the model, the record or the output selection is too "
                 "large for this computer's memory)\n";
    return 3;
  } catch (const std::exception& error) {
    std::cerr << "isolab: internal error: " << error.what() << "\n";
    return 1;
  }
}
