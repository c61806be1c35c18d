// The commands an executable runs, each listed once: its options registered with CLI11, and the
// function that runs it once parsed. main.cpp adds each command with one line.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <ostream>
#include <type_traits>
#include <vector>

namespace isolab::cli {

class CommandTable {
 public:
  // `add` registers the command's subcommand and options on `app`; `run` runs it (void, or
  // returning the exit code).
  template <typename Options, typename Run>
  void Add(CLI::App& app, void (*add)(CLI::App&, Options&), Run run) {
    auto options = std::make_shared<Options>();
    add(app, *options);
    // Every subcommand in the order added (an empty filter; the plain overload lists only the
    // parsed ones): the last is the one `add` just made.
    CLI::App* command = app.get_subcommands({}).back();
    commands_.push_back({command, [options, run](std::ostream& out) {
                           if constexpr (std::is_void_v<decltype(run(*options, out))>) {
                             run(*options, out);
                             return 0;
                           } else {
                             return run(*options, out);
                           }
                         }});
  }

  // Runs the command the arguments named; its exit code (0 when none was).
  int RunParsed(std::ostream& out) const {
    for (const Command& command : commands_) {
      if (command.app->parsed()) return command.run(out);
    }
    return 0;
  }

 private:
  struct Command {
    CLI::App* app;
    std::function<int(std::ostream&)> run;
  };
  std::vector<Command> commands_;
};

}  // namespace isolab::cli
