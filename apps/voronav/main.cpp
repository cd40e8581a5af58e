// voronav CLI entry point: builds the subcommands from the registry and maps errors to exit codes
// (0 ok, 1 a result the command reports as failed, 2 bad input or usage).
#include <algorithm>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/core/error.hpp"

namespace voronav::cli {
std::vector<CommandSpec>& command_registry() {
  static std::vector<CommandSpec> registry;
  return registry;
}
int& exit_code() {
  static int code = 0;
  return code;
}
}  // namespace voronav::cli

int main(int argc, char** argv) {
  using namespace voronav::cli;
  // The name is set so the usage line says "voronav", not the path the binary was started by.
  CLI::App app{
      "voronav: grid maps, Voronoi and topological maps, and planning for teams of mobile robots",
      "voronav"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "voronav 0.1.0");
  auto& reg = command_registry();
  std::stable_sort(reg.begin(), reg.end(),
                   [](const CommandSpec& a, const CommandSpec& b) { return a.order < b.order; });
  for (const auto& spec : reg)
    spec.setup(app);
  if (argc > 1) watch_long_run(argv[1], argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    finish_progress();
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const voronav::Error& e) {
    finish_progress();
    std::cerr << "voronav: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    finish_progress();
    std::cerr << "voronav: error: " << e.what() << "\n";
    return 2;
  }
  finish_progress();
  return exit_code();
}
