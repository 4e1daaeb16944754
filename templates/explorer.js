// The explorer page's script (stickslip, src/report/explorer.rs embeds it). It lays out the
// controls from the page data (the Rust registry, serialised), sends each parameter set to the
// engine (the crate compiled to wasm32, embedded in base64; ABI in src/wasm.rs) and draws what
// comes back: it computes no physics itself. Plain DOM and SVG, no framework, no network.
"use strict";
(() => {
  const DATA = JSON.parse(document.getElementById("explorer-data").textContent);
  const $ = (id) => document.getElementById(id);
  // The SVG namespace, read from the page rather than written here.
  const SVG = document.getElementById("plot-x").namespaceURI;
  const encoder = new TextEncoder();
  const decoder = new TextDecoder();
  const reducedMotion = window.matchMedia("(prefers-reduced-motion: reduce)");

  // What the tests read (tests/explorer.rs): the last evaluation as the engine wrote it, and
  // the timings of the first render and of every redraw (ms).
  const probe = { ready: false, evaluation: "", extras: null, request: null, curves: [],
    error: "", timings: { firstRender: null, redraws: [] }, mapCells: 0 };
  window.stickslipExplorer = probe;

  // ---------------------------------------------------------------------------------------
  // The engine

  let engine = null;
  let compiled = null;

  async function startEngine() {
    const text = $("explorer-engine").textContent.trim();
    const binary = atob(text);
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
    const { module, instance } = await WebAssembly.instantiate(bytes, {});
    compiled = module;
    engine = instance.exports;
  }

  /** Calls export `fn` with `request` as JSON; returns {ok, text, data}. An engine that traps
   *  (a bug: it refuses bad input with a message) is started afresh and the call refused. */
  function call(fn, request) {
    try {
      return callEngine(fn, request);
    } catch (e) {
      engine = new WebAssembly.Instance(compiled, {}).exports;
      return { ok: false, text: `the engine failed on these parameters (${e.message})`, data: new Float64Array(0) };
    }
  }

  function callEngine(fn, request) {
    const bytes = encoder.encode(JSON.stringify(request));
    const ptr = engine.alloc(bytes.length);
    new Uint8Array(engine.memory.buffer, ptr, bytes.length).set(bytes);
    const status = engine[fn](ptr, bytes.length);
    engine.free(ptr, bytes.length);
    const text = decoder.decode(new Uint8Array(engine.memory.buffer, engine.text_ptr(), engine.text_len()));
    const data = new Float64Array(engine.memory.buffer, engine.data_ptr(), engine.data_len()).slice();
    return { ok: status === 0, text, data };
  }

  // ---------------------------------------------------------------------------------------
  // State

  const models = Object.fromEntries(DATA.models.map((m) => [m.id, m]));
  const sets = {};
  for (const m of DATA.models) sets[m.id] = defaults(m);
  const state = { model: DATA.models[0].id, law: "harmonic", time: 0, playing: false,
    speed: 0.1, mapCursor: null };
  let view = null; // the last good evaluation and curves

  function defaults(m) {
    const values = {};
    for (const p of m.params) values[p.key] = p.default === null ? null : toSi(p.default, p);
    const choices = {};
    for (const c of m.choices) choices[c.key] = c.default;
    return { values, choices };
  }

  const model = () => models[state.model];
  const current = () => sets[state.model];

  function request() {
    const params = {};
    for (const [k, v] of Object.entries(current().values)) if (v !== null) params[k] = v;
    return { model: state.model, params, choices: { ...current().choices } };
  }

  // ---------------------------------------------------------------------------------------
  // Numbers

  /** A number for people: 6 significant digits, scientific outside [1e-3, 1e6). */
  function fmt(x, digits = 6) {
    if (typeof x !== "number") return x === null || x === undefined ? "—" : String(x);
    if (x === 0) return "0";
    const a = Math.abs(x);
    if (a >= 1e-3 && a < 1e6) return String(Number(x.toPrecision(digits)));
    const [m, e] = x.toExponential(digits - 1).split("e");
    return `${Number(m)}e${Number(e)}`;
  }

  /** A shown value in SI units, without the float noise of the unit's division (2.708 mm is
   *  0.002708 m, not 0.0027080000000000003): 15 significant digits, the page's value and the
   *  one its `stickslip eval` line prints. */
  function toSi(x, p) { return Number((x / p.factor).toPrecision(15)); }

  /** Rounds a slider's value to 4 significant digits (the value sent and shown). */
  const round4 = (x) => Number(x.toPrecision(4));

  function toPosition(p, display) {
    const steps = DATA.slider_steps;
    const f = p.log ? Math.log(display / p.min) / Math.log(p.max / p.min)
      : (display - p.min) / (p.max - p.min);
    return Math.round(Math.min(1, Math.max(0, Number.isFinite(f) ? f : 0)) * steps);
  }

  function fromPosition(p, pos) {
    const f = pos / DATA.slider_steps;
    return round4(p.log ? p.min * Math.pow(p.max / p.min, f) : p.min + (p.max - p.min) * f);
  }

  const unitText = (u) => (u ? ` ${u}` : "");

  // ---------------------------------------------------------------------------------------
  // Controls, built from the registry

  function el(tag, attrs = {}, text) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  function buildSwitches() {
    const box = $("models");
    for (const m of DATA.models) {
      const id = `model-${m.id}`;
      const input = el("input", { type: "radio", name: "model", id, value: m.id });
      input.addEventListener("change", () => { state.model = m.id; rebuild(); });
      const label = el("label", { for: id });
      label.append(input, ` ${m.name}`);
      box.append(label);
    }
    for (const law of DATA.laws) {
      const id = `law-${law.id}`;
      const input = el("input", { type: "radio", name: "law", id, value: law.id });
      input.checked = law.id === state.law;
      input.addEventListener("change", () => { state.law = law.id; drawApparatus(); scheduleMap(); });
      const label = el("label", { for: id });
      label.append(input, ` ${law.label}`);
      $("laws").append(label);
    }
    const preset = $("preset");
    preset.append(el("option", { value: "" }, "— choose a figure of the paper —"));
    for (const m of DATA.models) {
      const group = el("optgroup", { label: m.name });
      DATA.presets.filter((p) => p.model === m.id)
        .forEach((p) => group.append(el("option", { value: p.id }, p.title)));
      preset.append(group);
    }
    preset.addEventListener("change", () => { if (applyPreset(preset.value)) rebuild(); });
    $("reset").addEventListener("click", () => {
      sets[state.model] = defaults(model());
      rebuild();
    });
  }

  /** Selects the built-in scene `id` as the current set (false when there is no such scene). */
  function applyPreset(id) {
    const p = DATA.presets.find((q) => q.id === id);
    if (!p) return false;
    state.model = p.model;
    const set = defaults(models[p.model]);
    Object.assign(set.values, p.params);
    Object.assign(set.choices, p.choices);
    sets[p.model] = set;
    $("preset").value = id;
    return true;
  }

  function buildParams() {
    const m = model();
    $(`model-${m.id}`).checked = true;
    const box = $("params");
    box.replaceChildren();
    for (const p of m.params) {
      const div = el("div", { class: "param", id: `param-${p.key}` });
      const sid = `s-${p.key}`;
      const nid = `n-${p.key}`;
      const hid = `h-${p.key}`;
      const name = el("label", { class: "name", for: sid }, `${p.words}${p.unit ? ` (${p.unit})` : ""}`);
      const slider = el("input", { type: "range", id: sid, min: "0", max: String(DATA.slider_steps),
        step: "1", "aria-describedby": hid });
      const number = el("input", { type: "number", id: nid, step: "any",
        "aria-label": `${p.words}, value${p.unit ? ` in ${p.unit}` : ""}`, "aria-describedby": hid });
      const row = el("div", { class: "row" });
      row.append(slider, number, el("span", { "aria-hidden": "true" }, p.unit));
      const paper = p.default === null ? p.unset : fmt(p.default) + unitText(p.unit);
      const hint = el("div", { class: "hint", id: hid },
        `slider ${fmt(p.min)} to ${fmt(p.max)}${unitText(p.unit)}${p.log ? " (logarithmic)" : ""}; paper: ${paper}`);
      div.append(name, row, hint);
      if (p.default === null) {
        const cid = `u-${p.key}`;
        const check = el("input", { type: "checkbox", id: cid });
        check.addEventListener("change", () => {
          current().values[p.key] = check.checked ? null : toSi(fromPosition(p, Number(slider.value)), p);
          syncParam(p);
          update();
        });
        const label = el("label", { for: cid });
        label.append(check, ` ${p.symbol} = ${p.unset} (the paper's)`);
        div.append(label);
      }
      slider.addEventListener("input", () => {
        current().values[p.key] = toSi(fromPosition(p, Number(slider.value)), p);
        syncParam(p, "slider");
        update();
      });
      number.addEventListener("change", () => {
        const v = Number(number.value);
        if (number.value.trim() === "" || !Number.isFinite(v)) { syncParam(p); return; }
        current().values[p.key] = toSi(v, p);
        syncParam(p, "number");
        update();
      });
      box.append(div);
      syncParam(p);
    }
    const choices = $("choices");
    choices.replaceChildren();
    for (const c of m.choices) {
      const id = `c-${c.key}`;
      const [head, rest] = c.help.split(/:\s*/, 2);
      const p = el("p");
      const select = el("select", { id, "aria-describedby": `${id}-hint` });
      c.values.forEach((v) => select.append(el("option", { value: v }, v)));
      select.value = current().choices[c.key];
      select.addEventListener("change", () => { current().choices[c.key] = select.value; update(); });
      p.append(el("label", { for: id }, head), el("br"), select,
        el("span", { class: "hint muted", id: `${id}-hint` }, rest ? ` ${rest}` : ""));
      choices.append(p);
    }
  }

  /** Shows the stored value of `p` on its slider and number box (except the one being used). */
  function syncParam(p, from) {
    const v = current().values[p.key];
    const div = $(`param-${p.key}`);
    const slider = $(`s-${p.key}`);
    const number = $(`n-${p.key}`);
    const unset = v === null;
    div.classList.toggle("unset", unset);
    slider.disabled = unset;
    number.disabled = unset;
    const check = $(`u-${p.key}`);
    if (check) check.checked = unset;
    const display = unset ? null : v * p.factor;
    if (from !== "slider") slider.value = unset ? String(DATA.slider_steps / 2) : String(toPosition(p, display));
    if (from !== "number") number.value = unset ? "" : String(round4(display));
    number.placeholder = unset ? p.unset : "";
    slider.setAttribute("aria-valuetext", unset ? p.unset : `${fmt(display)}${unitText(p.unit)}`);
  }

  function rebuild() {
    buildParams();
    state.mapCursor = null;
    update();
  }

  // ---------------------------------------------------------------------------------------
  // One parameter set: evaluate, then draw everything

  function update() {
    const started = performance.now();
    const req = request();
    probe.request = req;
    const out = call("explore", req);
    if (!out.ok) {
      probe.error = out.text;
      $("error").textContent = out.text;
      document.body.classList.add("invalid");
      return;
    }
    probe.error = "";
    $("error").textContent = "";
    document.body.classList.remove("invalid");
    const cut = out.text.indexOf("\0");
    const evaluationText = out.text.slice(0, cut);
    const evaluation = JSON.parse(evaluationText);
    const extras = JSON.parse(out.text.slice(cut + 1));
    view = { evaluation, extras, curves: splitCurves(out.data), period: evaluation.params.T };
    probe.evaluation = evaluationText;
    probe.extras = extras;
    probe.curves = [out.data[0], out.data[1], out.data.reduce((a, b) => a + b, 0)];
    drawPlots();
    drawRegime();
    drawApparatus();
    drawTable();
    probe.timings.redraws.push(performance.now() - started);
    scheduleMap();
  }

  /** The engine's curves as {law: [[t, x, v, apparatus] …]} (src/explore.rs). */
  function splitCurves(data) {
    const out = {};
    let at = 2;
    DATA.laws.forEach((law, i) => {
      const n = data[i];
      const points = [];
      for (let j = 0; j < n; j++, at += 4) points.push([data[at], data[at + 1], data[at + 2], data[at + 3]]);
      out[law.id] = points;
    });
    return out;
  }

  // ---------------------------------------------------------------------------------------
  // Plots of position and speed (the report's colours and dashes)

  const PLOT = { w: 640, h: 210, left: 64, right: 12, top: 10, bottom: 40 };

  function niceTicks(lo, hi, count) {
    const span = hi - lo || 1;
    const raw = span / count;
    const mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 2.5, 5, 10].map((s) => s * mag).find((s) => span / s <= count) || 10 * mag;
    const ticks = [];
    for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) ticks.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    return ticks;
  }

  function svgEl(tag, attrs, text) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  function drawPlot(svg, column, yLabel, scale) {
    const title = svg.querySelector("title");
    svg.replaceChildren(title);
    const end = DATA.shown * view.period;
    let lo = Infinity;
    let hi = -Infinity;
    for (const law of DATA.laws) for (const s of view.curves[law.id]) { lo = Math.min(lo, s[column] * scale); hi = Math.max(hi, s[column] * scale); }
    if (!(hi > lo)) { lo = Math.min(lo, 0) - 1; hi = Math.max(hi, 0) + 1; }
    const pad = 0.05 * (hi - lo);
    lo -= pad; hi += pad;
    const x0 = PLOT.left;
    const x1 = PLOT.w - PLOT.right;
    const y0 = PLOT.h - PLOT.bottom;
    const y1 = PLOT.top;
    const px = (t) => x0 + ((x1 - x0) * t) / end;
    const py = (v) => y0 + ((y1 - y0) * (v - lo)) / (hi - lo);
    svg.append(svgEl("rect", { x: 0, y: 0, width: PLOT.w, height: PLOT.h, fill: "#fff" }));
    const grid = svgEl("g", { stroke: "#e3e3e3", "stroke-width": 1 });
    const labels = svgEl("g", { "font-family": "DejaVu Sans, Helvetica, Arial, sans-serif", "font-size": 12, fill: "#000" });
    for (const t of niceTicks(0, end, 8)) {
      grid.append(svgEl("line", { x1: px(t), x2: px(t), y1: y0, y2: y1 }));
      labels.append(svgEl("text", { x: px(t), y: y0 + 16, "text-anchor": "middle" }, fmt(t, 3)));
    }
    for (const v of niceTicks(lo, hi, 5)) {
      grid.append(svgEl("line", { x1: x0, x2: x1, y1: py(v), y2: py(v) }));
      labels.append(svgEl("text", { x: x0 - 6, y: py(v) + 4, "text-anchor": "end" }, fmt(v, 3)));
    }
    labels.append(svgEl("text", { x: (x0 + x1) / 2, y: PLOT.h - 6, "text-anchor": "middle", "font-size": 13 }, "t (s)"));
    labels.append(svgEl("text", { x: 14, y: (y0 + y1) / 2, "text-anchor": "middle", "font-size": 13,
      transform: `rotate(-90 14 ${(y0 + y1) / 2})` }, yLabel));
    svg.append(grid, svgEl("rect", { x: x0, y: y1, width: x1 - x0, height: y0 - y1, fill: "none", stroke: "#000" }), labels);
    const legend = svgEl("g", { "font-family": "DejaVu Sans, Helvetica, Arial, sans-serif", "font-size": 12 });
    let ly = y1 + 16;
    // Harmonic (solid) first, as in the report's legends.
    for (const law of [...DATA.laws].reverse()) {
      const points = view.curves[law.id];
      if (!points.length) continue;
      let d = "";
      for (let i = 0; i < points.length; i++) d += `${i ? "L" : "M"}${px(points[i][0]).toFixed(1)} ${py(points[i][column] * scale).toFixed(1)}`;
      svg.append(svgEl("path", { d, fill: "none", stroke: law.color, "stroke-width": law.width,
        "stroke-dasharray": law.dash || "none", "stroke-linejoin": "round" }));
      legend.append(svgEl("line", { x1: x0 + 10, x2: x0 + 40, y1: ly - 4, y2: ly - 4, stroke: law.color,
        "stroke-width": law.width, "stroke-dasharray": law.dash || "none" }));
      legend.append(svgEl("text", { x: x0 + 46, y: ly }, law.label));
      ly += 16;
    }
    svg.append(legend);
    const cursor = svgEl("line", { class: "cursor", x1: px(state.time), x2: px(state.time), y1: y0, y2: y1,
      stroke: "#606060", "stroke-width": 1, "stroke-dasharray": "5,4" });
    svg.append(cursor);
    // A dot on each law's curve, moved with the animation's time.
    svg.dots = [...DATA.laws].reverse().filter((law) => view.curves[law.id].length).map((law) => {
      const dot = svgEl("circle", { r: 4.5, fill: law.color, stroke: "#fff", "stroke-width": 1.5 });
      svg.append(dot);
      return { dot, points: view.curves[law.id] };
    });
    svg.cursorX = px;
    svg.cursorY = (v) => py(v * scale);
    svg.column = column;
  }

  /** Column `column` of `points` at time t, between the nearest samples. */
  function valueAt(points, column, t) {
    let lo = 0;
    let hi = points.length - 1;
    while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (points[mid][0] <= t) lo = mid; else hi = mid; }
    const a = points[lo];
    const b = points[hi];
    const f = b[0] > a[0] ? Math.min(1, Math.max(0, (t - a[0]) / (b[0] - a[0]))) : 0;
    return a[column] + (b[column] - a[column]) * f;
  }

  function drawPlots() {
    const pos = model().position;
    drawPlot($("plot-x"), 1, `${pos} (mm)`, 1e3);
    drawPlot($("plot-v"), 2, "v (mm/s)", 1e3);
    const e = view.evaluation;
    $("plot-x-title").textContent = `Position ${pos} in mm against time over ${DATA.shown} periods, both force laws`;
    $("plot-v-title").textContent = `Speed in mm/s against time over ${DATA.shown} periods, both force laws`;
    $("plots-caption").textContent = `Exact integration from rest over ${DATA.shown} periods (T = ${fmt(e.params.T, 4)} s): `
      + `harmonic law (solid) against the linearized law (dashed)${view.curves.linear.length ? "" : "; the linearized law does not exist for these parameters"}. `
      + "The dashed vertical line and the dots follow the time of the animation.";
  }

  function moveCursors() {
    for (const id of ["plot-x", "plot-v"]) {
      const svg = $(id);
      const line = svg.querySelector("line.cursor");
      if (!line || !svg.cursorX) continue;
      const x = svg.cursorX(state.time);
      line.setAttribute("x1", x);
      line.setAttribute("x2", x);
      for (const { dot, points } of svg.dots) {
        dot.setAttribute("cx", x);
        dot.setAttribute("cy", svg.cursorY(valueAt(points, svg.column, state.time)));
      }
    }
  }

  // ---------------------------------------------------------------------------------------
  // The regime in words

  /** "1 slip", "2 slips". */
  function plural(n, one, many) { return `${n} ${n === 1 ? one : many}`; }

  function lawWords(summary) {
    if (!summary) return "does not exist for these parameters";
    const r = DATA.integration_regimes.find((q) => q.id === summary.regime);
    const counts = summary.slips_per_period + summary.sticks_per_period > 0
      ? [`${plural(summary.slips_per_period, "slip", "slips")} and ${plural(summary.sticks_per_period, "stick", "sticks")} per period`] : [];
    if (summary.immediate_slip) counts.push("slips at t = 0");
    const speed = summary.v_avg === null ? "no steady mean speed" : `mean speed ${fmt(summary.v_avg * 1e3, 4)} mm/s`;
    return `${r ? r.words : summary.regime}${counts.length ? ` (${counts.join("; ")})` : ""}; ${speed}`;
  }

  function drawRegime() {
    const e = view.evaluation;
    const c = view.extras.closed_form;
    const lines = [
      ["Closed forms (linearized law)", `${c.words}, because ${c.why}.`],
      ["Exact integration, linearized law", lawWords(e.linear)],
      ["Exact integration, harmonic law", lawWords(e.harmonic)],
    ];
    const box = $("regime");
    box.replaceChildren();
    for (const [law, text] of lines) {
      const p = el("p");
      p.append(el("span", { class: "law" }, `${law}: `), text);
      box.append(p);
    }
    // The live region says the regimes in words only, and only when they change, so that a
    // screen reader announces a new regime, not every step of a slider.
    const words = (s) => (s ? (DATA.integration_regimes.find((q) => q.id === s.regime) || { words: s.regime }).words : "none");
    const live = `Regime of the closed forms: ${c.words}. Linearized law: ${words(e.linear)}. Harmonic law: ${words(e.harmonic)}.`;
    if ($("regime-live").textContent !== live) $("regime-live").textContent = live;
  }

  // ---------------------------------------------------------------------------------------
  // Every closed form against the integration

  // A value of the table: a number formatted, a regime id in words (the report's words).
  function inWords(value) {
    if (typeof value !== "string") return fmt(value);
    const closed = view.extras.closed_form;
    if (value === closed.id) return closed.words;
    const r = DATA.integration_regimes.find((q) => q.id === value);
    return r ? r.words : value;
  }

  function drawTable() {
    const e = view.evaluation;
    const applies = Object.fromEntries(view.extras.applicability.map((a) => [a.quantity, a]));
    const checks = Object.fromEntries(e.checks.map((c) => [c.quantity, c]));
    const rows = $("check-rows");
    rows.replaceChildren();
    const row = (q, id, c) => {
      const a = applies[id];
      const na = a && !a.applies;
      const value = c ? c.closed_form : e.closed_form[id];
      const verdict = !c ? "—" : na ? "n/a" : c.pass === true ? "pass" : c.pass === false ? "FAIL" : "n/a";
      const cls = na ? "na" : !c ? "none" : c.pass === true ? "pass" : c.pass === false ? "fail" : "na";
      const tr = el("tr", { class: cls, "data-quantity": id });
      const cell = (text, extra = {}) => tr.append(el("td", extra, text));
      cell(q ? q.symbol : id, { title: q ? q.words : id });
      cell(q ? `${c ? c.equation : q.equation} ${q.tag}` : c.equation);
      cell(inWords(value), { class: "num", "data-exact": String(value) });
      cell(c ? inWords(c.numeric) : "—", { class: "num", "data-exact": c ? String(c.numeric) : "" });
      cell(q ? q.unit : "");
      cell(!c || c.rel_error === null ? "—" : c.rel_error.toExponential(1), { class: "num" });
      cell(verdict, { class: "verdict" });
      const notes = [na ? a.reason : "", c ? c.note || "" : "no counterpart in the integration"];
      cell(notes.filter(Boolean).join("; "), { class: "note" });
      rows.append(tr);
    };
    // Every closed form of the registry in its order, with its check where it has one (as the
    // report's verification table), then the checks of the periodic orbit.
    for (const q of model().quantities) {
      if (q.id in checks || q.id in e.closed_form) row(q, q.id, checks[q.id]);
    }
    const known = new Set(model().quantities.map((q) => q.id));
    for (const c of e.checks) if (!known.has(c.quantity)) row(null, c.quantity, c);
    $("periods").textContent = String(e.params.periods);
    $("json").textContent = probe.evaluation;
    const req = probe.request;
    const flags = Object.entries(req.params).map(([k, v]) => `--${k.replace(/_/g, "-")}=${v}`)
      .concat(Object.entries(req.choices).map(([k, v]) => `--${k}=${v}`));
    $("cli-line").textContent = `stickslip eval ${req.model} ${flags.join(" ")} --json`;
  }

  // ---------------------------------------------------------------------------------------
  // The apparatus, moved by the computed motion

  const APP = { w: 640, h: 240 };

  /** (x, v, apparatus) of the animation's law at time t, between the nearest samples. */
  function stateAt(t) {
    const points = view.curves[state.law].length ? view.curves[state.law] : view.curves.harmonic;
    return { x: valueAt(points, 1, t), v: valueAt(points, 2, t), z: valueAt(points, 3, t), points };
  }

  function extent(points, i) {
    let lo = Infinity;
    let hi = -Infinity;
    for (const p of points) { lo = Math.min(lo, p[i]); hi = Math.max(hi, p[i]); }
    return [lo, hi];
  }

  function spring(x0, y0, x1, y1, turns) {
    const dx = x1 - x0;
    const dy = y1 - y0;
    const len = Math.hypot(dx, dy) || 1;
    const nx = -dy / len;
    const ny = dx / len;
    let d = `M${x0} ${y0}`;
    for (let i = 1; i < 2 * turns; i++) {
      const f = i / (2 * turns);
      const s = i % 2 ? 7 : -7;
      d += `L${(x0 + dx * f + nx * s).toFixed(1)} ${(y0 + dy * f + ny * s).toFixed(1)}`;
    }
    return `${d}L${x1} ${y1}`;
  }

  function drawApparatus() {
    if (!view) return;
    const svg = $("apparatus");
    const desc = svg.querySelector("desc");
    svg.replaceChildren(desc);
    const s = stateAt(state.time);
    const moving = Math.abs(s.v) > 1e-12;
    const body = moving ? DATA.palette[0] : "#8a8a8a";
    const word = moving ? "slipping" : "stuck";
    const text = { "font-family": "DejaVu Sans, Helvetica, Arial, sans-serif", "font-size": 13, fill: "#000" };
    svg.append(svgEl("rect", { x: 0, y: 0, width: APP.w, height: APP.h, fill: "#fff" }));
    const [xlo, xhi] = extent(s.points, 1);
    const [zlo, zhi] = extent(s.points, 3);
    const t = `t = ${fmt(state.time, 4)} s`;
    if (state.model === "woodpecker") {
      // Pole, sleeve sliding down, bird on its spring; one scale for both lengths.
      // y_W = y_S + z (downward): the bird sits z beside the sleeve, both on one scale.
      const scale = 180 / Math.max(xhi - xlo + Math.max(zhi, 0) - Math.min(zlo, 0), 1e-9);
      const sy = 24 + (Math.max(0, -zlo) + s.x - xlo) * scale;
      svg.append(svgEl("rect", { x: 310, y: 8, width: 12, height: 226, fill: "#c8c8c8", stroke: "#606060" }));
      svg.append(svgEl("rect", { x: 300, y: sy - 12, width: 32, height: 24, rx: 3, fill: body, stroke: "#000" }));
      const by = sy + s.z * scale;
      svg.append(svgEl("path", { d: spring(332, sy, 392, by, 6), fill: "none", stroke: "#000", "stroke-width": 1.5 }));
      const tilt = zhi > zlo ? 30 * ((s.z - zlo) / (zhi - zlo) - 0.5) : 0;
      const bird = svgEl("g", { transform: `translate(410 ${by.toFixed(1)}) rotate(${tilt.toFixed(1)})` });
      bird.append(svgEl("ellipse", { cx: 0, cy: 0, rx: 20, ry: 12, fill: DATA.palette[1], stroke: "#000" }));
      bird.append(svgEl("circle", { cx: 22, cy: -10, r: 8, fill: DATA.palette[1], stroke: "#000" }));
      bird.append(svgEl("path", { d: "M29 -12 L44 -8 L29 -6 Z", fill: DATA.palette[4], stroke: "#000" }));
      svg.append(bird);
      svg.append(svgEl("text", { ...text, x: 20, y: 30 }, t));
      svg.append(svgEl("text", { ...text, x: 20, y: 50 }, `sleeve ${word}, y_S = ${fmt(s.x * 1e3, 4)} mm`));
      svg.append(svgEl("text", { ...text, x: 20, y: 70 }, `v = ${fmt(s.v * 1e3, 4)} mm/s`));
      desc.textContent = `The woodpecker toy at ${t}: the sleeve is ${word} on the pole, ${fmt(s.x * 1e3, 4)} mm below its start, and the bird swings on its spring beside it.`;
    } else {
      // Table, block pulled by F, the hanging mass on its spring pressing it.
      const scale = 420 / Math.max(xhi - xlo, 1e-9);
      const bx = 60 + (s.x - xlo) * scale;
      svg.append(svgEl("line", { x1: 20, x2: 620, y1: 170, y2: 170, stroke: "#000", "stroke-width": 2 }));
      svg.append(svgEl("rect", { x: 20, y: 170, width: 600, height: 10, fill: "#d8c6a0" }));
      svg.append(svgEl("rect", { x: bx - 30, y: 132, width: 60, height: 38, fill: body, stroke: "#000" }));
      const amp = Math.max(Math.abs(zlo), Math.abs(zhi), 1e-12);
      const my = 62 + (s.z / amp) * 18;
      svg.append(svgEl("path", { d: spring(bx, 132, bx, my + 14, 5), fill: "none", stroke: "#000", "stroke-width": 1.5 }));
      svg.append(svgEl("rect", { x: bx - 18, y: my - 14, width: 36, height: 28, fill: DATA.palette[1], stroke: "#000" }));
      svg.append(svgEl("text", { ...text, x: bx, y: my + 5, "text-anchor": "middle", fill: "#000" }, "m′"));
      svg.append(svgEl("line", { x1: bx + 30, x2: bx + 80, y1: 151, y2: 151, stroke: "#000", "stroke-width": 2 }));
      svg.append(svgEl("path", { d: `M${bx + 80} 145 L${bx + 92} 151 L${bx + 80} 157 Z`, fill: "#000" }));
      svg.append(svgEl("text", { ...text, x: bx + 86, y: 140 }, "F"));
      svg.append(svgEl("text", { ...text, x: 20, y: 210 }, `${t}; block ${word}, x = ${fmt(s.x * 1e3, 4)} mm, v = ${fmt(s.v * 1e3, 4)} mm/s`));
      desc.textContent = `The pulled mass at ${t}: the block is ${word}, ${fmt(s.x * 1e3, 4)} mm from its start, pressed by the hanging mass m′ on its spring.`;
    }
    const end = DATA.shown * view.period;
    $("time").value = String(Math.round((state.time / end) * 1000));
    $("time-out").textContent = t;
    $("time").setAttribute("aria-valuetext", t);
    moveCursors();
  }

  function setupPlayer() {
    const play = $("play");
    const speed = $("speed");
    if (reducedMotion.matches) speed.value = "0.02";
    let last = null;
    let stepped = 0;
    const frame = (now) => {
      if (!state.playing || !view) return;
      const end = DATA.shown * view.period;
      if (last !== null) {
        if (reducedMotion.matches) {
          // No smooth motion: an eighth of a period per second.
          stepped += now - last;
          if (stepped >= 1000) { stepped = 0; state.time = (state.time + view.period / 8) % end; drawApparatus(); }
        } else {
          state.time = (state.time + ((now - last) / 1000) * Number(speed.value)) % end;
          drawApparatus();
        }
      }
      last = now;
      requestAnimationFrame(frame);
    };
    play.addEventListener("click", () => {
      state.playing = !state.playing;
      play.textContent = state.playing ? "Pause" : "Play";
      play.setAttribute("aria-pressed", String(state.playing));
      last = null;
      if (state.playing) requestAnimationFrame(frame);
    });
    $("time").addEventListener("input", () => {
      if (!view) return;
      state.time = (Number($("time").value) / 1000) * DATA.shown * view.period;
      drawApparatus();
    });
  }

  // ---------------------------------------------------------------------------------------
  // The regime map: computed a few rows at a time, so that sliders stay responsive

  // The canvas: the cells in a square of `size` px at (left, top), tick labels and axis
  // titles around it.
  const MAP = { w: 484, h: 456, left: 60, top: 10, size: 400 };
  let mapJob = 0;
  let mapTimer = null;
  let map = null; // {info, cells, n}

  function scheduleMap() {
    clearTimeout(mapTimer);
    const job = ++mapJob;
    mapTimer = setTimeout(() => computeMap(job), 120);
  }

  function computeMap(job) {
    const n = DATA.map_cells;
    const req = { ...request(), law: state.law, cells: n };
    const cells = new Uint8Array(n * n);
    let info = null;
    let row = 0;
    const chunk = () => {
      if (job !== mapJob) return;
      const rows = [row, Math.min(n, row + 5)];
      const out = call("map", { ...req, rows });
      if (!out.ok) { $("map-status").textContent = `No map: ${out.text}`; return; }
      info = JSON.parse(out.text);
      cells.set(Array.from(out.data), row * n);
      row = rows[1];
      if (row < n) { setTimeout(chunk, 0); return; }
      map = { info, cells, n };
      probe.mapCells += 1;
      drawMap();
    };
    chunk();
  }

  function axisParam(key) {
    return model().params.find((p) => p.key === key);
  }

  function drawMap() {
    if (!map || !view) return;
    const canvas = $("map");
    const ctx = canvas.getContext("2d");
    const { info, cells, n } = map;
    const { left, top, size } = MAP;
    const cell = size / n;
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, MAP.w, MAP.h);
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const cat = info.categories[cells[j * n + i]];
        ctx.fillStyle = cat ? DATA.fills[cat[1] % DATA.fills.length] : "#dddddd";
        ctx.fillRect(Math.floor(left + i * cell), Math.floor(top + size - (j + 1) * cell), Math.ceil(cell), Math.ceil(cell));
      }
    }
    const fx = (x) => (x - info.x.range[0]) / (info.x.range[1] - info.x.range[0]);
    const fy = (y) => (y - info.y.range[0]) / (info.y.range[1] - info.y.range[0]);
    const px = (x) => left + fx(x) * size;
    const py = (y) => top + size - fy(y) * size;
    const xp = axisParam(info.x.key);
    const yp = axisParam(info.y.key);
    // Frame, ticks at the ends, quarters and middle, axis titles.
    ctx.strokeStyle = "#000";
    ctx.lineWidth = 1;
    ctx.strokeRect(left - 0.5, top - 0.5, size + 1, size + 1);
    ctx.fillStyle = "#000";
    ctx.font = "12px DejaVu Sans, Helvetica, Arial, sans-serif";
    for (let k = 0; k <= 4; k++) {
      const f = k / 4;
      const xv = info.x.range[0] + f * (info.x.range[1] - info.x.range[0]);
      const yv = info.y.range[0] + f * (info.y.range[1] - info.y.range[0]);
      ctx.textAlign = "center";
      ctx.fillText(fmt(xv * xp.factor, 3), left + f * size, top + size + 16);
      ctx.textAlign = "right";
      ctx.fillText(fmt(yv * yp.factor, 3), left - 6, top + size - f * size + 4);
    }
    const title = (p) => `${p.symbol}${p.unit ? ` (${p.unit})` : ""}`;
    ctx.font = "13px DejaVu Sans, Helvetica, Arial, sans-serif";
    ctx.textAlign = "center";
    ctx.fillText(title(xp), left + size / 2, top + size + 38);
    ctx.save();
    ctx.translate(14, top + size / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.fillText(title(yp), 0, 0);
    ctx.restore();
    const values = view.evaluation.params;
    const cx = px(values[info.x.key]);
    const cy = py(values[info.y.key]);
    ctx.fillStyle = "#000";
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.moveTo(cx, cy - 8); ctx.lineTo(cx + 8, cy); ctx.lineTo(cx, cy + 8); ctx.lineTo(cx - 8, cy); ctx.closePath();
    ctx.fill(); ctx.stroke();
    if (state.mapCursor) {
      const [i, j] = state.mapCursor;
      ctx.strokeStyle = "#000";
      ctx.lineWidth = 2;
      ctx.strokeRect(left + i * cell, top + size - (j + 1) * cell, cell, cell);
    }
    const legend = $("map-legend");
    legend.replaceChildren();
    for (const [label, fill] of info.categories) {
      const li = el("li");
      const sw = el("span", { class: "swatch", "aria-hidden": "true" });
      sw.style.background = DATA.fills[fill % DATA.fills.length];
      li.append(sw, label);
      legend.append(li);
    }
    const range = (p, r) => `${p.symbol} from ${fmt(r[0] * p.factor, 3)} to ${fmt(r[1] * p.factor, 3)}${unitText(p.unit)}`;
    const here = (() => {
      const i = Math.floor(fx(values[info.x.key]) * n);
      const j = Math.floor(fy(values[info.y.key]) * n);
      const cat = i >= 0 && i < n && j >= 0 && j < n ? info.categories[cells[j * n + i]] : null;
      return cat ? `; the current set lies in "${cat[0]}"` : "; the current set lies outside the map";
    })();
    const law = DATA.laws.find((l) => l.id === state.law).label;
    $("map-status").textContent = `Regimes of the ${law}, ${n}×${n} cells: horizontally ${range(xp, info.x.range)}, vertically ${range(yp, info.y.range)}${here}.`;
    canvas.setAttribute("aria-label", `Regime map of the ${law} over ${xp.symbol} and ${yp.symbol}`);
  }

  /** The map cell (i, j) of the current set, clamped to the map; its centre without a set. */
  function currentCell() {
    const { info, n } = map;
    const values = view ? view.evaluation.params : null;
    const cellOf = (axis) => {
      const v = values ? values[axis.key] : NaN;
      const k = Math.floor(((v - axis.range[0]) / (axis.range[1] - axis.range[0])) * n);
      return Number.isFinite(k) ? Math.min(n - 1, Math.max(0, k)) : Math.floor(n / 2);
    };
    return [cellOf(info.x), cellOf(info.y)];
  }

  /** Sets the map's two parameters to the centre of cell (i, j). */
  function pickCell(i, j) {
    if (!map) return;
    const { info, n } = map;
    const at = (r, k) => r[0] + ((r[1] - r[0]) * (k + 0.5)) / n;
    for (const [axis, k] of [[info.x, i], [info.y, j]]) {
      const p = axisParam(axis.key);
      current().values[axis.key] = toSi(round4(at(axis.range, k) * p.factor), p);
      syncParam(p);
    }
    update();
  }

  function setupMap() {
    const canvas = $("map");
    canvas.addEventListener("click", (ev) => {
      if (!map) return;
      const r = canvas.getBoundingClientRect();
      const x = ((ev.clientX - r.left) / r.width) * MAP.w - MAP.left;
      const y = ((ev.clientY - r.top) / r.height) * MAP.h - MAP.top;
      if (x < 0 || y < 0 || x >= MAP.size || y >= MAP.size) return;
      const i = Math.floor((x / MAP.size) * map.n);
      const j = Math.floor((1 - y / MAP.size) * map.n);
      state.mapCursor = [Math.min(map.n - 1, Math.max(0, i)), Math.min(map.n - 1, Math.max(0, j))];
      pickCell(...state.mapCursor);
    });
    canvas.addEventListener("keydown", (ev) => {
      if (!map) return;
      const moves = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
      // The keyboard cursor starts at the cell of the current set (the map's centre when the
      // set lies outside the map).
      if (!state.mapCursor) state.mapCursor = currentCell();
      if (moves[ev.key]) {
        const [di, dj] = moves[ev.key];
        const [i, j] = state.mapCursor;
        state.mapCursor = [Math.min(map.n - 1, Math.max(0, i + di)), Math.min(map.n - 1, Math.max(0, j + dj))];
        drawMap();
        ev.preventDefault();
      } else if (ev.key === "Enter" || ev.key === " ") {
        pickCell(...state.mapCursor);
        ev.preventDefault();
      }
    });
  }

  // ---------------------------------------------------------------------------------------

  async function main() {
    try {
      await startEngine();
    } catch (e) {
      $("status").textContent = `The engine could not start in this browser (${e}). The report's pages show the paper's figures.`;
      return;
    }
    buildSwitches();
    setupPlayer();
    setupMap();
    // A scene page links here as explorer.html#preset=SCENE (works from file://).
    applyPreset(new URLSearchParams(window.location.hash.slice(1)).get("preset"));
    rebuild();
    probe.timings.firstRender = performance.now();
    $("status").textContent = "Ready: move a slider, pick a preset, or click the map.";
    probe.ready = true;
  }

  main();
})();
