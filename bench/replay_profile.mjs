// Where the frame time of a replay page goes while it plays near the end of the recording
// (issue 20), in headless Chromium: a V8 CPU profile (script time per page function, inclusive)
// and a Chromium trace (main-thread work outside script: style, layout, paint, compositing, and
// the raster and compositor threads). Usage: node replay_profile.mjs PAGE.html [SPEED] [SECONDS]
// Prints one JSON object: fps, ms per frame, the page functions' inclusive script ms per frame,
// and the trace's ms per frame by event name and thread.
import { launchChromium, openReplay } from "./chromium.mjs";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

const [pagePath, speedArg, secondsArg] = process.argv.slice(2);
if (!pagePath) {
  console.error("usage: node replay_profile.mjs PAGE.html [SPEED] [SECONDS]");
  process.exit(2);
}
const speed = Number(speedArg || 1), seconds = Number(secondsArg || 3);
const { browser, page, close } = await launchChromium();
const traceFile = path.join(fs.mkdtempSync(path.join(os.tmpdir(), "voronav-trace-")), "trace.json");
try {
  await openReplay(page, pagePath);
  await page.evaluate(([spd, secs]) => {
    const v = window.voronav, s = v.state();
    v.setSpeed(spd);
    v.setTime(Math.max(s.start, s.end - spd * (secs + 1.5)));
    v.play();
  }, [speed, seconds]);
  await page.waitForTimeout(500);
  const cdp = await page.context().newCDPSession(page);
  await cdp.send("Profiler.enable");
  await cdp.send("Profiler.setSamplingInterval", { interval: 200 });
  await browser.startTracing(page, { path: traceFile, categories: ["devtools.timeline", "disabled-by-default-devtools.timeline", "cc", "viz"] });
  const f0 = await page.evaluate(() => window.voronav.state().frames);
  await cdp.send("Profiler.start");
  const w0 = Date.now();
  await page.waitForTimeout(seconds * 1000);
  const { profile } = await cdp.send("Profiler.stop");
  const ms = Date.now() - w0;
  const f1 = await page.evaluate(() => window.voronav.state().frames);
  await browser.stopTracing();
  await page.evaluate(() => window.voronav.pause());
  const frames = Math.max(1, f1 - f0);

  // CPU profile: inclusive time per function name (each sample counted once per name on its stack).
  const byId = new Map(profile.nodes.map((n) => [n.id, n]));
  const parent = new Map();
  profile.nodes.forEach((n) => (n.children || []).forEach((c) => parent.set(c, n.id)));
  const dt = new Map();
  profile.samples.forEach((id, i) => dt.set(id, (dt.get(id) || 0) + (profile.timeDeltas[i] || 0)));
  const incl = new Map();
  dt.forEach((us, id) => {
    const seen = new Set();
    for (let k = id; k !== undefined; k = parent.get(k)) {
      const name = byId.get(k).callFrame.functionName || "(anonymous)";
      if (seen.has(name)) continue;
      seen.add(name);
      incl.set(name, (incl.get(name) || 0) + us);
    }
  });
  const script = {};
  [...incl.entries()].filter(([n]) => !["(root)", "(program)", "(idle)", "(garbage collector)"].includes(n) || n === "(garbage collector)")
    .sort((a, b) => b[1] - a[1]).slice(0, 25)
    .forEach(([n, us]) => { script[n] = +(us / 1000 / frames).toFixed(2); });

  // Trace: complete events by thread and name, ms per frame (top-level only: nested events of the
  // same thread are skipped so that the sums do not double count).
  const trace = JSON.parse(fs.readFileSync(traceFile, "utf8"));
  const events = trace.traceEvents || trace;
  const threads = new Map();
  events.filter((e) => e.ph === "M" && e.name === "thread_name").forEach((e) => threads.set(e.pid + ":" + e.tid, e.args.name));
  const byThread = new Map();
  events.filter((e) => e.ph === "X" && e.dur > 0).forEach((e) => {
    const key = e.pid + ":" + e.tid;
    if (!byThread.has(key)) byThread.set(key, []);
    byThread.get(key).push(e);
  });
  // Exclusive (self) CPU time per event name and thread: a parent's time minus its children's.
  const work = {};
  byThread.forEach((list, key) => {
    const tname = threads.get(key) || key;
    list.sort((a, b) => a.ts - b.ts || b.dur - a.dur);
    const stack = [];
    // Thread (CPU) time where the trace has it: less sensitive to a loaded machine than wall time.
    const cpu = (e) => (e.tdur !== undefined ? e.tdur : e.dur);
    const add = (e, us) => { const k = tname + " / " + e.name; work[k] = (work[k] || 0) + us; };
    list.forEach((e) => {
      while (stack.length && stack[stack.length - 1].end <= e.ts) stack.pop();
      if (stack.length) add(stack[stack.length - 1].e, -cpu(e));
      add(e, cpu(e));
      stack.push({ e, end: e.ts + e.dur });
    });
  });
  const trace_ms = {};
  Object.entries(work).sort((a, b) => b[1] - a[1]).filter(([, us]) => us / 1000 / frames >= 0.05).slice(0, 30)
    .forEach(([k, us]) => { trace_ms[k] = +(us / 1000 / frames).toFixed(2); });
  console.log(JSON.stringify({ page: pagePath, speed, fps: +(1000 * frames / ms).toFixed(1), frames,
                               ms_per_frame: +(ms / frames).toFixed(1), script_ms_per_frame: script,
                               trace_ms_per_frame: trace_ms }, null, 1));
} finally {
  await close();
  fs.rmSync(path.dirname(traceFile), { recursive: true, force: true });
}
