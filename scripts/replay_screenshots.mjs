// Screenshot of one replay page in headless Chromium (the browser test's machinery), paused at a
// chosen fraction of the recording. Used by scripts/replay_screenshots.sh.
// Usage: node replay_screenshots.mjs PAGE.html OUT.png FRACTION [WIDTH HEIGHT]
// Prints one JSON line: {"out": ..., "time": ..., "start": ..., "end": ...}.
import { chromium } from "playwright-core";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { pathToFileURL } from "node:url";

const [pagePath, outPath, fracArg, wArg, hArg] = process.argv.slice(2);
if (!pagePath || !outPath) {
  console.error("usage: node replay_screenshots.mjs PAGE.html OUT.png FRACTION [WIDTH HEIGHT]");
  process.exit(2);
}
const frac = Number(fracArg ?? 1);
if (!(frac >= 0 && frac <= 1)) {
  console.error(`replay_screenshots.mjs: FRACTION must be in [0, 1], got '${fracArg}'`);
  process.exit(2);
}
const width = Number(wArg || 1280), height = Number(hArg || 860);
const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), "voronav-shot-"));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-dev-shm-usage",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  viewport: { width, height },
  deviceScaleFactor: 1,
});
try {
  const page = context.pages()[0] || (await context.newPage());
  await page.goto(pathToFileURL(path.resolve(pagePath)).href);
  await page.waitForFunction(() => window.voronav && window.voronav.ready, null, { timeout: 60000 });
  const st = await page.evaluate((f) => {
    const v = window.voronav;
    v.pause();
    const s = v.state();
    v.setTime(s.start + f * (s.end - s.start));
    return v.state();
  }, frac);
  await page.waitForTimeout(500);
  await page.screenshot({ path: outPath, fullPage: false });
  console.log(JSON.stringify({ out: outPath, time: st.time, start: st.start, end: st.end }));
} finally {
  await context.close();
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
