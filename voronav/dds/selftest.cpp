#include "voronav/dds/selftest.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "voronav/core/error.hpp"
#include "voronav/dds/cyclone_config.hpp"
#include "voronav/dds/dds_transport.hpp"

namespace voronav::dds {
namespace {

using network::RobotId;
using nlohmann::json;

constexpr std::size_t kHeaderBytes = 16;
constexpr std::uint8_t kBroadcastKind = 0;
constexpr std::uint8_t kDirectKind = 1;

double now_s() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

void put_u32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i)
    b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}
std::uint32_t get_u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<std::uint32_t>(b[at + static_cast<std::size_t>(i)]) << (8 * i);
  return v;
}
std::uint8_t filler(std::uint32_t sender, std::uint32_t round, std::size_t i) {
  return static_cast<std::uint8_t>((sender * 31u + round * 7u + i) & 0xffu);
}

// Test payload: "VE", kind, 0, sender (u32 LE), round (u32 LE), size (u32 LE), filler bytes.
std::vector<std::uint8_t> make_payload(std::uint8_t kind, std::uint32_t sender, std::uint32_t round,
                                       std::size_t size) {
  std::vector<std::uint8_t> b(size);
  b[0] = 'V';
  b[1] = 'E';
  b[2] = kind;
  b[3] = 0;
  put_u32(b, 4, sender);
  put_u32(b, 8, round);
  put_u32(b, 12, static_cast<std::uint32_t>(size));
  for (std::size_t i = kHeaderBytes; i < size; ++i)
    b[i] = filler(sender, round, i);
  return b;
}

struct Parsed {
  std::uint8_t kind;
  std::uint32_t sender;
  std::uint32_t round;
};
std::optional<Parsed> parse_payload(const std::vector<std::uint8_t>& b) {
  if (b.size() < kHeaderBytes || b[0] != 'V' || b[1] != 'E' || b[2] > kDirectKind) return {};
  Parsed p{b[2], get_u32(b, 4), get_u32(b, 8)};
  if (get_u32(b, 12) != b.size()) return {};
  for (std::size_t i = kHeaderBytes; i < b.size(); ++i)
    if (b[i] != filler(p.sender, p.round, i)) return {};
  return p;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(
      std::clamp(q * static_cast<double>(v.size() - 1), 0.0, static_cast<double>(v.size() - 1)));
  return v[i];
}

Vec2 position_of(std::uint32_t id, double spacing) {
  return {id * spacing, 0.0};
}
bool in_range(std::uint32_t a, std::uint32_t b, double spacing, double range) {
  return !std::isfinite(range) ||
         distance(position_of(a, spacing), position_of(b, spacing)) <= range;
}
std::uint32_t target_of(std::uint32_t id, std::uint32_t peers) {
  return (id + 1) % peers;
}

void validate(const EchoOptions& o) {
  if (o.peers < 2) throw Error("--peers", 0, "expected at least 2 robots");
  if (o.id >= o.peers) throw Error("--id", 0, "expected 0.." + std::to_string(o.peers - 1));
  if (o.rounds < 1) throw Error("--rounds", 0, "expected >= 1");
  if (!(o.interval_s >= 0.0) || !std::isfinite(o.interval_s))
    throw Error("--interval", 0, "expected a finite number of seconds >= 0");
  if (o.payload_bytes < kHeaderBytes || o.payload_bytes > 60000)
    throw Error("--payload-bytes", 0, "expected 16..60000");
  if (!(o.spacing_m >= 0.0) || !std::isfinite(o.spacing_m))
    throw Error("--spacing", 0, "expected a finite distance >= 0 [m]");
  if (!(o.startup_timeout_s > 0.0) || !(o.quiet_s > 0.0) || !(o.timeout_s > 0.0) ||
      !std::isfinite(o.timeout_s))
    throw Error("--timeout", 0, "expected positive finite timeouts [s]");
}

std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

double parse_double(const std::string& flag, const std::string& v) {
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || end != v.c_str() + v.size() || std::isnan(d))
    throw Error(flag, 0, "expected a number, got '" + v + "'");
  return d;
}
std::uint64_t parse_uint(const std::string& flag, const std::string& v) {
  if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos || v.size() > 19)
    throw Error(flag, 0, "expected a non-negative integer, got '" + v + "'");
  return std::stoull(v);
}

json stats_json(const DdsTransportStats& s) {
  json r = json::object();
  for (std::size_t i = 0; i < kRejectReasonCount; ++i)
    r[std::string(to_string(static_cast<RejectReason>(i)))] = s.rejected_by_reason[i];
  return json{{"sent_unicast", s.sent_unicast},
              {"sent_broadcast", s.sent_broadcast},
              {"delivered", s.delivered},
              {"not_for_me", s.not_for_me},
              {"dropped_range", s.dropped_range},
              {"dropped_unknown_pose", s.dropped_unknown_pose},
              {"dropped_loss", s.dropped_loss},
              {"duplicates", s.duplicates},
              {"gaps", s.gaps},
              {"rejected", s.rejected},
              {"rejected_by_reason", r}};
}

}  // namespace

EchoOptions parse_echo_args(const std::vector<std::string>& args) {
  EchoOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& k = args[i];
    if (i + 1 >= args.size()) throw Error(k, 0, "expected a value");
    const std::string& v = args[++i];
    if (k == "--id")
      o.id = static_cast<std::uint32_t>(std::min<std::uint64_t>(parse_uint(k, v), 0xfffffffe));
    else if (k == "--peers")
      o.peers = static_cast<std::uint32_t>(std::min<std::uint64_t>(parse_uint(k, v), 100000));
    else if (k == "--rounds")
      o.rounds = static_cast<int>(std::min<std::uint64_t>(parse_uint(k, v), 10000000));
    else if (k == "--interval")
      o.interval_s = parse_double(k, v);
    else if (k == "--payload-bytes")
      o.payload_bytes = static_cast<std::size_t>(parse_uint(k, v));
    else if (k == "--spacing")
      o.spacing_m = parse_double(k, v);
    else if (k == "--range")
      o.range_m = parse_double(k, v);
    else if (k == "--loss")
      o.loss = parse_double(k, v);
    else if (k == "--seed")
      o.seed = parse_uint(k, v);
    else if (k == "--domain")
      o.domain_id = static_cast<std::uint32_t>(std::min<std::uint64_t>(parse_uint(k, v), 100000));
    else if (k == "--partition")
      o.partition = v;
    else if (k == "--history-depth")
      o.history_depth = static_cast<int>(std::min<std::uint64_t>(parse_uint(k, v), 1000000));
    else if (k == "--startup-timeout")
      o.startup_timeout_s = parse_double(k, v);
    else if (k == "--quiet")
      o.quiet_s = parse_double(k, v);
    else if (k == "--timeout")
      o.timeout_s = parse_double(k, v);
    else
      throw Error(k, 0, "unknown option");
  }
  return o;
}

std::vector<std::string> echo_args(const EchoOptions& o) {
  return {"--id",
          std::to_string(o.id),
          "--peers",
          std::to_string(o.peers),
          "--rounds",
          std::to_string(o.rounds),
          "--interval",
          num(o.interval_s),
          "--payload-bytes",
          std::to_string(o.payload_bytes),
          "--spacing",
          num(o.spacing_m),
          "--range",
          num(o.range_m),
          "--loss",
          num(o.loss),
          "--seed",
          std::to_string(o.seed),
          "--domain",
          std::to_string(o.domain_id),
          "--partition",
          o.partition,
          "--history-depth",
          std::to_string(o.history_depth),
          "--startup-timeout",
          num(o.startup_timeout_s),
          "--quiet",
          num(o.quiet_s),
          "--timeout",
          num(o.timeout_s)};
}

std::string run_echo(const EchoOptions& o) {
  validate(o);
  const double t0 = now_s();
  const double deadline = t0 + o.timeout_s;
  DdsTransportOptions to;
  to.self = RobotId{o.id};
  to.domain_id = o.domain_id;
  to.config_xml = o.config_xml;
  to.partition = o.partition;
  to.radio_range_m = o.range_m;
  to.loss_probability = o.loss;
  to.loss_seed = o.seed;
  to.history_depth = o.history_depth;
  to.close_timeout_s = 0.5;
  DdsTransport t(to);
  t.update_position(to.self, position_of(o.id, o.spacing_m));
  const bool ready = t.wait_for_peers(
      o.peers - 1, std::min(o.startup_timeout_s, std::max(0.0, deadline - now_s())));
  const double startup_s = now_s() - t0;
  const std::size_t known_at_start = t.known_robots().size();
  const std::size_t matched_at_start = t.matched_receivers();
  std::fprintf(stderr, "voronav-dds-echo %u: %s after %.3f s (%zu poses, %zu receivers)\n", o.id,
               ready ? "ready" : "not all peers found", startup_s, known_at_start,
               matched_at_start);

  // What this robot should get from each in-range peer.
  std::map<std::uint32_t, std::pair<int, int>> expected;  // from -> (broadcasts, directed)
  for (std::uint32_t s = 0; s < o.peers; ++s) {
    if (s == o.id || !in_range(s, o.id, o.spacing_m, o.range_m)) continue;
    expected[s] = {o.rounds, target_of(s, o.peers) == o.id ? o.rounds : 0};
  }
  std::map<std::uint32_t, std::pair<int, int>> received;
  std::set<std::tuple<std::uint32_t, std::uint8_t, std::uint32_t>> seen;
  std::uint64_t duplicates = 0, corrupt = 0, wrong_to = 0;
  std::vector<double> latency_ms;
  double first_rx = 0.0, last_rx = 0.0;
  auto drain = [&] {
    for (const auto& p : t.receive(to.self)) {
      const double now = now_s();
      if (first_rx == 0.0) first_rx = now;
      last_rx = now;
      const auto m = parse_payload(p.bytes);
      if (!m || m->sender != p.from.value) {
        ++corrupt;
        continue;
      }
      const bool directed = m->kind == kDirectKind;
      if (directed != (p.to != network::kBroadcast)) ++wrong_to;
      if (!seen.insert({m->sender, m->kind, m->round}).second) {
        ++duplicates;
        continue;
      }
      latency_ms.push_back((now - p.sent_at_s) * 1000.0);
      auto& r = received[m->sender];
      (directed ? r.second : r.first) += 1;
    }
  };
  auto complete = [&] {
    for (const auto& [s, e] : expected) {
      auto it = received.find(s);
      const std::pair<int, int> got = it == received.end() ? std::pair<int, int>{0, 0} : it->second;
      if (got.first < e.first || got.second < e.second) return false;
    }
    return true;
  };

  int sent_rounds = 0;
  const std::uint32_t target = target_of(o.id, o.peers);
  for (int r = 1; r <= o.rounds && now_s() < deadline; ++r) {
    const auto round = static_cast<std::uint32_t>(r);
    t.broadcast(to.self, make_payload(kBroadcastKind, o.id, round, o.payload_bytes));
    t.send(to.self, RobotId{target}, make_payload(kDirectKind, o.id, round, o.payload_bytes));
    sent_rounds = r;
    std::fprintf(stderr, "voronav-dds-echo %u: round %d sent\n", o.id, r);
    std::fflush(stderr);
    drain();
    if (o.interval_s > 0.0) {
      const double until = now_s() + o.interval_s;
      while (now_s() < until) {
        t.wait_for_data(std::max(0.0, until - now_s()));
        drain();
      }
    }
  }
  // Wait until every matched receiver acknowledged; a dead receiver stays matched until its lease
  // expires, so the wait is bounded by max(1 s, 2 quiet periods).
  const bool flushed =
      t.flush(std::min(std::max(0.0, deadline - now_s()), std::max(1.0, 2.0 * o.quiet_s)));
  const double sent_done = now_s();
  while (now_s() < deadline) {
    drain();
    if (complete()) break;
    const double now = now_s();
    if (now - std::max(last_rx, sent_done) >= o.quiet_s) break;
    t.wait_for_data(0.02);
  }
  // Linger briefly to catch duplicates or strays, then report.
  const double linger_end = std::min(deadline, now_s() + 0.05);
  while (now_s() < linger_end) {
    t.wait_for_data(0.01);
    drain();
  }

  json rec = json::object();
  std::uint64_t total = 0;
  for (const auto& [s, c] : received) {
    rec[std::to_string(s)] = {{"broadcast", c.first}, {"direct", c.second}};
    total += static_cast<std::uint64_t>(c.first + c.second);
  }
  const double window = last_rx - first_rx;
  double mean = 0.0;
  for (double l : latency_ms)
    mean += l;
  if (!latency_ms.empty()) mean /= static_cast<double>(latency_ms.size());
  json out{{"id", o.id},
           {"peers", o.peers},
           {"ready", ready},
           {"startup_s", startup_s},
           {"known_at_start", known_at_start},
           {"matched_at_start", matched_at_start},
           {"sent_rounds", sent_rounds},
           {"flushed", flushed},
           {"received", rec},
           {"received_total", total},
           {"duplicates", duplicates},
           {"corrupt", corrupt},
           {"wrong_destination", wrong_to},
           {"complete", complete()},
           {"latency_ms",
            {{"mean", mean},
             {"p50", percentile(latency_ms, 0.5)},
             {"p99", percentile(latency_ms, 0.99)},
             {"max", percentile(latency_ms, 1.0)}}},
           {"window_s", window},
           {"throughput_msgs_s", window > 0.0 ? static_cast<double>(total) / window : 0.0},
           {"transport", stats_json(t.stats())},
           {"wall_s", now_s() - t0}};
  return out.dump();
}

SelftestReport run_selftest(const SelftestOptions& o) {
  if (o.processes < 2 || o.processes > 110)
    throw Error("--processes", 0, "expected 2..110, got " + std::to_string(o.processes));
  if (o.kill_id && *o.kill_id >= o.processes)
    throw Error("--kill", 0, "expected a robot id 0.." + std::to_string(o.processes - 1));
  if (!(o.loss >= 0.0 && o.loss <= 1.0))
    throw Error("--loss", 0, "expected a probability in [0, 1]");
  if (!(o.timeout_s > 2.0) || !std::isfinite(o.timeout_s))
    throw Error("--timeout", 0, "expected more than 2 seconds");
  if (o.domain_id && *o.domain_id > 230) throw Error("--domain", 0, "expected 0..230");

  const double t0 = now_s();
  const auto pid = static_cast<std::uint32_t>(::getpid());
  const std::string tag =
      std::to_string(pid) + "-" +
      std::to_string(std::chrono::steady_clock::now().time_since_epoch().count() % 1000000007);
  namespace fs = std::filesystem;
  const fs::path dir = o.work_dir.empty() ? fs::temp_directory_path() : fs::path(o.work_dir);
  const fs::path config = dir / ("voronav-dds-" + tag + ".xml");
  write_cyclone_config(config, CycloneConfigOptions{});
  struct RemoveFile {
    fs::path p;
    ~RemoveFile() {
      std::error_code ec;
      fs::remove(p, ec);
    }
  } remove_config{config};

  std::vector<std::string> command = o.echo_command;
  if (command.empty()) command = {self_executable(), "dds-echo"};

  EchoOptions e;
  e.peers = o.processes;
  e.rounds = o.rounds;
  e.interval_s = o.interval_s;
  e.payload_bytes = o.payload_bytes;
  e.spacing_m = o.spacing_m;
  e.range_m = o.range_m;
  e.loss = o.loss;
  e.domain_id = o.domain_id.value_or(1 + pid % 200);
  e.partition = "selftest-" + tag;
  e.startup_timeout_s = o.startup_timeout_s;
  e.quiet_s = o.quiet_s;
  e.timeout_s = o.timeout_s - 2.0;
  validate(e);

  LaunchOptions lo;
  lo.timeout_s = o.timeout_s;
  ProcessGroup group(lo);
  for (std::uint32_t i = 0; i < o.processes; ++i) {
    EchoOptions ei = e;
    ei.id = i;
    ei.seed = o.seed * 1000003ULL + i;
    ChildSpec spec;
    spec.name = "robot-" + std::to_string(i);
    spec.argv = command;
    for (auto& a : echo_args(ei))
      spec.argv.push_back(std::move(a));
    spec.env["CYCLONEDDS_URI"] = cyclone_uri_for(config);
    group.start(std::move(spec));
  }
  // The victim is killed once every robot finished discovery (so that nobody waits for it) and
  // the victim itself sent its first round: a robot dying mid-run.
  auto kill_when_due = [&](ProcessGroup& g) {
    if (!o.kill_id || !g.running(*o.kill_id)) return;
    for (std::uint32_t i = 0; i < o.processes; ++i) {
      const std::string& err = g.stderr_so_far(i);
      const std::string me = "voronav-dds-echo " + std::to_string(i) + ": ";
      if (err.find(me + "ready") == std::string::npos &&
          err.find(me + "not all peers found") == std::string::npos && g.running(i))
        return;
    }
    const std::string victim = "voronav-dds-echo " + std::to_string(*o.kill_id) + ": round 1 sent";
    if (g.stderr_so_far(*o.kill_id).find(victim) != std::string::npos) g.kill(*o.kill_id);
  };
  SelftestReport rep;
  rep.processes = o.processes;
  rep.children = group.wait_all(kill_when_due);
  rep.wall_s = now_s() - t0;

  auto violation = [&](std::string v) {
    if (rep.violations.size() < 50) rep.violations.push_back(std::move(v));
  };
  std::map<std::uint32_t, json> reports;
  for (std::uint32_t i = 0; i < o.processes; ++i) {
    const ChildResult& c = rep.children[i];
    const bool victim = o.kill_id && *o.kill_id == i;
    if (victim) {
      if (c.status != ChildStatus::kKilled)
        violation("robot " + std::to_string(i) + " was to be killed but " +
                  std::string(to_string(c.status)));
      continue;
    }
    if (!c.ok()) {
      std::string tail = c.stderr_text.size() > 300
                             ? c.stderr_text.substr(c.stderr_text.size() - 300)
                             : c.stderr_text;
      violation("robot " + std::to_string(i) + " " + std::string(to_string(c.status)) + " (exit " +
                std::to_string(c.exit_code) + "): " + tail);
      continue;
    }
    try {
      reports[i] = json::parse(c.stdout_text);
    } catch (const std::exception& ex) {
      violation("robot " + std::to_string(i) + ": unreadable report: " + ex.what());
    }
  }

  std::vector<double> p50s;
  for (const auto& [r, j] : reports) {
    rep.duplicates += j.value("duplicates", 0ULL);
    if (j.value("corrupt", 0ULL) != 0)
      violation("robot " + std::to_string(r) + " got corrupt payloads");
    if (j.value("wrong_destination", 0ULL) != 0)
      violation("robot " + std::to_string(r) + " got packets with the wrong destination");
    rep.rejected += j["transport"].value("rejected", 0ULL);
    if (j.value("received_total", 0ULL) > 0) {
      p50s.push_back(j["latency_ms"].value("p50", 0.0));
      rep.latency_p99_ms = std::max(rep.latency_p99_ms, j["latency_ms"].value("p99", 0.0));
    }
    rep.throughput_msgs_s += j.value("throughput_msgs_s", 0.0);
    const json& rec = j["received"];
    for (std::uint32_t s = 0; s < o.processes; ++s) {
      if (s == r) continue;
      const std::string key = std::to_string(s);
      const long long b = rec.contains(key) ? rec[key].value("broadcast", 0LL) : 0LL;
      const long long d = rec.contains(key) ? rec[key].value("direct", 0LL) : 0LL;
      const bool near = in_range(s, r, o.spacing_m, o.range_m);
      if (!near) {
        if (b + d != 0) {
          rep.out_of_range_delivered += static_cast<std::uint64_t>(b + d);
          violation("robot " + std::to_string(r) + " heard out-of-range robot " + key);
        }
        continue;
      }
      const long long eb = o.rounds;
      const long long ed = target_of(s, o.processes) == r ? o.rounds : 0;
      if (b > eb || d > ed)
        violation("robot " + std::to_string(r) + " got more from " + key + " than was sent");
      const bool victim = o.kill_id && *o.kill_id == s;
      if (victim) continue;
      rep.expected += static_cast<std::uint64_t>(eb + ed);
      rep.delivered += static_cast<std::uint64_t>(std::min(b, eb) + std::min(d, ed));
      if (o.loss == 0.0 && (b != eb || d != ed))
        violation("robot " + std::to_string(r) + " got " + std::to_string(b) + "+" +
                  std::to_string(d) + " of " + std::to_string(eb) + "+" + std::to_string(ed) +
                  " messages from " + key);
    }
  }
  if (rep.duplicates != 0) violation(std::to_string(rep.duplicates) + " duplicate deliveries");
  if (!p50s.empty()) rep.latency_p50_ms = percentile(p50s, 0.5);
  rep.passed = rep.violations.empty();

  json children = json::array();
  for (std::uint32_t i = 0; i < o.processes; ++i) {
    const ChildResult& c = rep.children[i];
    json cj{{"id", i},
            {"status", std::string(to_string(c.status))},
            {"exit_code", c.exit_code},
            {"wall_s", c.wall_s}};
    if (reports.count(i) != 0) {
      const json& j = reports[i];
      cj["startup_s"] = j.value("startup_s", 0.0);
      cj["known_at_start"] = j.value("known_at_start", 0);
      cj["matched_at_start"] = j.value("matched_at_start", 0);
      cj["received_total"] = j.value("received_total", 0ULL);
      cj["complete"] = j.value("complete", false);
    }
    children.push_back(cj);
  }
  json out{
      {"passed", rep.passed},
      {"processes", o.processes},
      {"rounds", o.rounds},
      {"payload_bytes", o.payload_bytes},
      {"range_m", std::isfinite(o.range_m) ? json(o.range_m) : json("inf")},
      {"spacing_m", o.spacing_m},
      {"loss", o.loss},
      {"killed", o.kill_id ? json(*o.kill_id) : json(nullptr)},
      {"wall_s", rep.wall_s},
      {"expected", rep.expected},
      {"delivered", rep.delivered},
      {"delivery_ratio",
       rep.expected ? static_cast<double>(rep.delivered) / static_cast<double>(rep.expected) : 1.0},
      {"out_of_range_delivered", rep.out_of_range_delivered},
      {"duplicates", rep.duplicates},
      {"rejected", rep.rejected},
      {"latency_p50_ms", rep.latency_p50_ms},
      {"latency_p99_ms", rep.latency_p99_ms},
      {"throughput_msgs_s", rep.throughput_msgs_s},
      {"violations", rep.violations},
      {"children", children}};
  rep.json = out.dump();
  return rep;
}

}  // namespace voronav::dds
