// voronav explore: swarm exploration of an unknown world (seed 004: reactive 4-sector search,
// feature points, Voronoi tree dispatch) or a frontier baseline (nearest frontier / Burgard
// coordinated). Thin over voronav::exploration::run_exploration; JSON out, optional pictures
// and the recording in --out DIR.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"
#include "command.hpp"
#include "recordings.hpp"
#include "voronav/bag/run_bag.hpp"
#include "voronav/core/error.hpp"
#include "voronav/exploration/explorer.hpp"
#include "voronav/render/figure.hpp"
#include "voronav/report/replay_html.hpp"

namespace voronav::cli {
namespace {

/// The library's defaults: every default that `explore` shows in --help or uses is taken from a
/// default-constructed ExplorationOptions, so that a default changed in the library cannot
/// disagree with the CLI.
const exploration::ExplorationOptions& library_defaults() {
  static const exploration::ExplorationOptions d{};
  return d;
}

/// A default of the library as help text shows it: "60", "0.5" (no trailing zeros).
std::string shown(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

/// An on|off switch's value as the CLI spells it.
std::string on_off(bool on) {
  return on ? "on" : "off";
}

struct ExploreArgs {
  std::string world;
  int robots = library_defaults().robots;
  std::string method{to_string(library_defaults().method)};
  double time = library_defaults().time_limit;
  double tree_start = library_defaults().tree_start_time;
  double min_leaf_gain = library_defaults().min_leaf_gain;
  double stall_reach_radius = library_defaults().stall_reach_radius;
  std::string tree_replan{to_string(library_defaults().tree_replan)};
  std::string tree_leg_replan{to_string(library_defaults().tree_leg_replan)};
  std::string avoid_escape{robot::to_string(library_defaults().controller.avoid_escape)};
  double random_turn_rate = library_defaults().controller.random_turn_rate;
  std::string unstick = on_off(library_defaults().unstick);
  std::string frontier_unstick = on_off(library_defaults().frontier_unstick);
  std::string idle_unstick = on_off(library_defaults().idle_unstick);
  std::string disperse_neighbours = on_off(library_defaults().disperse_neighbours);
  std::string clear_way_out = on_off(library_defaults().clear_way_out);
  std::string unstick_retry = on_off(library_defaults().unstick_retry);
  std::string unstick_right_of_way = on_off(library_defaults().unstick_right_of_way);
  std::string yield_to_held = on_off(library_defaults().yield_to_held);
  std::string retry_banned = on_off(library_defaults().retry_banned);
  std::string share_bans = on_off(library_defaults().share_bans);
  int crowd_limit = library_defaults().crowd_limit;
  std::string drop_goalless_routes = on_off(library_defaults().drop_goalless_routes);
  std::string margin_escape = on_off(library_defaults().margin_escape);
  std::string skip_known_leaves = on_off(library_defaults().skip_known_leaves);
  std::string unknown_leaves_first = on_off(library_defaults().unknown_leaves_first);
  std::string nearest_leaf_next = on_off(library_defaults().nearest_leaf_next);
  std::string frontiers_after_leaves = on_off(library_defaults().frontiers_after_leaves);
  std::string gain_through_free = on_off(library_defaults().gain_through_free);
  std::string guard{to_string(library_defaults().guard)};
  std::uint64_t seed = library_defaults().seed;
  std::string start;
  std::filesystem::path out;
  double stop_at = library_defaults().stop_at_coverage;
  int picture_px = 900;  // CLI only (the pictures)
  bool json = false;
  std::filesystem::path mcap;
  double known_map_period_s = 5.0;  // CLI only (the bag)
};

render::Color robot_color(std::size_t i) {
  const render::Color c[] = {render::colors::kRed,    render::colors::kBlue,
                             render::colors::kGreen,  render::colors::kOrange,
                             render::colors::kPurple, render::colors::kCyan};
  return c[i % 6];
}

void draw_trajectories(render::Figure& fig, const exploration::ExplorationResult& r) {
  const auto& frames = r.recording.frames;
  if (frames.empty()) return;
  for (std::size_t i = 0; i < frames.front().poses.size(); ++i) {
    std::vector<Vec2> pts;
    for (const auto& f : frames)
      pts.push_back(f.poses[i].position);
    fig.polyline(pts, robot_color(i).with_alpha(0.7), 1.2);
    fig.circle(r.recording.starts[i], 0.12, robot_color(i));
    fig.point(pts.back(), robot_color(i), 4.0);
  }
}

// `world`: the resampled ground truth (same geometry as the recording).
void save_pictures(const OccupancyGrid& world, const exploration::ExplorationResult& r,
                   const std::filesystem::path& dir, int side_px) {
  {
    render::Figure fig(world.geometry(), {.auto_side_px = side_px,
                                          .title = "explore: team map and trajectories (" +
                                                   std::string(to_string(r.method)) + ")"});
    fig.occupancy(r.recording.team_map);
    draw_trajectories(fig, r);
    fig.save(dir / "explore.png");
  }
  if (r.recording.tree.empty()) return;
  render::Figure fig(world.geometry(),
                     {.auto_side_px = side_px, .title = "feature points, Voronoi tree and routes"});
  fig.occupancy(world);
  for (const auto& p : r.recording.feature_points)
    fig.point(p.position, render::colors::kRed, 2.5);
  const auto& tree = r.recording.tree;
  for (const auto& n : tree.nodes)
    if (n.parent >= 0) fig.polyline(n.path, render::colors::kGrey, 1.5);
  for (std::size_t i = 0; i < r.recording.routes.size(); ++i)
    fig.polyline(r.recording.routes[i], robot_color(i).with_alpha(0.6), 2.5);
  for (const auto& n : tree.nodes)
    fig.point(n.position, render::colors::kBlack, 2.0);
  for (int leaf : tree.leaves_by_distance())
    fig.circle(tree.nodes[static_cast<std::size_t>(leaf)].position, 0.25,
               render::colors::kTransparent, render::colors::kCyan, 2.0);
  if (!tree.empty())
    fig.circle(tree.nodes[static_cast<std::size_t>(tree.root)].position, 0.3,
               render::colors::kTransparent, render::colors::kRed, 2.5);
  fig.legend({{"feature point", render::colors::kRed},
              {"tree edge", render::colors::kGrey},
              {"root", render::colors::kRed},
              {"leaf (goal)", render::colors::kCyan}});
  fig.save(dir / "tree.png");
}

/// The fields every command's JSON has (docs/ros.md): frame, units, the inputs echoed (the
/// library's echo of the options the run used, and the map), each robot's start and final pose
/// {x, y, yaw} in `map`.
nlohmann::json with_frames(nlohmann::json j, const ExploreArgs& a,
                           const exploration::ExplorationOptions& o,
                           const exploration::ExplorationResult& r) {
  j["frame_id"] = "map";
  j["units"] = {{"time", "s"}, {"length", "m"}, {"coverage", "fraction"}, {"yaw", "rad"}};
  j["input"] = nlohmann::json::parse(exploration::to_json(o));
  j["input"]["map"] = a.world;
  nlohmann::json poses = nlohmann::json::array();
  const auto& rec = r.recording;
  for (std::size_t i = 0; i < rec.starts.size(); ++i) {
    nlohmann::json p = {{"id", i}, {"start", pose_json({rec.starts[i], 0.0})}};
    if (!rec.frames.empty() && i < rec.frames.back().poses.size())
      p["final"] = pose_json(rec.frames.back().poses[i]);
    poses.push_back(p);
  }
  j["robot_poses"] = poses;
  return j;
}

void run(const ExploreArgs& a) {
  OccupancyGrid world;
  if (a.world == "paper") {
    world = exploration::paper_world(0.05);
  } else {
    world = load_map_context(a.world, false).map.grid;
  }
  exploration::ExplorationOptions o;
  o.method = exploration::parse_exploration_method(a.method);
  o.robots = a.robots;
  o.time_limit = a.time;
  o.tree_start_time = a.tree_start;
  o.min_leaf_gain = a.min_leaf_gain;
  o.stall_reach_radius = a.stall_reach_radius;
  o.tree_replan = exploration::parse_tree_replan(a.tree_replan);
  o.tree_leg_replan = exploration::parse_tree_leg_replan(a.tree_leg_replan);
  o.controller.avoid_escape = robot::parse_avoid_escape(a.avoid_escape);
  o.controller.random_turn_rate = a.random_turn_rate;
  o.unstick = a.unstick == "on";
  o.frontier_unstick = a.frontier_unstick == "on";
  o.disperse_neighbours = a.disperse_neighbours == "on";
  o.clear_way_out = a.clear_way_out == "on";
  o.unstick_retry = a.unstick_retry == "on";
  o.unstick_right_of_way = a.unstick_right_of_way == "on";
  o.idle_unstick = a.idle_unstick == "on";
  o.yield_to_held = a.yield_to_held == "on";
  o.retry_banned = a.retry_banned == "on";
  o.share_bans = a.share_bans == "on";
  o.crowd_limit = a.crowd_limit;
  o.drop_goalless_routes = a.drop_goalless_routes == "on";
  o.margin_escape = a.margin_escape == "on";
  o.skip_known_leaves = a.skip_known_leaves == "on";
  o.unknown_leaves_first = a.unknown_leaves_first == "on";
  o.nearest_leaf_next = a.nearest_leaf_next == "on";
  o.frontiers_after_leaves = a.frontiers_after_leaves == "on";
  o.gain_through_free = a.gain_through_free == "on";
  o.guard = exploration::parse_front_guard(a.guard);
  o.seed = a.seed;
  o.stop_at_coverage = a.stop_at;
  if (!a.start.empty())
    o.start = parse_point(a.start, "--start");
  else if (a.world == "paper")
    o.start = exploration::kPaperWorldStart;
  o.on_frame = [limit = a.time](double t, double coverage) {
    char what[96];
    std::snprintf(what, sizeof what, "of %.0f s simulated, coverage %.1f %%", limit,
                  100.0 * coverage);
    set_progress(t / limit, what);
  };
  const exploration::ExplorationResult r = exploration::run_exploration(world, o);

  if (!a.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(a.out, ec);
    if (ec) throw Error(a.out.string(), 0, "cannot create the output folder: " + ec.message());
    std::ofstream f(a.out / "exploration.json");
    if (!f) throw Error((a.out / "exploration.json").string(), 0, "cannot write");
    f << with_frames(nlohmann::json::parse(exploration::to_json(r, true)), a, o, r).dump() << "\n";
    save_pictures(exploration::resample_world(world, o.min_cell_size), r, a.out, a.picture_px);
    report::write_replay_html(exploration_recording(r), (a.out / "index.html").string());
  }
  if (!a.mcap.empty()) {
    // /map: the ground truth explored (it does not change); /known_map: the team's merged map
    // as it grows, every --known-map-period seconds from the cells' first-seen times.
    report::Recording rec = exploration_recording(r);
    rec.map = exploration::resample_world(world, o.min_cell_size);
    rec.obstacle_changes.clear();  // the page's reveal of the team map, not changes of /map
    bag::BagExtras extras;
    if (r.recording.reveal_time.size() == r.recording.team_map.size())
      extras.known_maps = bag::known_map_series(r.recording.team_map, r.recording.reveal_time,
                                                r.sim_time_s, a.known_map_period_s);
    else
      extras.known_maps.emplace_back(r.sim_time_s, r.recording.team_map);
    bag::write_run_bag(rec, a.mcap, extras);
  }
  if (a.json) {
    print_json(with_frames(nlohmann::json::parse(exploration::to_json(r, false)), a, o, r));
  } else {
    const auto opt = [](const std::optional<double>& v) {
      return v ? std::to_string(*v) + " s" : std::string("not reached");
    };
    std::cout << "method:         " << to_string(r.method) << " (" << r.robots << " robots)\n"
              << "coverage:       " << r.coverage * 100.0 << " %\n"
              << "t90:            " << opt(r.t90_s) << "\n"
              << "t99:            " << opt(r.t99_s) << "\n"
              << "distance:       " << r.distance_m << " m\n"
              << "collisions:     " << r.collisions << "\n"
              << "overlap:        " << r.overlap << "\n"
              << "feature points: " << r.feature_points << "\n"
              << "leaves:         " << r.leaves << " (" << r.leaves_reached << " reached)\n"
              << "stalled robots: " << r.stalled_robots << " (" << r.stalled_without_target
              << " with no target any robot could reach)\n"
              << "idle when done: " << r.idle_when_explored << "\n";
  }
}

/// An on|off switch of `explore`, its default shown in --help.
void add_on_off(CLI::App* cmd, const std::string& name, std::string& value,
                const std::string& help) {
  cmd->add_option(name, value, help)->check(CLI::IsMember({"on", "off"}))->capture_default_str();
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "explore",
      "Explore an unknown world with a team of robots: reactive search, then a Voronoi tree of "
      "the places worth visiting shared out among the robots (Lee & Joo, 'Distributed search of "
      "swarm robots in unknown environments with a tree structure', 2018), or frontier "
      "baselines");
  auto args = std::make_shared<ExploreArgs>();
  cmd->add_option("--map,--world", args->world,
                  "The world to explore (the robots do not know it): ROS map .yaml, Moving AI "
                  ".map, floor plan .png/.pgm, or 'paper' (the paper's 20 m x 20 m test world); "
                  "--world is the older name")
      ->required();
  cmd->add_option("--robots", args->robots, "Number of robots (1..64)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_option("--method", args->method, "tree | frontier | coordinated | tree-frontier")
      ->capture_default_str();
  cmd->add_option("--tree-replan", args->tree_replan,
                  "tree: after its leaves a robot searches reactively (none, the paper) or gets a "
                  "new tree rooted where it is (robots)")
      ->capture_default_str();
  cmd->add_option("--tree-leg-replan", args->tree_leg_replan,
                  "tree: a robot blocked on a tree leg skips a waypoint (none) or re-plans the "
                  "leg around the robots near it (robots)")
      ->capture_default_str();
  cmd->add_option("--avoid-escape", args->avoid_escape,
                  "tree: reactive rule 2 when no heading clears the front: turn on for ever (spin, "
                  "the rule as written) or drive out along the longest body-wide corridor "
                  "(corridor); the frontier methods keep spin")
      ->capture_default_str();
  cmd->add_option(
         "--random-turn-rate", args->random_turn_rate,
         "tree: largest turn rate [rad/s] of the reactive search's driving, redrawn every 4 s "
         "(0 = straight ahead while the front is clear, Table 1's CLEAR -> F; the frontier "
         "methods' reactive windows keep 0.4)")
      ->check(finite_range(0.0, 10.0))
      ->capture_default_str();
  add_on_off(cmd, "--unstick", args->unstick,
             "tree: a robot on one spot for 20 s drives to open space nearby around the "
             "other robots (on, ours) or not (off)");
  add_on_off(cmd, "--frontier-unstick", args->frontier_unstick,
             "frontier, coordinated, tree-frontier: the same (off by default: on willow it "
             "stalled more robots)");
  add_on_off(cmd, "--idle-unstick", args->idle_unstick,
             "frontier, coordinated, tree-frontier: a robot without a goal on one spot for "
             "20 s drives to open space even with --frontier-unstick off (on, ours) or not");
  add_on_off(cmd, "--disperse-neighbours", args->disperse_neighbours,
             "tree: when the watchdog finds a robot on one spot, the robots without a route "
             "within " +
                 shown(library_defaults().disperse_range) +
                 " m of it drive to open space first (ours)");
  add_on_off(cmd, "--clear-way-out", args->clear_way_out,
             "tree: when the watchdog finds a robot on one spot, the robots whose discs touch "
             "its way out to open space (planned without the robots) drive to open space first "
             "(on, ours) or stay (off)");
  add_on_off(cmd, "--unstick-retry", args->unstick_retry,
             "tree: a robot the watchdog found on one spot plans its unstick route again every " +
                 shown(library_defaults().unstick_retry_period) +
                 " s that it has none, until it has left the spot or the next watchdog (on, "
                 "ours) or waits for the next watchdog (off)");
  add_on_off(cmd, "--unstick-right-of-way", args->unstick_right_of_way,
             "tree: a robot on an unstick route goes first, the robot the guard stops for it "
             "backs off whatever the indices (on, ours) or the lower index goes first (off)");
  add_on_off(cmd, "--yield-to-held", args->yield_to_held,
             "every method: a robot stopped by a robot in front that is held up itself "
             "backs off whatever their indices (on, ours) or only from a lower index (off)");
  add_on_off(cmd, "--retry-banned", args->retry_banned,
             "frontier, coordinated, tree-frontier: a robot left without a goal may take "
             "again the goals it gave up when blocked, once per 60 s (on, ours) or never");
  add_on_off(cmd, "--share-bans", args->share_bans,
             "frontier, coordinated, tree-frontier: a goal a robot reached while its "
             "frontier stayed (unobservable from there) is banned for every robot (on, ours) "
             "or only for that robot (off)");
  cmd->add_option("--crowd-limit", args->crowd_limit,
                  "frontier: a frontier that this many other robots are at already (within 2 m "
                  "of its target or heading to it) is not a robot's nearest-frontier choice unless "
                  "it is within 2 m itself (ours); 0 = off (Yamauchi)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  add_on_off(cmd, "--drop-goalless-routes", args->drop_goalless_routes,
             "frontier, coordinated, tree-frontier: a robot left without a goal stops "
             "following the route to its old goal (on, ours) or drives it on (off)");
  add_on_off(cmd, "--margin-escape", args->margin_escape,
             "every method: a robot on one spot for 20 s that stands nearer than body + "
             "clearance to a known wall first drives straight out of that margin (on, ours) "
             "or is given routes from where it stands (off)");
  add_on_off(cmd, "--skip-known-leaves", args->skip_known_leaves,
             "tree: a robot skips its dispatched leaves whose surroundings the team map already "
             "knows (less than --min-leaf-gain unknown) and drives on to its next leaf (on, ours) "
             "or visits every leaf in figure 9's order (off, the paper)");
  add_on_off(cmd, "--unknown-leaves-first", args->unknown_leaves_first,
             "tree: a robot drives first to the next of its dispatched leaves that still faces "
             "unknown space (--min-leaf-gain) and visits the others after; none is dropped for "
             "being known, one out of reach from where it stands is given up (on, ours), or "
             "visits them in figure 9's order (off, the paper)");
  add_on_off(cmd, "--nearest-leaf-next", args->nearest_leaf_next,
             "tree: after figure 9's first round (one leaf per robot) a robot takes the leaf "
             "nearest its last one along the tree from one shared pool (on, ours) or drives "
             "its dealt list i, i + N, ... (off)");
  add_on_off(cmd, "--frontiers-after-leaves", args->frontiers_after_leaves,
             "tree: a robot done with its leaves takes coordinated frontier goals (on, ours, "
             "beyond the paper) or searches reactively (off, the paper)");
  add_on_off(cmd, "--gain-through-free", args->gain_through_free,
             "tree-frontier, --tree-replan robots, --skip-known-leaves, --unknown-leaves-first: "
             "a target's information gain counts only the unknown cells within 3 m that connect "
             "to it through cells not known occupied (on, ours) or every unknown cell within 3 m "
             "(off)");
  cmd->add_option("--guard", args->guard,
                  "every method: the front guard of a robot on its route stops for anything "
                  "within 0.24 m in a +-40 deg fan (cone) or for a robot there and for a wall only "
                  "when the body swept along the next 0.12 m of its route would touch it, and "
                  "routes' corners are not cut where the body would touch a wall (corridor, ours)")
      ->check(CLI::IsMember({"cone", "corridor"}))
      ->capture_default_str();
  cmd->add_option("--time", args->time, "Simulated time limit [s]")
      ->check(finite_range(1e-3, 1e6))
      ->capture_default_str();
  cmd->add_option("--tree-start", args->tree_start,
                  "tree: reactive search before the first Voronoi tree [s]")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--min-leaf-gain", args->min_leaf_gain,
                  "tree-frontier, --tree-replan robots: a leaf is a goal only when at least this "
                  "fraction of the cells within 3 m of it is unknown (1 = leaves never qualify); "
                  "--skip-known-leaves skips and --unknown-leaves-first passes over a dealt leaf "
                  "below it")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--stall-reach-radius", args->stall_reach_radius,
                  "Stall rule: a robot idle for " + shown(library_defaults().stall_time) +
                      " s is stalled while unknown space remains where a robot centre fits at "
                      "this clearance [m] (0 = body radius + clearance)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed (start spot, random driving)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--start", args->start,
                  "Team start X,Y [m, map frame] (default: a seeded free spot; (2,2) for paper)");
  cmd->add_option("--stop-at", args->stop_at,
                  "Stop when the coverage reaches this fraction (default: run the full time)")
      ->check(finite_range(0.0, 1.0));
  cmd->add_option("--out", args->out,
                  "Folder for exploration.json (with the recording), explore.png and tree.png")
      ->check(output_dir());
  cmd->add_option("--mcap", args->mcap,
                  "Write a ROS 2 bag (MCAP): /map, /known_map, /tf, /robots, /voronoi, "
                  "/robot_N/plan (docs/ros.md)");
  cmd->add_option("--known-map-period", args->known_map_period_s,
                  "With --mcap: publish /known_map every this many seconds of simulated time [s] "
                  "(at most 200 maps per bag)")
      ->check(finite_range(1e-3, 1e6))
      ->capture_default_str();
  cmd->add_option("--picture-px", args->picture_px, "Larger side of the pictures [px]")
      ->check(CLI::Range(100, 4000))
      ->capture_default_str();
  add_quiet_flag(cmd);
  cmd->add_flag("--json", args->json,
                "JSON output: coverage, t90_s, t99_s (null if not reached), distance_m, "
                "collisions, overlap, feature_points, leaves, ...");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"explore", setup, 40}};

}  // namespace
}  // namespace voronav::cli
