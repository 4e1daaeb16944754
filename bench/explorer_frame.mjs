// Times the explorer page where a user waits (issue 31), in headless Chromium driven by
// playwright-core; prints one line per measure and a JSON summary. Not a test: the numbers
// depend on the machine and its load (note `uptime` with them).
//
//   node bench/explorer_frame.mjs CHROMIUM NODE_MODULES PAGE [MOVES]
//   e.g. cargo run --release -- explorer --out /tmp/x &&
//        node bench/explorer_frame.mjs /usr/bin/chromium target/axe/node_modules /tmp/x/explorer.html
//
// 1. A slider move (the pulled mass's F, dragged with the mouse, MOVES ≥ 50 steps, default 60):
//    from the input event (its timeStamp, when the browser received it) to the next animation
//    frame (requestAnimationFrame callback), and to the end of that frame (a message posted
//    from the callback runs after the frame's style, layout and paint); medians, maxima.
//    Mouse moves are delivered aligned with frames, as a user's are. The same for a bare
//    slider added to the page (no handler): the browser's own cost of a frame here.
// 2. The regime map: the woodpecker's harmonic-law map as the page computes it (two Web
//    Workers, a 40×40 pass then 400×400, one cell per pixel of the map), from the start of the
//    computation to its last cell, as the page reports it (stickslipExplorer.mapAt()), 3 runs.
import { createRequire } from "node:module";
import path from "node:path";

const [chromium, modules, file, movesArg] = process.argv.slice(2);
if (!chromium || !modules || !file) {
  console.error("usage: node bench/explorer_frame.mjs CHROMIUM NODE_MODULES PAGE [MOVES]");
  process.exit(2);
}
const moves = Number(movesArg || 60);
const require = createRequire(path.join(path.resolve(modules), "noop.js"));
const { chromium: launcher } = require("playwright-core");

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const max = (xs) => Math.max(...xs);
const summary = {};
const browser = await launcher.launch({ executablePath: chromium, args: ["--no-sandbox"] });
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 1000 } });
  await page.goto("file://" + path.resolve(file));
  await page.waitForFunction(() => window.stickslipExplorer && window.stickslipExplorer.ready, null, { timeout: 0 });
  await page.waitForFunction(() => window.stickslipExplorer.mapCells > 0, null, { timeout: 0 });

  // 1. Slider moves: the F slider, and for comparison a bare slider added to the page (no
  // handler: what the browser's frame costs by itself on this machine).
  await page.evaluate(() => {
    window.benchFrames = [];
    const bare = document.createElement("input");
    Object.assign(bare, { type: "range", id: "bench-bare", min: 0, max: 1000, value: 300 });
    bare.setAttribute("aria-label", "bench");
    document.getElementById("controls").prepend(bare);
    for (const slider of [document.getElementById("s-force"), bare]) slider.addEventListener("input", (ev) => {
      const start = performance.now();
      const received = ev.timeStamp;
      requestAnimationFrame(() => {
        const frame = performance.now();
        const channel = new MessageChannel();
        channel.port1.onmessage = () => window.benchFrames.push({
          toFrame: frame - received, toFrameEnd: performance.now() - received, handlerToFrame: frame - start });
        channel.port2.postMessage(0);
      });
    }, { capture: true });
  });
  const drag = async (selector) => {
    await page.evaluate(() => { window.benchFrames = []; });
    const box = await page.locator(selector).boundingBox();
    const y = box.y + box.height / 2;
    let x = box.x + box.width * 0.3;
    await page.mouse.move(x, y);
    await page.mouse.down();
    const step = (box.width * 0.4) / moves;
    for (let i = 0; i < moves; i++) {
      x += step;
      const before = await page.evaluate(() => window.benchFrames.length);
      await page.mouse.move(x, y);
      await page.waitForFunction((n) => window.benchFrames.length > n, before, { timeout: 0 });
    }
    await page.mouse.up();
    return page.evaluate(() => window.benchFrames);
  };
  const bareFrames = await drag("#bench-bare");
  const frames = await drag("#s-force");
  const redraws = await page.evaluate((n) => window.stickslipExplorer.timings.redraws.slice(-n), frames.length);
  const pick = (k, list = frames) => list.map((f) => f[k]);
  summary.bare = { moves: bareFrames.length, toFrameMedianMs: median(pick("toFrame", bareFrames)),
    toFrameEndMedianMs: median(pick("toFrameEnd", bareFrames)) };
  console.log(`bare slider (${bareFrames.length} moves): input event to next frame ${summary.bare.toFrameMedianMs.toFixed(1)} ms median, `
    + `to the frame's end ${summary.bare.toFrameEndMedianMs.toFixed(1)} ms median`);
  summary.slider = {
    moves: frames.length,
    toFrameMedianMs: median(pick("toFrame")), toFrameMaxMs: max(pick("toFrame")),
    toFrameEndMedianMs: median(pick("toFrameEnd")), toFrameEndMaxMs: max(pick("toFrameEnd")),
    scriptMedianMs: median(redraws), scriptMaxMs: max(redraws),
  };
  console.log(`slider move (${frames.length} moves): input event to next frame ${summary.slider.toFrameMedianMs.toFixed(1)} ms median `
    + `(${summary.slider.toFrameMaxMs.toFixed(1)} max), to the frame's end ${summary.slider.toFrameEndMedianMs.toFixed(1)} ms median; `
    + `page script ${summary.slider.scriptMedianMs.toFixed(1)} ms median`);

  // 2. The woodpecker's 400×400 map, harmonic law (pages before the workers have no mapAt).
  const sized = await page.evaluate(() => typeof window.stickslipExplorer.mapAt === "function");
  if (sized) {
    await page.check("#model-woodpecker");
    await page.check("#law-harmonic");
    const runs = [];
    for (let i = 0; i < 3; i++) {
      runs.push(await page.evaluate(async () => await window.stickslipExplorer.mapAt()));
    }
    summary.map = { cells: 400, law: "harmonic", model: "woodpecker", runsMs: runs, medianMs: median(runs) };
    console.log(`woodpecker map, harmonic law, 400×400 cells: ${runs.map((r) => r.toFixed(0)).join(", ")} ms (median ${median(runs).toFixed(0)} ms)`);
  } else {
    console.log("this page has no stickslipExplorer.mapAt: map not measured");
  }
} finally {
  await browser.close();
}
console.log(JSON.stringify(summary));
