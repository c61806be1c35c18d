// isolab: time-history analysis of base-isolated structures. Exit codes: 0 success, 1 a failure
// inside isolab, 2 bad input (file, option, parameter), with a message saying where and why.
#include <CLI/CLI.hpp>
#include <iostream>

#include "compare_command.h"
#include "cyclic_command.h"
#include "diagnose_command.h"
#include "finite_options.h"
#include "fit_command.h"
#include "isolab/core/errors.h"
#include "run_command.h"
#include "shaketable_command.h"
#include "spectrum_command.h"
#include "synth_command.h"

int main(int argc, char** argv) {
  CLI::App app{"isolab: time-history solver for base-isolated structures"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("isolab ") + ISOLAB_VERSION);

  isolab::cli::CyclicOptions cyclic;
  isolab::cli::RegisterCyclicCommand(app, cyclic);
  isolab::cli::RunOptions run;
  isolab::cli::RegisterRunCommand(app, run);
  isolab::cli::SynthOptions synth;
  isolab::cli::RegisterSynthCommand(app, synth);
  isolab::cli::FitOptions fit;
  isolab::cli::RegisterFitCommand(app, fit);
  isolab::cli::DiagnoseOptions diagnose;
  isolab::cli::RegisterDiagnoseCommand(app, diagnose);
  isolab::cli::SpectrumOptions spectrum;
  isolab::cli::RegisterSpectrumCommand(app, spectrum);
  isolab::cli::CompareOptions compare;
  isolab::cli::RegisterCompareCommand(app, compare);
  isolab::cli::ShakeTableOptions shaketable;
  isolab::cli::RegisterShakeTableCommand(app, shaketable);
  isolab::cli::RequireFiniteNumbers(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }

  try {
    if (app.got_subcommand("cyclic")) isolab::cli::RunCyclicCommand(cyclic, std::cout);
    if (app.got_subcommand("run")) return isolab::cli::RunRunCommand(run, std::cout);
    if (app.got_subcommand("synth")) isolab::cli::RunSynthCommand(synth);
    if (app.got_subcommand("fit")) isolab::cli::RunFitCommand(fit, std::cout);
    if (app.got_subcommand("diagnose")) isolab::cli::RunDiagnoseCommand(diagnose, std::cout);
    if (app.got_subcommand("spectrum")) isolab::cli::RunSpectrumCommand(spectrum, std::cout);
    if (app.got_subcommand("compare")) return isolab::cli::RunCompareCommand(compare, std::cout);
    if (app.got_subcommand("shaketable")) {
      isolab::cli::RunShakeTableCommand(shaketable, std::cout);
    }
  } catch (const isolab::InputError& error) {
    std::cerr << "isolab: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "isolab: internal error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
