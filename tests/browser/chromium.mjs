// Headless Chromium for the replay page tools (issue 20): one launch shared by the browser test
// (replay.test.mjs), the fps benchmark (bench/replay_fps.mjs, bench/replay_profile.mjs) and the
// screenshots (scripts/replay_screenshots.mjs). The system's Chromium (Debian package, or
// $CHROMIUM) driven by playwright-core, software drawing (--disable-gpu), no network services,
// a fresh profile per launch. prepare.sh copies this file next to the scripts that import it.
import { chromium } from "playwright-core";
import path from "node:path";
import { pathToFileURL } from "node:url";

export const CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                              "--disable-background-networking", "--disable-component-update",
                              "--disable-sync", "--disable-dev-shm-usage"];

// Launches Chromium and opens one page of WIDTH x HEIGHT CSS pixels at device scale 1.
// Returns { browser, context, page, close }; call close() in a finally block.
export async function launchChromium({ width = 1400, height = 1000, args = [] } = {}) {
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: CHROMIUM_ARGS.concat(args),
  });
  try {
    const context = await browser.newContext({ viewport: { width, height }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    return { browser, context, page, close: () => browser.close() };
  } catch (e) {
    await browser.close();
    throw e;
  }
}

// Opens a replay page from a file path and waits until it has drawn its first frame
// (window.voronav.ready). Returns the milliseconds this took.
export async function openReplay(page, pagePath, timeoutMs = 60000) {
  const t0 = Date.now();
  await page.goto(pathToFileURL(path.resolve(pagePath)).href);
  await page.waitForFunction(() => window.voronav && window.voronav.ready, null, { timeout: timeoutMs });
  return Date.now() - t0;
}
