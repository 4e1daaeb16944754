// Runs axe-core on HTML pages in headless Chromium (playwright-core, Debian's chromium) at a
// 1280-px and a 390-px window, two pages at a time, and prints one JSON line per page and
// width: {"page", "width", "violations": [{"id", "impact", "nodes"}], "outside": [...],
// "scrolled": [...], "tables": [...]}: only the serious and critical violations; the elements
// that reach past the window's right edge with no scrolling box around them (`outside`), the
// boxes that scroll sideways because their content is wider (`scrolled`, e.g. a table wider
// than its column), and the tables wider than the box that holds them (`tables`).
// Usage: node run.mjs CHROMIUM NODE_MODULES PAGE...
// Called by tests/browser.rs; .ci/run installs axe-core and playwright-core with npm.
import { createRequire } from "node:module";
import path from "node:path";

const [chromium, modules, ...pages] = process.argv.slice(2);
const require = createRequire(path.join(modules, "noop.js"));
const { chromium: launcher } = require("playwright-core");
const fs = require("fs");
const axeSource = fs.readFileSync(require.resolve("axe-core/axe.min.js"), "utf8");

// One job per page and width, the largest files first so that the two workers finish
// together; each worker has its own tab (browser context) per width, and the results are
// printed in the order page by page, 1280 px first, whatever order they finished in.
const widths = [[1280, 1000], [390, 844]];
const size = (file) => fs.statSync(file).size;
const jobs = pages
  .flatMap((file, p) => widths.map((viewport, w) => ({ file, p, w, viewport })))
  .sort((a, b) => size(b.file) - size(a.file) || a.p - b.p || a.w - b.w);
// Two pages checked at a time on this 2-core machine (each tab renders in its own process).
const WORKERS = 2;
const results = [];

const browser = await launcher.launch({ executablePath: chromium, args: ["--no-sandbox"] });
try {
  await Promise.all(Array.from({ length: WORKERS }, async () => {
    const tabs = new Map();
    try {
      for (let job = jobs.shift(); job; job = jobs.shift()) {
        const [width, height] = job.viewport;
        if (!tabs.has(width)) tabs.set(width, await browser.newPage({ viewport: { width, height } }));
        const line = await check(tabs.get(width), job.file, width);
        results.push({ ...job, line });
      }
    } finally {
      for (const tab of tabs.values()) await tab.close();
    }
  }));
} finally {
  await browser.close();
}
results.sort((a, b) => a.w - b.w || a.p - b.p);
for (const r of results) console.log(r.line);

// axe and the layout measures on `file` in `page` (a tab `width` px wide): one JSON line.
async function check(page, file, width) {
  await page.goto("file://" + path.resolve(file));
  await page.addScriptTag({ content: axeSource });
  // Every rule runs; only the violations are read, so axe skips the node lists and CSS
  // selectors of the passes and of what needs review (the costly part of its report).
  const options = { resultTypes: ["violations"], selectors: false };
  const result = await page.evaluate(async (o) => await window.axe.run(document, o), options);
  const violations = result.violations
    .filter((v) => v.impact === "serious" || v.impact === "critical")
    .map((v) => ({ id: v.id, impact: v.impact, nodes: v.nodes.length }));
  const { outside, scrolled, tables } = await page.evaluate(() => {
    const vw = document.documentElement.clientWidth;
    const name = (el) => el.tagName.toLowerCase() + (el.id ? "#" + el.id : "") +
      (el.className && typeof el.className === "string" ? "." + el.className.trim().split(/\s+/).join(".") : "");
    const clips = (el) => ["auto", "scroll", "hidden", "clip"].includes(getComputedStyle(el).overflowX);
    const outside = [];
    const scrolled = [];
    for (const el of document.body.querySelectorAll("*")) {
      const style = getComputedStyle(el);
      if (style.display === "none" || style.visibility === "hidden") continue;
      if (["auto", "scroll"].includes(style.overflowX) && el.scrollWidth > el.clientWidth + 1) {
        scrolled.push(`${name(el)} ${el.scrollWidth} > ${el.clientWidth}`);
      }
      const right = el.getBoundingClientRect().right;
      if (right > vw + 1) {
        let a = el.parentElement;
        while (a && a !== document.body && !clips(a)) a = a.parentElement;
        if (!a || a === document.body) outside.push(`${name(el)} right ${Math.round(right)} > ${vw}`);
      }
    }
    const tables = [...document.querySelectorAll("table")]
      .filter((t) => getComputedStyle(t).display !== "none" && t.offsetWidth > t.parentElement.clientWidth + 1)
      .map((t) => `${name(t)} ${t.offsetWidth} > ${t.parentElement.clientWidth}`);
    return { outside: outside.slice(0, 5), scrolled: scrolled.slice(0, 5), tables: tables.slice(0, 5) };
  });
  const where = path.relative(process.cwd(), file);
  return JSON.stringify({ page: where, width, violations, outside, scrolled, tables });
}
