// Runs axe-core on HTML pages in headless Chromium (playwright-core, Debian's chromium) and
// prints one JSON line per page: {"page", "violations": [{"id", "impact", "nodes"}]}, only the
// serious and critical ones. Usage: node run.mjs CHROMIUM NODE_MODULES PAGE...
// Called by tests/browser.rs; .ci/run installs axe-core and playwright-core with npm.
import { createRequire } from "node:module";
import path from "node:path";

const [chromium, modules, ...pages] = process.argv.slice(2);
const require = createRequire(path.join(modules, "noop.js"));
const { chromium: launcher } = require("playwright-core");
const axeSource = require("fs").readFileSync(require.resolve("axe-core/axe.min.js"), "utf8");

const browser = await launcher.launch({ executablePath: chromium, args: ["--no-sandbox"] });
try {
  for (const [width, height] of [[1200, 1600], [390, 844]]) {
    const page = await browser.newPage({ viewport: { width, height } });
    for (const file of pages) {
      await page.goto("file://" + path.resolve(file));
      await page.addScriptTag({ content: axeSource });
      const result = await page.evaluate(async () => await window.axe.run(document));
      const violations = result.violations
        .filter((v) => v.impact === "serious" || v.impact === "critical")
        .map((v) => ({ id: v.id, impact: v.impact, nodes: v.nodes.length }));
      console.log(JSON.stringify({ page: path.basename(file), width, violations }));
    }
    await page.close();
  }
} finally {
  await browser.close();
}
