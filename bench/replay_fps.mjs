// Frames per second of a replay page in headless Chromium while it plays near the end of the
// recording (where every trail is longest). Usage: node replay_fps.mjs PAGE.html [SPEED] [SECONDS]
// Prints one JSON line: {"fps": ..., "frames": ..., "ms": ..., "load_ms": ...}.
import { chromium } from "playwright-core";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { pathToFileURL } from "node:url";

const [pagePath, speedArg, secondsArg] = process.argv.slice(2);
const speed = Number(speedArg || 1), seconds = Number(secondsArg || 4);
const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), "voronav-fps-"));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-dev-shm-usage",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  viewport: { width: 1400, height: 1000 },
  deviceScaleFactor: 1,
});
try {
  const page = context.pages()[0] || (await context.newPage());
  const t0 = Date.now();
  await page.goto(pathToFileURL(path.resolve(pagePath)).href);
  await page.waitForFunction(() => window.voronav && window.voronav.ready, null, { timeout: 60000 });
  const loadMs = Date.now() - t0;
  const r = await page.evaluate(async ([spd, secs]) => {
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
  }, [speed, seconds]);
  console.log(JSON.stringify({ fps: (1000 * r.frames) / r.ms, frames: r.frames, ms: r.ms, load_ms: loadMs }));
} finally {
  await context.close();
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
