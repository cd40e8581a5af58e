// Frames per second of a replay page in headless Chromium while it plays near the end of the
// recording (where every trail is longest), with a baseline measured in the same browser right
// after, and the renderer's CPU time per frame (from a Chromium trace: thread time, which a
// loaded machine disturbs less than frame rates).
// Usage: node replay_fps.mjs PAGE.html [SPEED] [SECONDS] [BASELINE_PAGE.html]
// Prints one JSON line: {"fps", "frames", "ms", "load_ms", "cpu_ms_per_frame": {"main", "script",
// "raster"}, "baseline_fps"} (baseline_fps only with a baseline page).
import { launchChromium, openReplay } from "./chromium.mjs";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

const [pagePath, speedArg, secondsArg, baselinePath] = process.argv.slice(2);
if (!pagePath) {
  console.error("usage: node replay_fps.mjs PAGE.html [SPEED] [SECONDS] [BASELINE_PAGE.html]");
  process.exit(2);
}
const speed = Number(speedArg || 1), seconds = Number(secondsArg || 4);
const { browser, page, close } = await launchChromium({ width: 1400, height: 1000 });

// Plays the open page from (end - speed * (secs + 1.5)) and counts the frames drawn in `secs`.
async function measure(page, spd, secs) {
  return page.evaluate(async ([spd, secs]) => {
    const v = window.voronav, s = v.state();
    v.setSpeed(spd);
    // Start far enough before the end that playback lasts the whole measurement, and let the
    // page draw every trail up to there first (a seek rebuilds the trail layer once).
    v.setTime(Math.max(s.start, s.end - spd * (secs + 1.5)));
    v.play();
    await new Promise((ok) => setTimeout(ok, 500));
    const f0 = v.state().frames, w0 = performance.now();
    await new Promise((ok) => setTimeout(ok, secs * 1000));
    const f1 = v.state().frames, w1 = performance.now();
    v.pause();
    return { frames: f1 - f0, ms: w1 - w0 };
  }, [spd, secs]);
}

const traceDir = fs.mkdtempSync(path.join(os.tmpdir(), "voronav-fps-"));
try {
  const loadMs = await openReplay(page, pagePath);
  const r = await measure(page, speed, seconds);
  // CPU time per frame on the renderer's main thread (script, style, layout, and the canvas
  // drawing that Chromium does when it commits a frame), measured in a second, traced, playback.
  const traceFile = path.join(traceDir, "trace.json");
  await page.evaluate((spd) => { const v = window.voronav, s = v.state(); v.setSpeed(spd); v.setTime(Math.max(s.start, s.end - spd * 4)); v.play(); }, speed);
  await page.waitForTimeout(300);
  await browser.startTracing(page, { path: traceFile, categories: ["devtools.timeline", "cc"] });
  const g0 = await page.evaluate(() => window.voronav.state().frames);
  await page.waitForTimeout(2000);
  const g1 = await page.evaluate(() => window.voronav.state().frames);
  await browser.stopTracing();
  await page.evaluate(() => window.voronav.pause());
  const events = JSON.parse(fs.readFileSync(traceFile, "utf8")).traceEvents;
  const mainTid = new Set(events.filter((e) => e.ph === "M" && e.name === "thread_name" && e.args.name === "CrRendererMain")
    .map((e) => e.pid + ":" + e.tid));
  const cpu = (e) => (e.tdur !== undefined ? e.tdur : e.dur);
  const onMain = events.filter((e) => e.ph === "X" && mainTid.has(e.pid + ":" + e.tid)).sort((a, b) => a.ts - b.ts);
  let main = 0, end = -Infinity;
  onMain.forEach((e) => { if (e.ts >= end) { main += cpu(e); end = e.ts + e.dur; } });  // top level only
  const sum = (name) => onMain.filter((e) => e.name === name).reduce((a, e) => a + cpu(e), 0);
  const n = Math.max(1, g1 - g0);
  const out = { fps: (1000 * r.frames) / r.ms, frames: r.frames, ms: r.ms, load_ms: loadMs,
                cpu_ms_per_frame: { main: main / 1000 / n, script: sum("FunctionCall") / 1000 / n,
                                    raster: sum("LayerTreeHost::DoUpdateLayers") / 1000 / n } };
  if (baselinePath) {
    await openReplay(page, baselinePath);
    const b = await measure(page, speed, seconds);
    out.baseline_fps = (1000 * b.frames) / b.ms;
  }
  console.log(JSON.stringify(out));
} finally {
  await close();
  fs.rmSync(traceDir, { recursive: true, force: true });
}
