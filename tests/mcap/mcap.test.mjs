// Reads the ROS 2 bags (MCAP) that short runs of voronav's commands write, with the reference
// reader (@mcap/core: indexed reader over the summary and chunk indexes, chunk and summary CRCs;
// stream reader over every record) and decodes every message of every channel with
// @foxglove/rosmsg2-serialization against the ros2msg schema stored in the file. Then checks
// values: the map's width/height/resolution/origin equal the input map; a path's first and last
// poses equal start and goal; /tf is map -> robot_N/base_link; times never decrease.
// Usage: node mcap.test.mjs VORONAV_BINARY DATA_DIR WORK_DIR
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import assert from "node:assert/strict";
import { McapIndexedReader, McapStreamReader, hasMcapPrefix } from "@mcap/core";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import { decompress as zstdDecompress } from "fzstd";

// Also: node mcap.test.mjs --check FILE.mcap...  (the generic checks on any bag, e.g. demo's)
const [bin, data, work] = process.argv.slice(2);
const checkOnly = bin === "--check";
if (!checkOnly && (!bin || !data || !work)) {
  console.error("usage: node mcap.test.mjs VORONAV_BINARY DATA_DIR WORK_DIR | --check FILE...");
  process.exit(2);
}
if (!checkOnly) fs.mkdirSync(work, { recursive: true });

const decompressHandlers = { zstd: (buf, size) => zstdDecompress(buf, new Uint8Array(Number(size))) };

// CRC-32 (IEEE), as the MCAP specification uses it.
const crcTable = Array.from({ length: 256 }, (_, i) => {
  let c = i;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

function run(args) {
  return execFileSync(bin, args, { cwd: work, encoding: "utf8" });
}

const near = (a, b, tol, what) =>
  assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b} (tolerance ${tol})`);
const toSec = (t) => t.sec + t.nanosec * 1e-9;
const yawOf = (q) => Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));

/// Reads and decodes a whole bag; returns {topics: {topic: [{t, msg}]}, types: {topic: type}}.
async function readBag(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  assert.ok(hasMcapPrefix(new DataView(bytes.buffer, bytes.byteOffset, 8)), `${file}: no MCAP magic`);
  const readable = {
    size: async () => BigInt(bytes.length),
    read: async (offset, size) => bytes.subarray(Number(offset), Number(offset + size)),
  };
  // The indexed reader checks the footer, the summary CRC and reads the summary.
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  assert.equal(reader.header.profile, "ros2", `${file}: profile`);
  assert.ok(reader.statistics, `${file}: no Statistics record in the summary`);
  assert.ok(reader.chunkIndexes.length > 0, `${file}: no chunk index`);
  assert.equal(reader.chunkIndexes.length, reader.statistics.chunkCount, `${file}: chunk count`);
  assert.equal(reader.channelsById.size, reader.statistics.channelCount, `${file}: channel count`);
  // Data section CRC (Data End record right before the summary).
  const summaryStart = Number(reader.footer.summaryStart);
  const dataEnd = summaryStart - 13;
  assert.equal(bytes[dataEnd], 0x0f, `${file}: Data End record not before the summary`);
  const view = new DataView(bytes.buffer, bytes.byteOffset);
  assert.equal(view.getUint32(summaryStart - 4, true), crc32(bytes.subarray(0, dataEnd)),
    `${file}: data section CRC`);

  const decoders = new Map();
  const types = {};
  for (const [id, ch] of reader.channelsById) {
    const schema = reader.schemasById.get(ch.schemaId);
    assert.equal(ch.messageEncoding, "cdr", `${file}: ${ch.topic} encoding`);
    assert.equal(schema.encoding, "ros2msg", `${file}: ${ch.topic} schema encoding`);
    const text = new TextDecoder().decode(schema.data);
    decoders.set(id, new MessageReader(parse(text, { ros2: true })));
    types[ch.topic] = schema.name;
  }
  // Every message through the index (chunk CRCs checked), decoded against its schema.
  const topics = {};
  let count = 0;
  let last = -1n;
  for await (const m of reader.readMessages({ validateCrcs: true })) {
    const ch = reader.channelsById.get(m.channelId);
    assert.ok(m.logTime >= last, `${file}: log times decrease`);
    last = m.logTime;
    assert.equal(m.publishTime, m.logTime, `${file}: publish_time != log_time`);
    const msg = decoders.get(m.channelId).readMessage(m.data);
    (topics[ch.topic] ??= []).push({ t: Number(m.logTime) * 1e-9, msg });
    count++;
  }
  assert.equal(BigInt(count), reader.statistics.messageCount, `${file}: message count`);
  for (const [id, n] of reader.statistics.channelMessageCounts)
    assert.equal(BigInt(topics[reader.channelsById.get(id).topic]?.length ?? 0), n,
      `${file}: per-channel count`);
  // The same messages once more, record by record in file order, with the stream reader.
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(bytes);
  let streamed = 0;
  let footer = false;
  for (let r; (r = stream.nextRecord()); ) {
    if (r.type === "Message") streamed++;
    if (r.type === "Footer") footer = true;
  }
  assert.ok(stream.done() && footer, `${file}: stream reader did not reach the footer`);
  assert.equal(streamed, count, `${file}: stream reader message count`);
  checkCommon(file, topics, types);
  return { topics, types };
}

function checkCommon(file, topics, types) {
  const expected = {
    "/map": "nav_msgs/msg/OccupancyGrid", "/known_map": "nav_msgs/msg/OccupancyGrid",
    "/plan": "nav_msgs/msg/Path", "/tf": "tf2_msgs/msg/TFMessage",
    "/robots": "geometry_msgs/msg/PoseArray", "/voronoi": "visualization_msgs/msg/MarkerArray",
    "/topology": "visualization_msgs/msg/MarkerArray",
    "/collision_boxes": "visualization_msgs/msg/MarkerArray",
    "/messages": "visualization_msgs/msg/MarkerArray", "/events": "std_msgs/msg/String",
  };
  for (const [topic, type] of Object.entries(types)) {
    const want = /^\/robot_\d+\/plan$/.test(topic) ? "nav_msgs/msg/Path" : expected[topic];
    assert.equal(type, want, `${file}: ${topic} type`);
    for (const { t, msg } of topics[topic]) {
      if (msg.header) {
        assert.equal(msg.header.frame_id, "map", `${file}: ${topic} frame`);
        near(toSec(msg.header.stamp), t, 1e-6, `${file}: ${topic} stamp = log time`);
      }
    }
  }
  for (const topic of ["/tf", "/robots"]) {
    const ts = (topics[topic] ?? []).map((m) => m.t);
    for (let i = 1; i < ts.length; i++) assert.ok(ts[i] > ts[i - 1], `${file}: ${topic} times`);
  }
  for (const { msg } of topics["/tf"] ?? []) {
    assert.ok(msg.transforms.length > 0);
    for (const tf of msg.transforms) {
      assert.equal(tf.header.frame_id, "map", `${file}: /tf parent`);
      assert.match(tf.child_frame_id, /^robot_\d+\/base_link$/, `${file}: /tf child`);
      const q = tf.transform.rotation;
      near(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1, 1e-9, `${file}: unit quaternion`);
    }
  }
  for (const { msg } of topics["/events"] ?? []) {
    const e = JSON.parse(msg.data);
    assert.ok(typeof e.t === "number" && typeof e.event === "string", `${file}: /events JSON`);
  }
  for (const { msg } of topics["/map"] ?? [])
    assert.equal(msg.data.length, msg.info.width * msg.info.height, `${file}: /map data size`);
}

function checkMap(file, m, want) {
  near(m.info.resolution, want.resolution, 1e-6, `${file}: /map resolution`);
  assert.equal(m.info.width, want.width, `${file}: /map width`);
  assert.equal(m.info.height, want.height, `${file}: /map height`);
  near(m.info.origin.position.x, want.origin[0], 1e-9, `${file}: /map origin x`);
  near(m.info.origin.position.y, want.origin[1], 1e-9, `${file}: /map origin y`);
  near(yawOf(m.info.origin.orientation), want.origin[2], 1e-9, `${file}: /map origin yaw`);
}

function pgmSize(file) {
  const tokens = fs.readFileSync(file, "latin1").slice(0, 200).replace(/#[^\n]*\n/g, " ")
    .split(/\s+/).filter(Boolean);
  return [Number(tokens[1]), Number(tokens[2])];
}

function checkPath(file, msg, first, last, tol) {
  const p = msg.poses;
  assert.ok(p.length >= 2, `${file}: path too short`);
  near(p[0].pose.position.x, first[0], tol, `${file}: path start x`);
  near(p[0].pose.position.y, first[1], tol, `${file}: path start y`);
  near(p.at(-1).pose.position.x, last[0], tol, `${file}: path goal x`);
  near(p.at(-1).pose.position.y, last[1], tol, `${file}: path goal y`);
}

const checks = [];
function test(name, fn) { checks.push([name, fn]); }

test("plan on a ROS map (metres)", async () => {
  const yaml = path.join(data, "ros_maps/turtlebot3_world/map.yaml");
  const out = JSON.parse(run(["plan", "--map", yaml, "--start", "-1.9,-0.5", "--goal", "1.9,0.5",
    "--radius", "0.1", "--json", "--mcap", "plan_ros.mcap"]));
  const { topics } = await readBag(path.join(work, "plan_ros.mcap"));
  const [w, h] = pgmSize(path.join(data, "ros_maps/turtlebot3_world/map.pgm"));
  assert.equal(topics["/map"].length, 1);
  checkMap("plan_ros", topics["/map"][0].msg, { resolution: 0.05, width: w, height: h, origin: [-10, -10, 0] });
  const plan = topics["/plan"][0].msg;
  checkPath("plan_ros", plan, out.path_world[0], out.path_world.at(-1), 1e-9);
  checkPath("plan_ros", plan, [-1.9, -0.5], [1.9, 0.5], 0.05 / Math.SQRT2 + 1e-9);
  assert.equal(plan.poses.length, out.path_world.length);
  assert.deepEqual(topics["/robot_0/plan"][0].msg, plan);
  // The robot drives the path: /tf starts at the start and ends at the goal.
  const tf = topics["/tf"];
  near(tf[0].msg.transforms[0].transform.translation.x, out.path_world[0][0], 1e-9, "tf start");
  near(tf.at(-1).msg.transforms[0].transform.translation.y, out.path_world.at(-1)[1], 1e-9, "tf goal");
  assert.equal(tf.at(-1).msg.transforms[0].child_frame_id, "robot_0/base_link");
  near(tf.at(-1).t, out.length, 1e-6, "1 m/s along the path");
  assert.equal(topics["/robots"].length, tf.length);
  assert.equal(JSON.parse(topics["/events"][0].msg.data).event, "path");
});

test("plan on a Moving AI map (cells, y down)", async () => {
  const map = path.join(data, "movingai/arena.map");
  const out = JSON.parse(run(["plan", "--map", map, "--start", "3,3", "--goal", "40,40", "--json",
    "--mcap", "plan_movingai.mcap"]));
  const { topics } = await readBag(path.join(work, "plan_movingai.mcap"));
  const head = fs.readFileSync(map, "utf8").split("\n");
  const H = Number(head[1].split(" ")[1]), W = Number(head[2].split(" ")[1]);
  checkMap("plan_movingai", topics["/map"][0].msg, { resolution: 1, width: W, height: H, origin: [0, 0, 0] });
  // Cell (x, y) of the .scen convention (y down) is the world point (x + 0.5, H - y - 0.5).
  checkPath("plan_movingai", topics["/plan"][0].msg, [3.5, H - 3.5], [40.5, H - 40.5], 1e-9);
  checkPath("plan_movingai", topics["/plan"][0].msg, out.path_world[0], out.path_world.at(-1), 1e-9);
});

test("plan without a path", async () => {
  let failed = false;
  try {  // (0, 0) is a wall of the arena
    run(["plan", "--map", path.join(data, "movingai/arena.map"), "--start", "3,3", "--goal", "0,0",
      "--mcap", "plan_none.mcap"]);
  } catch (e) { failed = e.status === 1 || e.status === 2; }
  assert.ok(failed, "no path: exit code 1");
  const { topics } = await readBag(path.join(work, "plan_none.mcap"));
  assert.equal(topics["/plan"], undefined);
  assert.equal(JSON.parse(topics["/events"][0].msg.data).event, "no_path");
});

test("topo", async () => {
  const yaml = path.join(data, "ros_maps/turtlebot3_world/map.yaml");
  const out = JSON.parse(run(["topo", "--map", yaml, "--json", "--mcap", "topo.mcap"]));
  const { topics } = await readBag(path.join(work, "topo.mcap"));
  checkMap("topo", topics["/map"][0].msg, { resolution: out.resolution, width: out.width, height: out.height, origin: [-10, -10, 0] });
  const vor = topics["/voronoi"][0].msg.markers;
  const cells = vor.find((m) => m.ns === "Voronoi diagram");
  assert.equal(cells.points.length, out.voronoi_cells);
  assert.equal(vor.find((m) => m.ns === "Voronoi critical points nodes").points.length, out.critical_points.length);
  const topo = topics["/topology"][0].msg.markers;
  assert.equal(topo.find((m) => m.ns === "Topological graph nodes").points.length, out.regions);
  assert.equal(topo.find((m) => m.ns === "Topological graph edges").points.length, 2 * out.graph.edges.length);
});

test("coordinate", async () => {
  // Moving AI cells, y down: robot 1 goes from (3, 5) to (45, 12) on the 49 x 49 arena.
  const out = JSON.parse(run(["coordinate", "--scenario", path.join(data, "coordination/arena_four.yaml"),
    "--search", "exhaustive", "--json", "--mcap", "coordinate.mcap"]));
  const { topics } = await readBag(path.join(work, "coordinate.mcap"));
  checkMap("coordinate", topics["/map"][0].msg, { resolution: 1, width: 49, height: 49, origin: [0, 0, 0] });
  checkPath("coordinate", topics["/robot_1/plan"][0].msg, [3.5, 49 - 5.5], [45.5, 49 - 12.5], 1e-9);
  assert.equal(topics["/plan"], undefined, "a team has no single /plan");
  const boxes = topics["/collision_boxes"]?.[0].msg.markers ?? [];
  assert.equal(boxes.filter((m) => m.type === 4).length, out.boxes, "one line strip per collision box");
  const tf = topics["/tf"];
  near(tf.at(-1).t, out.makespan, 1e-6, "last /tf at the makespan");
  const ev = topics["/events"].map((e) => JSON.parse(e.msg.data));
  for (const a of out.agents) {
    const plan = topics[`/robot_${a.id}/plan`][0].msg.poses;
    const at = (k) => tf[k].msg.transforms.find((x) => x.child_frame_id === `robot_${a.id}/base_link`).transform.translation;
    near(at(0).x, plan[0].pose.position.x, 1e-9, `robot ${a.id} starts at its path start`);
    near(at(0).y, plan[0].pose.position.y, 1e-9, `robot ${a.id} starts at its path start`);
    near(at(tf.length - 1).x, plan.at(-1).pose.position.x, 1e-6, `robot ${a.id} ends at its goal`);
    near(at(tf.length - 1).y, plan.at(-1).pose.position.y, 1e-6, `robot ${a.id} ends at its goal`);
    const dep = ev.find((e) => e.event === "depart" && e.detail === `robot ${a.id}`);
    near(dep.t, a.delay, 1e-6, `robot ${a.id} departs after its delay`);
    const arr = ev.find((e) => e.event === "arrive" && e.detail === `robot ${a.id}`);
    near(arr.t, a.arrival, 1e-6, `robot ${a.id} arrival`);
  }
});

test("netsim (in process)", async () => {
  run(["netsim", "--scenario", path.join(data, "netsim/corridor.yaml"), "--json", "--mcap", "netsim.mcap"]);
  const { topics } = await readBag(path.join(work, "netsim.mcap"));
  const [w, h] = [topics["/map"][0].msg.info.width, topics["/map"][0].msg.info.height];
  assert.ok(w > 0 && h > 0);
  const robots = topics["/robots"][0].msg.poses;
  assert.equal(robots.length, 10);
  near(robots[0].position.x, 2.1, 1e-9, "source robot at its scenario position");
  near(robots[0].position.y, 1.7, 1e-9, "source robot at its scenario position");
  assert.equal(topics["/tf"][0].msg.transforms[9].child_frame_id, "robot_9/base_link");
  const route = topics["/plan"][0].msg;
  assert.ok(topics["/events"].some((e) => ["route_found", "route"].includes(JSON.parse(e.msg.data).event)));
  near(route.poses.at(-1).pose.position.x, 38.5, 0.5, "route ends at the destination");
  const arrows = topics["/messages"].flatMap((m) => m.msg.markers);
  assert.ok(arrows.length > 0 && arrows.every((a) => a.type === 0 && a.points.length === 2));
});

test("netsim over DDS records the processes' run (robot 5 killed)", async () => {
  // One process per robot; robot 5's dies after step 20 (t = 4 s). The bag is what the processes
  // recorded, so the kill is in /events and robot 5 stands still from then on.
  const out = JSON.parse(run(["netsim", "--scenario", path.join(data, "netsim/corridor.yaml"),
    "--method", "decentralized", "--transport", "dds", "--kill-robot", "5", "--kill-at-step", "20",
    "--json", "--mcap", "netsim_dds.mcap"]));
  const { topics } = await readBag(path.join(work, "netsim_dds.mcap"));
  const ev = topics["/events"].map((e) => JSON.parse(e.msg.data));
  const kill = ev.find((e) => e.event === "kill");
  assert.ok(kill, `a kill event: ${JSON.stringify(ev)}`);
  near(kill.t, 4.0, 1e-9, "killed at step 20 = 4 s");
  assert.deepEqual(out.decentralized.per_run[0].dead_robots, [5]);
  assert.match(out.decentralized.per_run[0].faults, /^robot 5 killed at step 20/);
  const at5 = (m) => m.msg.transforms.find((x) => x.child_frame_id === "robot_5/base_link")
    .transform.translation;
  const after = topics["/tf"].filter((m) => m.t >= 4.0 + 1e-9).map(at5);
  assert.ok(after.length > 0, "/tf after the kill");
  for (const p of after) {
    near(p.x, after[0].x, 1e-12, "robot 5 does not move after its death");
    near(p.y, after[0].y, 1e-12, "robot 5 does not move after its death");
  }
  assert.ok(topics["/messages"].flatMap((m) => m.msg.markers).length > 0, "the processes' messages");
});

test("explore", async () => {
  const out = JSON.parse(run(["explore", "--map", "paper", "--robots", "2", "--time", "60", "--json",
    "--mcap", "explore.mcap"]));
  const { topics } = await readBag(path.join(work, "explore.mcap"));
  const map = topics["/map"][0].msg, known = topics["/known_map"].at(-1).msg;
  assert.equal(known.info.width, map.info.width);
  assert.equal(known.info.height, map.info.height);
  near(map.info.width * map.info.resolution, 20, 1e-3, "paper world is 20 m wide");
  const unknown = known.data.filter((v) => v === -1).length;
  assert.ok(unknown > 0 && unknown < known.data.length, "known map partly explored");
  // /known_map grows during the run (every --known-map-period s), not once at the end.
  const knownCells = topics["/known_map"].map((m) => m.msg.data.filter((v) => v !== -1).length);
  assert.ok(knownCells.length >= 5, `several /known_map messages: ${knownCells.length}`);
  for (let i = 1; i < knownCells.length; i++)
    assert.ok(knownCells[i] > knownCells[i - 1], `known cells increase: ${knownCells}`);
  assert.ok(topics["/known_map"][0].t < 10, "the first /known_map early in the run");
  assert.equal(topics["/map"].length, 1, "the ground truth does not change");
  assert.equal(topics["/tf"][0].msg.transforms.length, 2);
  near(topics["/tf"].at(-1).t, out.sim_time_s ?? topics["/tf"].at(-1).t, 1.0, "run length");
});

if (checkOnly) {
  checks.length = 0;
  for (const file of process.argv.slice(3))
    test(file, async () => {
      const { topics } = await readBag(file);
      console.log(Object.entries(topics).map(([t, m]) => `${t}: ${m.length}`).join(", "));
    });
}
let failed = 0;
for (const [name, fn] of checks) {
  try {
    await fn();
    console.log(`ok   ${name}`);
  } catch (e) {
    failed++;
    console.log(`FAIL ${name}\n${e.stack}`);
  }
}
if (failed) process.exit(1);
console.log(`all ${checks.length} MCAP checks passed`);
