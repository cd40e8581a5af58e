// Subcommand registry of the voronav CLI. Each cmd_*.cpp defines a static Command that adds its
// CLI11 subcommand; main() builds the app from the registry. Keeps every subcommand in its own
// file and main.cpp free of feature code.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace voronav::cli {

struct CommandSpec {
  std::string name;
  /// Adds the subcommand to `app` and sets its callback.
  std::function<void(CLI::App& app)> setup;
  int order = 100;  ///< position in --help
};

std::vector<CommandSpec>& command_registry();

/// Registers a subcommand at static-initialisation time: `static Command reg{{"plan", setup, 10}};`
struct Command {
  explicit Command(CommandSpec spec) { command_registry().push_back(std::move(spec)); }
};

/// Exit code set by a subcommand callback (0 unless it reports failure).
int& exit_code();

}  // namespace voronav::cli
