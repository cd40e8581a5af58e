// `voronav robot` and `voronav netsim-world`: one robot of a netsim scenario as its own process
// over Cyclone DDS, and the world process (clock, obstacle changes, who is alive, metrics) that
// steps the robots in lockstep (issue #8, voronav/dds/netsim_dds.hpp). `voronav netsim
// --transport dds` starts them; both can also be started by hand, e.g. on different machines.
#include <iostream>
#include <memory>

#include "command.hpp"
#include "voronav/core/error.hpp"
#include "voronav/dds/netsim_dds.hpp"

namespace voronav::cli {
namespace {

void add_link_options(CLI::App* c, dds::LockstepLink& l) {
  c->add_option("--domain", l.domain_id, "DDS domain id (0..230)")->capture_default_str();
  c->add_option("--partition", l.partition, "DDS partition shared by the run's processes")
      ->capture_default_str();
  c->add_option("--startup-timeout", l.startup_timeout_s, "Discovery of every process [s]")
      ->capture_default_str();
  c->add_option("--step-timeout", l.step_timeout_s,
                "A robot silent this long in one step is declared dead [s]")
      ->capture_default_str();
  c->add_option("--world-timeout", l.world_timeout_s,
                "A robot gives up after this long without a tick [s]")
      ->capture_default_str();
}

void setup_robot(CLI::App& app) {
  auto o = std::make_shared<dds::RobotProcessOptions>();
  auto transport = std::make_shared<std::string>("dds");
  auto die = std::make_shared<long>(-1);
  auto* c = app.add_subcommand(
      "robot",
      "One robot of a netsim scenario as its own process (Cyclone DDS, lockstep with "
      "a world process started by 'voronav netsim-world')");
  c->add_option("--id", o->id, "Robot id (index in the scenario's robots)")->required();
  c->add_option("--scenario", o->scenario_path, "Netsim scenario file (YAML)")->required();
  c->add_option("--transport", *transport, "dds (the only transport between processes)")
      ->capture_default_str();
  c->add_option("--loss", o->loss, "Injected loss probability of receptions")
      ->check(CLI::Range(0.0, 1.0));
  c->add_option("--die-at-step", *die, "Fault injection: SIGKILL itself after this step");
  c->add_option("--trace", o->trace_path,
                "Append one JSON line per step here: pose and messages sent (netsim --mcap/--out)");
  add_link_options(c, o->link);
  c->callback([o, transport, die] {
    if (*transport != "dds")
      throw Error("--transport", 0,
                  "expected 'dds', got '" + *transport +
                      "' (the simulated radio runs every robot in one process: voronav netsim)");
    if (*die >= 0) o->die_at_step = static_cast<std::uint32_t>(*die);
    exit_code() = dds::run_robot_process(*o);
  });
}

void setup_world(CLI::App& app) {
  auto o = std::make_shared<dds::WorldProcessOptions>();
  auto die = std::make_shared<long>(-1);
  auto* c = app.add_subcommand("netsim-world",
                               "The world process of a multi-process netsim run: clock, obstacle "
                               "changes, liveness; prints the run's metrics as JSON");
  c->add_option("--scenario", o->scenario_path, "Netsim scenario file (YAML)")->required();
  c->add_flag("--resume", o->resume, "Take over a run whose world process died");
  c->add_option("--die-at-step", *die, "Fault injection: SIGKILL itself after this tick");
  c->add_option("--trace", o->trace_path,
                "Append one JSON line per event here: robots declared dead, obstacle changes");
  add_link_options(c, o->link);
  c->callback([o, die] {
    if (*die >= 0) o->die_at_step = static_cast<std::uint32_t>(*die);
    exit_code() = dds::run_world_process(*o);
  });
}

const Command reg_robot{{"robot", setup_robot, 61}};
const Command reg_world{{"netsim-world", setup_world, 62}};

}  // namespace
}  // namespace voronav::cli
