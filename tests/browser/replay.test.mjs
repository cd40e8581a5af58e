// End-to-end test of the replay page in a real browser (issue 9): the system's headless Chromium
// driven by playwright-core. Usage: node replay.test.mjs PAGE.html SCREENSHOT.png
// Checks: no console errors and no network requests, the map canvas is drawn, toggling a layer
// changes pixels (and toggling back restores them), the time slider moves the robots, play
// advances time and pause stops it, the plots are drawn; saves a screenshot. With TEMPLATE.html
// (voronav/report/viewer.html) also checks that the bare template explains itself, and with
// MINIMAL.html (a page of a map-only recording) that an almost empty recording shows cleanly.
import { launchChromium } from "./chromium.mjs";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

const [pagePath, screenshotPath, templatePath, minimalPath, manyPath] = process.argv.slice(2);
if (!pagePath || !screenshotPath) {
  console.error("usage: node replay.test.mjs PAGE.html SCREENSHOT.png");
  process.exit(2);
}

let failures = 0;
function check(cond, what) {
  console.log((cond ? "ok   " : "FAIL ") + what);
  if (!cond) failures++;
}

const { context, page, close } = await launchChromium({ width: 1400, height: 1000 });

try {
  const errors = [];
  const requests = [];
  await context.route("**/*", (route) => {
    const url = route.request().url();
    if (url.startsWith("file:") || url.startsWith("data:")) return route.continue();
    requests.push(url);
    return route.abort();
  });
  page.setDefaultTimeout(30000);
  // Errors and warnings fail the test, except Chromium's hint about this test's own repeated
  // getImageData readbacks (the page itself never reads pixels back).
  page.on("console", (m) => {
    if (m.type() !== "error" && m.type() !== "warning") return;
    if (m.type() === "warning" && m.text().includes("willReadFrequently")) return;
    errors.push(m.type() + ": " + m.text());
  });
  page.on("pageerror", (e) => errors.push("pageerror: " + e.message));

  await page.goto(pathToFileURL(path.resolve(pagePath)).href);
  await page.waitForFunction(() => window.voronav && window.voronav.ready, null, { timeout: 20000 });

  // Pixels of the map canvas, summarised in the page (no big transfers).
  const mapStats = () => page.evaluate(() => {
    const c = document.getElementById("map");
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    let nonBackground = 0, hash = 0;
    for (let i = 0; i < d.length; i += 4) {
      const v = (d[i] << 16) | (d[i + 1] << 8) | d[i + 2];
      if (colours.size < 5000) colours.add(v);
      if (v !== 0xe9ebef) nonBackground++;
      hash = (hash * 31 + v) | 0;
    }
    return { pixels: d.length / 4, colours: colours.size, nonBackground, hash };
  });
  // Snapshots of the map canvas stay in the page; only pixel-difference counts come back.
  const snap = (name) => page.evaluate((n) => {
    const c = document.getElementById("map");
    window.__snaps = window.__snaps || {};
    window.__snaps[n] = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
  }, name);
  const diff = (a, b) => page.evaluate(([x, y]) => {
    const p = window.__snaps[x], q = window.__snaps[y];
    if (p.length !== q.length) return -1;
    let n = 0;
    for (let i = 0; i < p.length; i += 4) if (p[i] !== q[i] || p[i + 1] !== q[i + 1] || p[i + 2] !== q[i + 2]) n++;
    return n;
  }, [a, b]);

  const s0 = await mapStats();
  check(s0.pixels > 100000, `map canvas is large (${s0.pixels} px)`);
  check(s0.nonBackground > 0.5 * s0.pixels, `map canvas is not blank (${s0.nonBackground} drawn px)`);
  check(s0.colours >= 5, `map canvas shows several colours (${s0.colours})`);

  const title = await page.textContent("#title");
  check(title.includes("three robots"), `title shown: "${title}"`);
  const layerNames = await page.$$eval("#layers label", (ls) => ls.map((l) => l.textContent.trim()));
  check(layerNames.includes("Voronoi (medial axis)") && layerNames.includes("Topological graph") &&
        layerNames.includes("Regions"), "layer toggles listed: " + layerNames.join(", "));

  // Toggle a layer with a real click on its checkbox.
  await snap("before");
  await page.getByLabel("Voronoi (medial axis)").click();
  let state = await page.evaluate(() => window.voronav.state());
  check(state.layers["raster:1"] === false, "Voronoi layer off after the click");
  await snap("without");
  const changed = await diff("before", "without");
  check(changed > 500, `hiding the Voronoi layer changes ${changed} pixels`);
  await page.getByLabel("Voronoi (medial axis)").click();
  await snap("again");
  check((await diff("before", "again")) === 0, "showing it again restores the picture");
  await page.getByLabel("Regions").click();
  await snap("regions");
  const regionsChanged = await diff("before", "regions");
  check(regionsChanged > 20000, `showing the Regions layer tints ${regionsChanged} pixels`);
  await page.getByLabel("Regions").click();

  // The time slider moves the robots.
  const pos0 = await page.evaluate(() => window.voronav.robotPositions());
  const t0 = (await page.evaluate(() => window.voronav.state())).time;
  await page.locator("#slider").fill("500");
  state = await page.evaluate(() => window.voronav.state());
  const pos1 = await page.evaluate(() => window.voronav.robotPositions());
  check(Math.abs(state.time - (state.start + (state.end - state.start) / 2)) < 0.1,
        `slider at the middle sets t = ${state.time.toFixed(2)} s of ${state.end.toFixed(2)} s`);
  const moved = pos0.map((p, i) => Math.hypot(pos1[i].x - p.x, pos1[i].y - p.y));
  check(moved.every((d) => d > 2), "every robot moved: " + moved.map((d) => d.toFixed(1) + " m").join(", "));
  await snap("middle");
  check((await diff("before", "middle")) > 200, "the map picture changes with the time");
  const timeText = await page.textContent("#timetext");
  check(timeText.startsWith("t = " + state.time.toFixed(1)), `time display reads "${timeText}"`);
  check(t0 === state.start, "the page opens at the start time");

  // The obstacle change shows up after its time.
  await page.evaluate(() => window.voronav.setTime(5.9));
  await snap("t5.9");
  await page.evaluate(() => window.voronav.setTime(6.05));
  await snap("t6.05");
  check((await diff("t5.9", "t6.05")) > 100, "the box appears at t = 6 s");

  // Zoom with the wheel, hover shows coordinates, double-click restores the view.
  await snap("view0");
  const box = await page.locator("#map").boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await snap("hover");
  check((await diff("view0", "hover")) > 100, "hovering the map draws the world coordinates");
  await page.mouse.wheel(0, -300);
  await page.waitForTimeout(100);
  await snap("zoomed");
  check((await diff("hover", "zoomed")) > 10000, "the wheel zooms the map");
  await page.mouse.dblclick(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.move(box.x + box.width / 2, box.y + box.height + 200);
  await page.evaluate(() => window.voronav.selectRobot(null));  // the click may have picked one
  await snap("reset");
  check((await diff("view0", "reset")) === 0, "double-click restores the view");

  // Play advances time, pause stops it.
  await page.locator("#speed").selectOption("4");
  await page.evaluate(() => window.voronav.setTime(window.voronav.state().start));
  await page.click("#play");
  await page.waitForTimeout(1200);
  state = await page.evaluate(() => window.voronav.state());
  check(state.playing && state.time > state.start + 0.5, `play advances time to t = ${state.time.toFixed(2)} s at speed ${state.speed}x`);
  const buttonText = await page.textContent("#play");
  check(buttonText.includes("Pause"), `the button offers "${buttonText.trim()}" while playing`);
  await page.click("#play");
  const tPaused = (await page.evaluate(() => window.voronav.state())).time;
  await page.waitForTimeout(400);
  state = await page.evaluate(() => window.voronav.state());
  check(!state.playing && state.time === tPaused, "pause stops the time");

  // Plots are drawn.
  const plots = await page.$$eval("canvas.plot", (cs) => cs.map((c) => {
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let ink = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) ink++;
    return ink / (d.length / 4);
  }));
  check(plots.length === 2, `two plots (${plots.length})`);
  check(plots.every((f) => f > 0.01), "plots are drawn: " + plots.map((f) => (100 * f).toFixed(1) + "% ink").join(", "));

  // Goals are marked in their robot's colour, on the map.
  const markers = await page.evaluate(() => window.voronav.markers());
  const colours = await page.evaluate(() => window.voronav.robotColors());
  const canvasBox = await page.locator("#map").boundingBox();
  check(markers.length === 3 && markers.every((m) => m.kind === "goal"), `three goal markers (${markers.length})`);
  check(markers.every((m) => colours.includes(m.color)), "each goal is drawn in its robot's colour");
  check(markers.every((m) => m.px > 0 && m.py > 0 && m.px < canvasBox.width && m.py < canvasBox.height),
        "every goal lies inside the map view");
  await page.evaluate(() => window.voronav.setLayer("markers", false));
  await snap("nomarkers");
  await page.evaluate(() => window.voronav.setLayer("markers", true));
  await snap("markers");
  check((await diff("nomarkers", "markers")) > 50, "the goal markers are drawn");

  // The event track lists the run's events; a click jumps to one.
  const events = await page.evaluate(() => window.voronav.events());
  const kinds = new Set(events.map((e) => e.kind));
  check(kinds.has("change") && kinds.has("repair") && kinds.has("arrival"),
        "events: " + events.map((e) => e.kind + "@" + e.t.toFixed(1)).join(", "));
  const marks = await page.evaluate(() => window.voronav.eventMarks());
  check(marks.reduce((a, m) => a + m.count, 0) === events.length && marks.length <= events.length,
        `the ${marks.length} marks on the track under the slider stand for all ${events.length} events`);
  await page.locator('#eventtrack .ev[data-kind="arrival"]').first().click();
  state = await page.evaluate(() => window.voronav.state());
  check(Math.abs(state.time - events.find((e) => e.kind === "arrival").t) < 1e-9 && !state.playing,
        `clicking the first arrival mark jumps to t = ${state.time} s`);
  // The change and the repair are 0.15 s apart, a few pixels: one mark stands for both, and a
  // click jumps to the first of them, the change.
  await page.locator('#eventtrack .ev[data-kinds~="change"]').dispatchEvent("click");
  state = await page.evaluate(() => window.voronav.state());
  check(Math.abs(state.time - 6.0) < 1e-9, `the change event jumps to t = ${state.time} s`);
  const evTitle = await page.getAttribute('#eventtrack .ev[data-kinds~="repair"]', "title");
  check(evTitle && evTitle.includes("re-plans"), `event tooltip: "${evTitle}"`);
  const rows = await page.evaluate(() => window.voronav.eventRows());
  check(rows.reduce((a, r) => a + r.count, 0) === events.length, "the events are listed beside the map");

  // Speeds up to 64x.
  const speeds = await page.$$eval("#speed option", (os) => os.map((o) => Number(o.value)));
  check(Math.max(...speeds) === 64, "speeds up to " + Math.max(...speeds) + "x");

  // Follow mode keeps the selected robot in the middle of the view.
  await page.evaluate(() => { window.voronav.selectRobot(2, true); window.voronav.setTime(10); });
  const followed = (await page.evaluate(() => window.voronav.robotPositions())).find((r) => r.id === 2);
  check(Math.abs(followed.px - canvasBox.width / 2) < 2, `followed robot at the centre (${followed.px.toFixed(1)} of ${canvasBox.width})`);
  await page.evaluate(() => { window.voronav.selectRobot(null, false); });
  await page.mouse.dblclick(canvasBox.x + 5, canvasBox.y + 5);

  // A moment with messages in flight, for the screenshot.
  await page.evaluate(() => window.voronav.setTime(6.2));
  await page.screenshot({ path: screenshotPath, fullPage: true });
  check(fs.statSync(screenshotPath).size > 20000, `screenshot saved: ${screenshotPath}`);

  // The bare template (no recording embedded) explains itself instead of failing.
  if (templatePath) {
    await page.goto(pathToFileURL(path.resolve(templatePath)).href);
    await page.waitForFunction(() => window.voronav !== undefined, null, { timeout: 20000 });
    const msg = await page.textContent("#error");
    check(await page.isVisible("#error") && msg.includes("no recording is embedded"),
          "the bare template says that no recording is embedded");
  }

  // A minimal recording (a map and nothing else) shows without errors.
  if (minimalPath) {
    await page.goto(pathToFileURL(path.resolve(minimalPath)).href);
    await page.waitForFunction(() => window.voronav && window.voronav.ready, null, { timeout: 20000 });
    const m = await mapStats();
    check(m.nonBackground > 0.3 * m.pixels, `a map-only recording is drawn (${m.nonBackground} px)`);
    await page.click("#play");
    await page.waitForTimeout(200);
    const st = await page.evaluate(() => window.voronav.state());
    check(!st.playing && st.time === 0 && st.end === 0, "play on a recording without time stops at once");
  }

  // Many robots: distinct colours, a short searchable list, the map revealed over time, a tree
  // that appears when it is built.
  if (manyPath) {
    await page.goto(pathToFileURL(path.resolve(manyPath)).href);
    await page.waitForFunction(() => window.voronav && window.voronav.ready, null, { timeout: 20000 });
    const cols = await page.evaluate(() => window.voronav.robotColors());
    check(new Set(cols).size === cols.length && cols.length === 60, `60 robots get ${new Set(cols).size} distinct colours`);
    const listed = await page.evaluate(() => window.voronav.listedRobots());
    check(listed.length > 0 && listed.length <= 30, `the robot list shows ${listed.length} rows, not 60`);
    // A bar per robot: the category labels are thinned so that none overlaps another.
    await page.locator("canvas.plot").first().scrollIntoViewIfNeeded();
    await page.waitForFunction(() => { const c = document.querySelector("canvas.plot"); return c && c.dataset.labels; }, null, { timeout: 10000 });
    const labels = JSON.parse(await page.$eval("canvas.plot", (c) => c.dataset.labels));
    const overlapping = labels.filter((b, i) => i > 0 && b[0] < labels[i - 1][1]).length;
    check(labels.length >= 2 && labels.length < 60 && overlapping === 0,
          `60 bar labels: ${labels.length} drawn, ${overlapping} overlapping`);
    await page.fill("#robotfind", "42");
    const found = await page.evaluate(() => window.voronav.listedRobots());
    check(found.length >= 1 && found[0] === 42, "typing an id finds the robot: " + found.join(","));
    await page.evaluate(() => window.voronav.setTime(1.0));
    const early = await page.evaluate(() => window.voronav.knownCells());
    await page.evaluate(() => window.voronav.setTime(window.voronav.state().end));
    const late = await page.evaluate(() => window.voronav.knownCells());
    check(early > 0 && early < late, `explored area grows: ${early} cells known at t = 1 s, ${late} at the end`);
    await page.evaluate(() => window.voronav.setTime(1.0));
    check((await page.evaluate(() => window.voronav.knownCells())) === early, "seeking back hides the later cells again");
    const treeDiff = async (t) => {
      await page.evaluate((x) => window.voronav.setTime(x), t);
      await page.evaluate(() => window.voronav.setLayer("graph:0", true));
      await snap("tree_on");
      await page.evaluate(() => window.voronav.setLayer("graph:0", false));
      await snap("tree_off");
      await page.evaluate(() => window.voronav.setLayer("graph:0", true));
      return diff("tree_on", "tree_off");
    };
    // Dense events: 40 requests 0.1 s apart (3 px on the track) share one mark (with its count)
    // and one list row.
    const evs = await page.evaluate(() => window.voronav.events());
    const dense = evs.filter((e) => e.kind === "blocked");
    const evMarks = await page.evaluate(() => window.voronav.eventMarks());
    check(dense.length === 40 && evMarks.reduce((a, m) => a + m.count, 0) === evs.length &&
          evMarks.length === 2 && evMarks.some((m) => m.count === 40 && m.kinds === "blocked"),
          `${evs.length} events on ${evMarks.length} track marks (counts ${evMarks.map((m) => m.count).join(",")})`);
    const evRows = await page.evaluate(() => window.voronav.eventRows());
    check(evRows.length === 2 && evRows.some((r) => r.count === 40 && r.text.includes("(x40)")),
          "the list folds the 40 repeats into one row: " + evRows.map((r) => r.text).join(" | "));
    check((await treeDiff(4.9)) === 0, "the tree is not drawn before it is built (t = 4.9 s)");
    check((await treeDiff(5.0)) > 20, "the tree is drawn once it is built (t = 5 s)");
  }

  check(errors.length === 0, "no console errors or warnings" + (errors.length ? ": " + errors.join(" | ") : ""));
  check(requests.length === 0, "no network requests" + (requests.length ? ": " + requests.join(", ") : ""));
} catch (e) {
  console.error("FAIL exception: " + (e && e.stack ? e.stack : e));
  failures++;
} finally {
  await close();
}
console.log(failures ? `${failures} check(s) failed` : "all browser checks passed");
process.exit(failures ? 1 : 0);
