// Screenshot of one replay page in headless Chromium (the browser test's machinery), paused at a
// chosen fraction of the recording. Used by scripts/replay_screenshots.sh (which copies it next to
// the shared launch module tests/browser/chromium.mjs).
// Usage: node replay_screenshots.mjs PAGE.html OUT.png FRACTION [WIDTH HEIGHT]
// Prints one JSON line: {"out": ..., "time": ..., "start": ..., "end": ...}.
import { launchChromium, openReplay } from "./chromium.mjs";

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
const { page, close } = await launchChromium({ width, height });
try {
  await openReplay(page, pagePath);
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
  await close();
}
