// Drives the explorer page in headless Chromium (playwright-core, Debian's chromium) and prints
// one JSON object: the parameter sets it visited with the page's evaluation of each (the Rust
// test compares them with `stickslip eval … --json`), timings, requests, console errors and the
// serious or critical axe violations. Usage:
//   node run.mjs CHROMIUM NODE_MODULES PAGE [SCREENSHOT_DIR]
// Called by tests/explorer.rs.
import { createRequire } from "node:module";
import path from "node:path";

const [chromium, modules, file, shots] = process.argv.slice(2);
const require = createRequire(path.join(path.resolve(modules), "noop.js"));
const { chromium: launcher } = require("playwright-core");
const axeSource = require("fs").readFileSync(require.resolve("axe-core/axe.min.js"), "utf8");

const out = { visited: [], requests: [], errors: [], checks: {}, timings: {} };
const browser = await launcher.launch({ executablePath: chromium, args: ["--no-sandbox"] });
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 1000 } });
  page.on("request", (r) => out.requests.push(r.url().slice(0, 60)));
  page.on("console", (m) => { if (m.type() === "error") out.errors.push(m.text()); });
  page.on("pageerror", (e) => out.errors.push(String(e)));
  const probe = () => page.evaluate(() => {
    const p = window.stickslipExplorer;
    return { evaluation: p.evaluation, request: p.request, curves: p.curves, error: p.error,
      mapCells: p.mapCells, table: document.querySelectorAll("#check-rows tr").length,
      greyed: document.querySelectorAll("#check-rows tr.na").length,
      regime: document.getElementById("regime").textContent,
      path: document.querySelector("#plot-x path") ? document.querySelector("#plot-x path").getAttribute("d").length : 0 };
  });
  const visit = async (what) => { const p = await probe(); out.visited.push({ what, request: p.request, evaluation: p.evaluation }); return p; };
  // No time limits (timeout 0): a loaded machine is slow, not wrong; a page that never gets
  // there leaves the test running, which shows.
  const mapDone = async (before) => page.waitForFunction((n) => window.stickslipExplorer.mapCells > n, before, { timeout: 0 });

  await page.goto("file://" + path.resolve(file));
  await page.waitForFunction(() => window.stickslipExplorer && window.stickslipExplorer.ready, null, { timeout: 0 });
  out.timings.firstRender = await page.evaluate(() => window.stickslipExplorer.timings.firstRender);
  const first = await visit("pulled mass, defaults");
  out.checks.firstRegime = first.regime;
  out.checks.firstTable = first.table;
  await mapDone(0);

  // Keyboard: the μd slider, five steps right.
  await page.focus("#s-mu_d");
  for (let i = 0; i < 5; i++) await page.keyboard.press("ArrowRight");
  const keyed = await visit("pulled mass, μd moved by keyboard");
  out.checks.keyboardChanged = keyed.evaluation !== first.evaluation && keyed.path > 0;

  // The pulled mass's apparatus as drawn: the sizes of its block, hanging mass and spring.
  out.checks.pulledApparatus = await page.evaluate(() => {
    const size = (sel) => { const r = document.querySelector(`#apparatus ${sel}`); return [Number(r.getAttribute("width")), Number(r.getAttribute("height"))]; };
    const pts = document.querySelector("#apparatus polyline.spring").getAttribute("points").trim().split(" ").map((p) => p.split(",").map(Number));
    return { block: size("rect.block"), hanging: size("rect.hanging"), springPoints: pts.length,
      springHalf: Math.max(...pts.map(([x]) => Math.abs(x - pts[0][0]))) };
  });
  // Every element of the plots, the apparatus, the regime, the table and the map's legend,
  // marked before the drag below: a slider move must move them, not make new ones.
  await page.evaluate(() => {
    window.marked = new WeakSet();
    for (const id of ["plot-x", "plot-v", "apparatus", "regime", "check-rows", "map-legend"]) {
      for (const e of document.getElementById(id).querySelectorAll("*")) window.marked.add(e);
    }
  });
  const rowsBefore = await page.evaluate(() => document.querySelectorAll("#check-rows tr").length);

  // A slider dragged: 30 moves of F, each timed from the input event to the page laid out
  // again (engine, both laws' curves, regime, apparatus, table; style and layout), and to the
  // next frame (which also waits for the display's refresh).
  const drag = await page.evaluate(async () => {
    const slider = document.getElementById("s-force");
    const layout = [];
    const frames = [];
    for (let i = 0; i < 30; i++) {
      slider.value = String(300 + 10 * i);
      const t0 = performance.now();
      slider.dispatchEvent(new Event("input", { bubbles: true }));
      void document.body.offsetHeight;
      layout.push(performance.now() - t0);
      await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      frames.push(performance.now() - t0);
    }
    return { layout, frames };
  });
  out.timings.layout = drag.layout;
  out.timings.frames = drag.frames;
  out.timings.redraws = await page.evaluate(() => window.stickslipExplorer.timings.redraws.slice(-30));
  await mapDone(await page.evaluate(() => window.stickslipExplorer.mapCells));
  out.checks.newNodes = await page.evaluate(() => {
    const made = [];
    for (const id of ["plot-x", "plot-v", "apparatus", "regime", "check-rows", "map-legend"]) {
      for (const e of document.getElementById(id).querySelectorAll("*")) if (!window.marked.has(e)) made.push(`${id} ${e.tagName}`);
    }
    return made;
  });
  out.checks.rowsKept = rowsBefore === await page.evaluate(() => document.querySelectorAll("#check-rows tr").length);
  const dragged = await visit("pulled mass, F dragged");
  out.checks.dragChanged = dragged.evaluation !== keyed.evaluation
    && JSON.stringify(dragged.curves) !== JSON.stringify(keyed.curves);

  // A click on the map sets (μd, μs).
  let maps = await page.evaluate(() => window.stickslipExplorer.mapCells);
  await mapDone(maps - 1);
  const box = await page.locator("#map").boundingBox();
  await page.locator("#map").click({ position: { x: box.width * 0.2, y: box.height * 0.3 } });
  const clicked = await visit("pulled mass, map clicked");
  out.checks.mapChanged = clicked.request.params.mu_d !== dragged.request.params.mu_d
    && clicked.request.params.mu_s !== dragged.request.params.mu_s;
  maps = await page.evaluate(() => window.stickslipExplorer.mapCells);
  // The map by keyboard: focus, move, Enter.
  await page.focus("#map");
  await page.keyboard.press("ArrowUp");
  await page.keyboard.press("ArrowRight");
  await page.keyboard.press("Enter");
  const mapKeyed = await visit("pulled mass, map by keyboard");
  out.checks.mapKeyboard = mapKeyed.evaluation !== clicked.evaluation;
  // The keyboard cursor starts at the current set, not at the map's centre: after the
  // defaults, Enter alone moves the set only to the centre of its own cell.
  await page.click("#reset");
  const reset = await visit("pulled mass, defaults again");
  await page.focus("#map");
  await page.keyboard.press("Enter");
  const entered = await visit("pulled mass, map Enter at once");
  const near = (k) => Math.abs(entered.request.params[k] - reset.request.params[k]) <= 0.05 * Math.abs(reset.request.params[k]);
  out.checks.mapCursorAtSet = near("mu_s") && near("mu_d");

  // An invalid value typed in: the one-line error, no console error.
  await page.fill("#n-mu_d", "5");
  await page.press("#n-mu_d", "Enter");
  out.checks.invalidMessage = (await probe()).error;
  await page.click("#reset");

  // A preset, then the woodpecker.
  await mapDone(maps);
  if (shots) await page.screenshot({ path: path.join(shots, "explorer-pulled-mass.png"), fullPage: true });
  await page.check("#model-woodpecker");
  const wood = await visit("woodpecker, defaults");
  out.checks.woodRegime = wood.regime;
  out.checks.woodTable = wood.table;
  out.checks.woodGreyed = wood.greyed;
  // The woodpecker's apparatus as drawn: its layout (scale, l, h, tilt) and, measured on the
  // drawing, the contacts' height difference and the spring's distance from the pole's axis.
  out.checks.woodApparatus = await page.evaluate(() => {
    const num = (sel, a) => Number(document.querySelector(`#apparatus ${sel}`).getAttribute(a));
    const circles = [...document.querySelectorAll("#apparatus > circle")].map((c) => Number(c.getAttribute("cy")));
    const pole = num("rect", "x") + num("rect", "width") / 2;
    const spring = Number(document.querySelector("#apparatus polyline.spring").getAttribute("points").split(",")[0]);
    return { layout: window.stickslipExplorer.apparatus, contacts: Math.abs(circles[1] - circles[0]), arm: spring - pole };
  });
  await page.selectOption("#c-counterpart", "extremes");
  await page.focus("#s-z0");
  for (let i = 0; i < 20; i++) await page.keyboard.press("ArrowLeft");
  const moved = await visit("woodpecker, counterpart and z0 changed");
  out.checks.woodChanged = moved.evaluation !== wood.evaluation;
  await page.selectOption("#preset", "fig26-tracked-toy");
  await visit("woodpecker, preset fig26-tracked-toy");
  maps = await page.evaluate(() => window.stickslipExplorer.mapCells);
  await mapDone(maps);
  if (shots) await page.screenshot({ path: path.join(shots, "explorer-woodpecker.png"), fullPage: true });

  // The animation: play until the time shown moves, pause.
  const shown = () => document.getElementById("time-out").textContent;
  await page.click("#play");
  await page.waitForFunction(() => document.getElementById("time-out").textContent !== "t = 0 s", null, { timeout: 0 });
  out.checks.animationTime = await page.evaluate(() => document.getElementById("time-out").textContent);
  if (shots) await page.locator("#motion").screenshot({ path: path.join(shots, "explorer-animation.png") });
  await page.click("#play");

  // Reduced motion: no smooth animation, the time moves in steps of an eighth of a period.
  // Played until the time shown has moved, then paused: the steps taken are a whole number
  // whatever the machine's load.
  await page.emulateMedia({ reducedMotion: "reduce" });
  const before = await page.evaluate(shown);
  await page.click("#play");
  await page.waitForFunction((b) => document.getElementById("time-out").textContent !== b, before, { timeout: 0 });
  await page.click("#play");
  const after = await page.evaluate(shown);
  const period = JSON.parse(await page.evaluate(() => window.stickslipExplorer.evaluation)).params.T;
  const seconds = (s) => Number(s.replace(/^t = /, "").replace(/ s$/, ""));
  out.checks.reducedMotionStep = (seconds(after) - seconds(before)) / (period / 8);

  // The belt: a block on a moving belt held by a spring to a wall, moved by the computed
  // motion (the time slider set to thousandths of the shown periods).
  await page.emulateMedia({ reducedMotion: "no-preference" });
  await page.check("#model-belt");
  const belt = await visit("belt, defaults");
  out.checks.beltRegime = belt.regime;
  out.checks.beltTable = belt.table;
  out.checks.beltLaws = await page.evaluate(() => [...document.querySelectorAll("#laws label")].filter((l) => !l.hidden).map((l) => l.textContent.trim()));
  const beltAt = (value) => page.evaluate((v) => {
    const time = document.getElementById("time");
    time.value = String(v);
    time.dispatchEvent(new Event("input", { bubbles: true }));
    const a = document.getElementById("apparatus");
    const num = (sel, attr) => Number(a.querySelector(sel).getAttribute(attr));
    return { ...window.stickslipExplorer.apparatus, blockX: num("rect.block", "x"),
      blockSize: [num("rect.block", "width"), num("rect.block", "height")],
      parts: ["rect.wall", "rect.belt", "polyline.spring", ".belt-marks line"].map((sel) => a.querySelectorAll(sel).length),
      fill: a.querySelector("rect.block").getAttribute("fill"), desc: a.querySelector("desc").textContent };
  }, value);
  out.checks.beltApparatus = [await beltAt(50), await beltAt(150), await beltAt(280)];
  if (shots) await page.locator("#motion").screenshot({ path: path.join(shots, "explorer-belt.png") });
  // The belt's map (its legend names the shares of the cycle stuck), once drawn.
  await page.waitForFunction(() => document.getElementById("map-status").textContent.includes("v_b from"), null, { timeout: 0 });
  out.checks.beltMap = await page.evaluate(() => document.getElementById("map-status").textContent);

  // Accessibility at desktop and phone width, light and dark; no sideways scrolling on a phone.
  out.axe = [];
  for (const [width, height, colorScheme] of [[1280, 1000, "light"], [390, 844, "light"], [390, 844, "dark"]]) {
    await page.setViewportSize({ width, height });
    await page.emulateMedia({ colorScheme });
    await page.addScriptTag({ content: axeSource });
    const result = await page.evaluate(async () => await window.axe.run(document));
    out.axe.push(...result.violations
      .filter((v) => v.impact === "serious" || v.impact === "critical")
      .map((v) => ({ id: v.id, impact: v.impact, width, colorScheme, nodes: v.nodes.map((n) => n.target.join(" ")).slice(0, 3) })));
    if (width < 500) out.checks.phoneOverflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    // On a phone a plot stays in view while the last slider is in view (and moved).
    if (width < 500) out.checks.phonePlotWithSlider = await page.evaluate(() => {
      const slider = [...document.querySelectorAll("#params input[type=range]")].pop();
      slider.scrollIntoView({ block: "end" });
      const inView = (r) => r.top >= -1 && r.bottom <= window.innerHeight + 1 && r.height > 0;
      return inView(slider.getBoundingClientRect()) && inView(document.getElementById("plot-x").getBoundingClientRect());
    });
    if (width < 500 && shots) await page.screenshot({ path: path.join(shots, `explorer-390-${colorScheme}.png`) });
  }
} finally {
  await browser.close();
}
console.log(JSON.stringify(out));
