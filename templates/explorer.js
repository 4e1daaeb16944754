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
  const reducedMotion = window.matchMedia("(prefers-reduced-motion: reduce)");

  // What the tests read (tests/explorer.rs): the last evaluation as the engine wrote it, the
  // timings of the first render, of every redraw and of every finished map (ms, from the
  // request to the last cell), what the apparatus drawing reports; `mapAt()` (bench/) computes the
  // map afresh and answers its time.
  const probe = { ready: false, evaluation: "", extras: null, request: null, curves: [],
    error: "", timings: { firstRender: null, redraws: [], maps: [] }, mapCells: 0, apparatus: null };
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
      return callEngine(engine, fn, request);
    } catch (e) {
      engine = new WebAssembly.Instance(compiled, {}).exports;
      return { ok: false, text: `the engine failed on these parameters (${e.message})`, data: new Float64Array(0) };
    }
  }

  /** Calls export `fn` of the instance `engine` (its exports) with `request` as JSON; also
   *  the workers' (its source is theirs: it uses nothing outside it). */
  function callEngine(engine, fn, request) {
    const encoder = new TextEncoder();
    const decoder = new TextDecoder();
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
      const label = el("label", { for: id, id: `law-label-${law.id}` });
      label.append(input, el("span", {}, ` ${law.label}`));
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

  /** The model's law of slot `id` ({id, label, summary}), or undefined. */
  function modelLaw(id) { return model().laws.find((l) => l.id === id); }

  /** The law switches of the model: its laws' labels, the others hidden; the animation's
   *  and the map's law one of them. */
  function syncLaws() {
    if (!modelLaw(state.law)) state.law = model().laws[model().laws.length - 1].id;
    for (const law of DATA.laws) {
      const label = $(`law-label-${law.id}`);
      const mine = modelLaw(law.id);
      label.hidden = !mine;
      if (mine) setText(label.lastChild, ` ${mine.label}`);
      $(`law-${law.id}`).checked = law.id === state.law;
    }
  }

  function rebuild() {
    buildParams();
    syncLaws();
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
    view = { evaluation, extras, curves: splitCurves(out.data), period: extras.period };
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
  // Plots of position and speed (the report's colours and dashes). Each plot's elements are
  // made once; a new parameter set moves them (path data, attributes, texts), it does not
  // make new ones (tests/explorer.rs counts them).

  const PLOT = { w: 640, h: 210, left: 64, right: 12, top: 10, bottom: 40 };
  const FONT = "DejaVu Sans, Helvetica, Arial, sans-serif";

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
    set(e, attrs);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  /** Sets attributes of an existing element. */
  function set(e, attrs) {
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    return e;
  }

  /** Sets the text of an element, reusing its text node. */
  function setText(e, text) {
    const t = e.firstChild;
    if (t && t.nodeType === Node.TEXT_NODE && !t.nextSibling) {
      if (t.data !== text) t.data = text;
    } else {
      e.textContent = text;
    }
  }

  /** The first `n` items of `list` shown (made by `make` when missing), the others hidden. */
  function pool(list, n, make) {
    while (list.length < n) list.push(make());
    list.forEach((item, i) => {
      for (const e of Object.values(item)) {
        if (i < n) e.removeAttribute("display");
        else e.setAttribute("display", "none");
      }
    });
    return list.slice(0, n);
  }

  /** The elements of a plot, made on first use. */
  function plotParts(svg, yLabel) {
    if (svg.parts) return svg.parts;
    const x0 = PLOT.left;
    const x1 = PLOT.w - PLOT.right;
    const y0 = PLOT.h - PLOT.bottom;
    const y1 = PLOT.top;
    const grid = svgEl("g", { stroke: "#e3e3e3", "stroke-width": 1 });
    const labels = svgEl("g", { "font-family": FONT, "font-size": 12, fill: "#000" });
    const yTitle = svgEl("text", { x: 14, y: (y0 + y1) / 2, "text-anchor": "middle", "font-size": 13,
      transform: `rotate(-90 14 ${(y0 + y1) / 2})` }, yLabel);
    labels.append(svgEl("text", { x: (x0 + x1) / 2, y: PLOT.h - 6, "text-anchor": "middle", "font-size": 13 }, "t (s)"), yTitle);
    const legend = svgEl("g", { "font-family": FONT, "font-size": 12 });
    // Harmonic (solid) first, as in the report's legends.
    const laws = [...DATA.laws].reverse().map((law) => {
      const stroke = { stroke: law.color, "stroke-width": law.width, "stroke-dasharray": law.dash || "none" };
      const key = svgEl("line", { x1: x0 + 10, x2: x0 + 40, ...stroke });
      const label = svgEl("text", { x: x0 + 46 }, law.label);
      legend.append(key, label);
      return { law, key, label,
        path: svgEl("path", { fill: "none", ...stroke, "stroke-linejoin": "round" }),
        dot: svgEl("circle", { r: 4.5, fill: law.color, stroke: "#fff", "stroke-width": 1.5 }) };
    });
    const cursor = svgEl("line", { class: "cursor", y1: y0, y2: y1, stroke: "#606060", "stroke-width": 1, "stroke-dasharray": "5,4" });
    svg.replaceChildren(svg.querySelector("title"),
      svgEl("rect", { x: 0, y: 0, width: PLOT.w, height: PLOT.h, fill: "#fff" }), grid,
      svgEl("rect", { x: x0, y: y1, width: x1 - x0, height: y0 - y1, fill: "none", stroke: "#000" }), labels,
      ...laws.map((l) => l.path), legend, cursor, ...laws.map((l) => l.dot));
    const tick = () => ({ line: grid.appendChild(svgEl("line", {})), text: labels.appendChild(svgEl("text", {})) });
    const parts = { x0, x1, y0, y1, laws, cursor, yTitle, xTicks: [], yTicks: [], tick };
    // As many ticks as niceTicks gives (count + 2 at most): none is made later.
    pool(parts.xTicks, 10, tick);
    pool(parts.yTicks, 7, tick);
    svg.parts = parts;
    return parts;
  }

  function drawPlot(svg, column, yLabel, scale) {
    const parts = plotParts(svg, yLabel);
    const { x0, x1, y0, y1 } = parts;
    setText(parts.yTitle, yLabel);
    const end = DATA.shown * view.period;
    let lo = Infinity;
    let hi = -Infinity;
    for (const law of DATA.laws) for (const s of view.curves[law.id]) { lo = Math.min(lo, s[column] * scale); hi = Math.max(hi, s[column] * scale); }
    if (!(hi > lo)) { lo = Math.min(lo, 0) - 1; hi = Math.max(hi, 0) + 1; }
    const pad = 0.05 * (hi - lo);
    lo -= pad; hi += pad;
    const px = (t) => x0 + ((x1 - x0) * t) / end;
    const py = (v) => y0 + ((y1 - y0) * (v - lo)) / (hi - lo);
    const xs = niceTicks(0, end, 8);
    pool(parts.xTicks, xs.length, parts.tick).forEach(({ line, text }, i) => {
      const x = px(xs[i]);
      set(line, { x1: x, x2: x, y1: y0, y2: y1 });
      set(text, { x, y: y0 + 16, "text-anchor": "middle" });
      setText(text, fmt(xs[i], 3));
    });
    const ys = niceTicks(lo, hi, 5);
    pool(parts.yTicks, ys.length, parts.tick).forEach(({ line, text }, i) => {
      const y = py(ys[i]);
      set(line, { x1: x0, x2: x1, y1: y, y2: y });
      set(text, { x: x0 - 6, y: y + 4, "text-anchor": "end" });
      setText(text, fmt(ys[i], 3));
    });
    let ly = y1 + 16;
    for (const part of parts.laws) {
      const points = view.curves[part.law.id];
      const shown = points.length > 0;
      for (const e of [part.path, part.key, part.label, part.dot]) {
        if (shown) e.removeAttribute("display"); else e.setAttribute("display", "none");
      }
      if (!shown) continue;
      setText(part.label, modelLaw(part.law.id).label);
      let d = "";
      for (let i = 0; i < points.length; i++) d += `${i ? "L" : "M"}${px(points[i][0]).toFixed(1)} ${py(points[i][column] * scale).toFixed(1)}`;
      part.path.setAttribute("d", d);
      set(part.key, { y1: ly - 4, y2: ly - 4 });
      part.label.setAttribute("y", ly);
      ly += 16;
    }
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
    const laws = model().laws;
    const which = laws.length > 1 ? "both force laws" : `the ${laws[0].label}`;
    setText($("plot-x-title"), `Position ${pos} in mm against time over ${DATA.shown} periods, ${which}`);
    setText($("plot-v-title"), `Speed in mm/s against time over ${DATA.shown} periods, ${which}`);
    // The solid law (the last slot) against the dashed one, as the report's legends.
    const [solid, dashed] = [laws[laws.length - 1], laws.length > 1 ? laws[0] : null];
    const against = dashed ? ` (solid) against the ${dashed.label} (dashed)${view.curves[dashed.id].length ? "" : `; the ${dashed.label} does not exist for these parameters`}` : "";
    setText($("plots-caption"), `Exact integration from rest over ${DATA.shown} periods (T = ${fmt(view.period, 4)} s): `
      + `${solid.label}${against}. `
      + "The dashed vertical line and the dots follow the time of the animation.");
  }

  function moveCursors() {
    for (const id of ["plot-x", "plot-v"]) {
      const svg = $(id);
      if (!svg.parts || !svg.cursorX) continue;
      const x = svg.cursorX(state.time);
      set(svg.parts.cursor, { x1: x, x2: x });
      for (const { law, dot } of svg.parts.laws) {
        const points = view.curves[law.id];
        if (points.length) set(dot, { cx: x, cy: svg.cursorY(valueAt(points, svg.column, state.time)) });
      }
    }
  }

  // ---------------------------------------------------------------------------------------
  // The regime in words

  /** "1 slip", "2 slips". */
  function plural(n, one, many) { return `${n} ${n === 1 ? one : many}`; }

  /** The regime `id` of an integration in words: the engine's, or the model's own. */
  function regimeText(id) {
    const r = DATA.integration_regimes.find((q) => q.id === id) || model().regimes.find((q) => q.id === id);
    return r ? r.words : id;
  }

  /** An integration's summary in words: its regime, its slips and sticks per period and its
   *  mean speed where it counts them, its period where it measures one. */
  function lawWords(summary) {
    if (!summary) return "does not exist for these parameters";
    if (!summary.regime) return "no complete cycle";
    const counts = summary.slips_per_period + summary.sticks_per_period > 0
      ? [`${plural(summary.slips_per_period, "slip", "slips")} and ${plural(summary.sticks_per_period, "stick", "sticks")} per period`] : [];
    if (summary.immediate_slip) counts.push("slips at t = 0");
    const speed = "v_avg" in summary
      ? (summary.v_avg === null ? "no steady mean speed" : `mean speed ${fmt(summary.v_avg * 1e3, 4)} mm/s`)
      : `period ${fmt(summary.period, 4)} s`;
    return `${regimeText(summary.regime)}${counts.length ? ` (${counts.join("; ")})` : ""}; ${speed}`;
  }

  const capital = (s) => s.charAt(0).toUpperCase() + s.slice(1);

  /** The three lines of the regime, made once: [law, text] element pairs. */
  let regimeLines = null;

  function drawRegime() {
    const e = view.evaluation;
    const c = view.extras.closed_form;
    const laws = model().laws;
    const lines = [
      [`Closed forms (${model().closed_forms})`, `${c.words}, because ${c.why}.`],
      ...laws.map((l) => [`Exact integration, ${l.label}`, lawWords(e[l.summary])]),
    ];
    // One line per law, made when more are needed and hidden when fewer are.
    if (!regimeLines) regimeLines = [];
    while (regimeLines.length < lines.length) {
      const p = el("p");
      const law = el("span", { class: "law" }, "");
      const text = el("span", {}, "");
      p.append(law, text);
      $("regime").append(p);
      regimeLines.push([law, text, p]);
    }
    regimeLines.forEach(([law, text, p], i) => {
      p.hidden = i >= lines.length;
      setText(law, p.hidden ? "" : `${lines[i][0]}: `);
      setText(text, p.hidden ? "" : lines[i][1]);
    });
    // The live region says the regimes in words only, and only when they change, so that a
    // screen reader announces a new regime, not every step of a slider.
    const words = (s) => (s && s.regime ? regimeText(s.regime) : "none");
    const live = `Regime of the closed forms: ${c.words}. ${laws.map((l) => `${capital(l.label)}: ${words(e[l.summary])}.`).join(" ")}`;
    if ($("regime-live").textContent !== live) $("regime-live").textContent = live;
  }

  // ---------------------------------------------------------------------------------------
  // Every closed form against the integration

  // A value of the table: a number formatted, a regime id in words (the report's words).
  function inWords(value) {
    if (typeof value !== "string") return fmt(value);
    const closed = view.extras.closed_form;
    if (value === closed.id) return closed.words;
    return regimeText(value);
  }

  /** The table's rows by model and quantity, made once each and kept when not shown. */
  const tableRows = new Map();

  function tableRow(id) {
    const key = `${state.model} ${id}`;
    if (!tableRows.has(key)) {
      const tr = el("tr", { "data-quantity": id });
      const cells = ["", "", "num", "num", "", "num", "verdict", "note"].map((cls) => {
        const td = el("td", cls ? { class: cls } : {}, "");
        tr.append(td);
        return td;
      });
      tableRows.set(key, { tr, cells });
    }
    return tableRows.get(key);
  }

  function drawTable() {
    const e = view.evaluation;
    const applies = Object.fromEntries(view.extras.applicability.map((a) => [a.quantity, a]));
    const checks = Object.fromEntries(e.checks.map((c) => [c.quantity, c]));
    const shown = [];
    const row = (q, id, c) => {
      const a = applies[id];
      const na = a && !a.applies;
      const value = c ? c.closed_form : e.closed_form[id];
      const verdict = !c ? "—" : na ? "n/a" : c.pass === true ? "pass" : c.pass === false ? "FAIL" : "n/a";
      const cls = na ? "na" : !c ? "none" : c.pass === true ? "pass" : c.pass === false ? "fail" : "na";
      const { tr, cells } = tableRow(id);
      if (tr.className !== cls) tr.className = cls;
      const notes = [na ? a.reason : "", c ? c.note || "" : "no counterpart in the integration"];
      const texts = [q ? q.symbol : id, q ? `${c ? c.equation : q.equation} ${q.tag}` : c.equation,
        inWords(value), c ? inWords(c.numeric) : "—", q ? q.unit : "",
        !c || c.rel_error === null ? "—" : c.rel_error.toExponential(1), verdict, notes.filter(Boolean).join("; ")];
      texts.forEach((t, i) => setText(cells[i], t));
      cells[0].title = q ? q.words : id;
      cells[2].dataset.exact = String(value);
      cells[3].dataset.exact = c ? String(c.numeric) : "";
      shown.push(tr);
    };
    // Every closed form of the registry in its order, with its check where it has one (as the
    // report's verification table), then the checks of the periodic orbit.
    for (const q of model().quantities) {
      if (q.id in checks || q.id in e.closed_form) row(q, q.id, checks[q.id]);
    }
    const known = new Set(model().quantities.map((q) => q.id));
    for (const c of e.checks) if (!known.has(c.quantity)) row(null, c.quantity, c);
    // The rows in order: those already in place stay, others move in or out.
    const rows = $("check-rows");
    shown.forEach((tr, i) => { if (rows.children[i] !== tr) rows.insertBefore(tr, rows.children[i] || null); });
    while (rows.children.length > shown.length) rows.lastElementChild.remove();
    // The checks compare the closed forms with the integration of the first law.
    setText($("table-law"), capital(model().laws[0].label));
    setText($("periods"), String(view.extras.periods));
    setText($("json"), probe.evaluation);
    const req = probe.request;
    const flags = Object.entries(req.params).map(([k, v]) => `--${k.replace(/_/g, "-")}=${v}`)
      .concat(Object.entries(req.choices).map(([k, v]) => `--${k}=${v}`));
    setText($("cli-line"), `stickslip eval ${req.model} ${flags.join(" ")} --json`);
  }

  // ---------------------------------------------------------------------------------------
  // The apparatus, moved by the computed motion: the report's sketch of each model (the same
  // sizes: each model's apparatus data, its kind and its sketch's geometry), its bodies moved. Its elements are made
  // once per model and moved in place on each frame.

  const INK = "#000";
  const PURPLE = "#cc79a7";
  const BLUE = "#0072b2";

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

  /** The sketch's vertical coil spring (src/report/sketch.rs, Svg::spring) from y1 down to
   *  y2 at x: straight ends, `coils` zigzags of half-width `half`; polyline points. */
  function springPoints(x, y1, y2, coils, half) {
    const end = Math.min(10, (y2 - y1) / 4);
    const a = y1 + end;
    const b = y2 - end;
    const n = 2 * Math.max(1, coils);
    const step = (b - a) / n;
    const pts = [[x, y1], [x, a]];
    for (let i = 0; i < n; i++) pts.push([x + (i % 2 === 0 ? -half : half), a + step * (i + 0.5)]);
    pts.push([x, b], [x, y2]);
    return pts.map(([px, py]) => `${px.toFixed(1)},${py.toFixed(1)}`).join(" ");
  }

  const points = (pts) => pts.map(([x, y]) => `${x.toFixed(1)},${y.toFixed(1)}`).join(" ");

  let apparatus = null; // {model, parts}

  /** The sketch's geometry of the current model's apparatus (px, src/models/<name>/sketch.rs). */
  function geometry() { return model().apparatus.geometry; }

  function textEl(attrs, text) {
    return svgEl("text", { "font-family": FONT, fill: INK, ...attrs }, text);
  }

  /** One drawing per kind of apparatus (the model's data names its kind), each from the
   *  model's folder (src/models/<name>/explorer.js, inserted here by src/report/explorer.rs):
   *  its elements, made once, their move to the state s, and the speed of the surface the
   *  body sticks to. */
  const DRAWINGS = {};
  /* stickslip: the models' drawings */

  function drawApparatus() {
    if (!view) return;
    const svg = $("apparatus");
    const drawing = DRAWINGS[model().apparatus.kind];
    if (!apparatus || apparatus.model !== state.model) {
      svg.replaceChildren(svg.querySelector("desc"));
      const parts = drawing.parts(svg);
      apparatus = { model: state.model, parts };
      if (parts.height) svg.setAttribute("viewBox", `0 0 ${parts.width} ${parts.height}`);
    }
    const s = stateAt(state.time);
    const moving = Math.abs(s.v - drawing.surface()) > 1e-12 * Math.max(1, Math.abs(s.v));
    const body = moving ? DATA.palette[0] : "#8a8a8a";
    const word = moving ? "slipping" : "stuck";
    const t = `t = ${fmt(state.time, 4)} s`;
    const desc = drawing.draw(apparatus.parts, s, body, word, t, svg);
    setText(svg.querySelector("desc"), desc);
    const end = DATA.shown * view.period;
    $("time").value = String(Math.round((state.time / end) * 1000));
    setText($("time-out"), t);
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
  // The regime map: computed by two Web Workers (each with its own instance of the page's
  // engine module), a coarse pass first, then one cell per pixel of the map; rows are drawn
  // as they come, and the sliders never wait for it. Without workers, the coarse pass only,
  // a few rows at a time in the page.

  // The canvas: the cells in a square of `size` px at (left, top), tick labels and axis
  // titles around it.
  const MAP = { w: 484, h: 456, left: 60, top: 10, size: 400 };
  let mapJob = 0;
  let mapTimer = null;
  // The map shown: its axes and legend, the grid of the cursor and of clicks (`n`, the coarse
  // pass), and the finest finished pass (`best`: {n, cells}).
  let map = null;
  let mapImage = null; // the cells' pixels, MAP.size square
  let mapLevel = null; // per pixel row, the cells per side of the pass drawn there
  let mapDrawPending = false;
  let mapWaiting = null; // {resolve, started} of stickslipExplorer.mapAt
  const slots = []; // the workers: {worker, task}
  let queue = [];

  /** A worker's code (made into a Blob URL: nothing is fetched). It instantiates the module
   *  it is sent and answers map requests: {id, ok, text, data (categories)}. */
  function workerMain(callEngine) {
    let module = null;
    let ready = null;
    self.onmessage = async (ev) => {
      const m = ev.data;
      if (m.module) { module = m.module; ready = WebAssembly.instantiate(module, {}); return; }
      const engine = (await ready).exports;
      try {
        const out = callEngine(engine, "map", m.request);
        const data = Uint8Array.from(out.data);
        self.postMessage({ id: m.id, ok: out.ok, text: out.text, data }, [data.buffer]);
      } catch (e) {
        ready = WebAssembly.instantiate(module, {});
        self.postMessage({ id: m.id, ok: false, text: `the engine failed on these parameters (${e.message})`, data: new Uint8Array(0) });
      }
    };
  }

  function startWorkers() {
    if (typeof Worker === "undefined" || typeof Blob === "undefined") return;
    try {
      const url = URL.createObjectURL(new Blob([`"use strict";(${workerMain.toString()})(${callEngine.toString()});`], { type: "text/javascript" }));
      for (let i = 0; i < 2; i++) {
        const slot = { worker: new Worker(url), task: null };
        slot.worker.onmessage = (ev) => finished(slot, ev.data);
        slot.worker.onerror = (ev) => { ev.preventDefault(); stopWorkers(); };
        slot.worker.postMessage({ module: compiled });
        slots.push(slot);
      }
    } catch (e) {
      stopWorkers();
    }
  }

  /** Workers that fail (a browser that refuses them): the map is computed in the page. */
  function stopWorkers() {
    if (!slots.length) return;
    for (const s of slots) s.worker.terminate();
    slots.length = 0;
    scheduleMap();
  }

  function scheduleMap() {
    clearTimeout(mapTimer);
    queue = [];
    const job = ++mapJob;
    // After a pause of the sliders: while one is dragged, the workers would take the cores
    // the page draws with.
    mapTimer = setTimeout(() => computeMap(job), 100);
  }

  /** Queues the passes of map `job`: rows in tasks of about 4,000 cells, coarse pass first. */
  function computeMap(job) {
    const req = { ...request(), law: state.law };
    const passes = slots.length ? [DATA.map_cells, MAP.size] : [DATA.map_cells];
    mapLevel = new Uint16Array(MAP.size);
    const run = { job, req, started: performance.now(), passes: passes.map((n) => ({ n, cells: new Uint8Array(n * n), left: n })) };
    for (const pass of run.passes) {
      const step = Math.max(1, Math.min(Math.ceil(pass.n / 2), Math.floor(4000 / pass.n)));
      for (let r = 0; r < pass.n; r += step) queue.push({ run, pass, rows: [r, Math.min(pass.n, r + step)] });
    }
    dispatch();
  }

  let taskId = 0;

  function dispatch() {
    if (!slots.length) {
      const task = queue.shift();
      if (!task) return;
      const out = call("map", { ...task.run.req, cells: task.pass.n, rows: task.rows });
      received(task, { ok: out.ok, text: out.text, data: Uint8Array.from(out.data) });
      setTimeout(dispatch, 0);
      return;
    }
    for (const slot of slots) {
      if (slot.task || !queue.length) continue;
      slot.task = queue.shift();
      slot.task.id = ++taskId;
      slot.worker.postMessage({ id: slot.task.id, request: { ...slot.task.run.req, cells: slot.task.pass.n, rows: slot.task.rows } });
    }
  }

  function finished(slot, answer) {
    const task = slot.task;
    slot.task = null;
    if (task && task.id === answer.id) received(task, answer);
    dispatch();
  }

  /** The fills as [r, g, b]. */
  const fillRgb = DATA.fills.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));

  /** Rows of a pass arrived: into the pass's cells and the map's pixels. */
  function received(task, answer) {
    const { run, pass, rows } = task;
    if (run.job !== mapJob) return;
    if (!answer.ok) { queue = []; setText($("map-status"), `No map: ${answer.text}`); return; }
    const info = run.info || (run.info = JSON.parse(answer.text));
    const n = pass.n;
    pass.cells.set(answer.data, rows[0] * n);
    paintRows(info, pass, rows);
    pass.left -= rows[1] - rows[0];
    if (!map || map.run !== run) map = { run, info, n: run.passes[0].n, best: null };
    if (pass.left === 0) {
      map.best = { n, cells: pass.cells };
      if (pass === run.passes[run.passes.length - 1]) {
        const ms = performance.now() - run.started;
        probe.timings.maps.push(ms);
        probe.mapCells += 1;
        if (mapWaiting) { mapWaiting(ms); mapWaiting = null; }
      }
    }
    if (!mapDrawPending) {
      mapDrawPending = true;
      requestAnimationFrame(() => { mapDrawPending = false; drawMap(); });
    }
  }

  /** Paints cell rows `rows` of `pass` into the map's pixels (rows from the bottom), where no
   *  finer pass has painted yet. */
  function paintRows(info, pass, rows) {
    const size = MAP.size;
    if (!mapImage) mapImage = new ImageData(size, size);
    const px = mapImage.data;
    const n = pass.n;
    const line = new Uint8ClampedArray(size * 4);
    for (let j = rows[0]; j < rows[1]; j++) {
      for (let x = 0; x < size; x++) {
        const cat = info.categories[pass.cells[j * n + Math.floor((x * n) / size)]];
        const [r, g, b] = cat ? fillRgb[cat[1] % fillRgb.length] : [221, 221, 221];
        line[4 * x] = r; line[4 * x + 1] = g; line[4 * x + 2] = b; line[4 * x + 3] = 255;
      }
      const y0 = Math.ceil(size - ((j + 1) * size) / n);
      const y1 = Math.ceil(size - (j * size) / n);
      for (let y = y0; y < y1; y++) {
        if (mapLevel[y] > n) continue;
        mapLevel[y] = n;
        px.set(line, y * size * 4);
      }
    }
  }

  function axisParam(key) {
    return model().params.find((p) => p.key === key);
  }

  const legendItems = [];

  function drawMap() {
    if (!map || !view) return;
    const canvas = $("map");
    const ctx = canvas.getContext("2d");
    const { info, n } = map;
    const { left, top, size } = MAP;
    const cell = size / n;
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, MAP.w, MAP.h);
    ctx.putImageData(mapImage, left, top);
    const fx = (x) => (x - info.x.range[0]) / (info.x.range[1] - info.x.range[0]);
    const fy = (y) => (y - info.y.range[0]) / (info.y.range[1] - info.y.range[0]);
    const px = (x) => left + fx(x) * size;
    const py = (y) => top + size - fy(y) * size;
    const xp = axisParam(info.x.key);
    const yp = axisParam(info.y.key);
    if (!xp || !yp) return; // a map of the other model, replaced in a moment
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
    // The legend's items, made when more are needed and hidden when fewer are.
    const legend = $("map-legend");
    while (legendItems.length < info.categories.length) {
      const li = el("li");
      const sw = el("span", { class: "swatch", "aria-hidden": "true" });
      const label = el("span", {}, "");
      li.append(sw, label);
      legend.append(li);
      legendItems.push({ li, sw, label });
    }
    legendItems.forEach(({ li, sw, label }, k) => {
      const cat = info.categories[k];
      li.hidden = !cat;
      if (!cat) return;
      sw.style.background = DATA.fills[cat[1] % DATA.fills.length];
      setText(label, cat[0]);
    });
    const range = (p, r) => `${p.symbol} from ${fmt(r[0] * p.factor, 3)} to ${fmt(r[1] * p.factor, 3)}${unitText(p.unit)}`;
    const best = map.best || { n, cells: new Uint8Array(n * n).fill(255) };
    const here = (() => {
      const i = Math.floor(fx(values[info.x.key]) * best.n);
      const j = Math.floor(fy(values[info.y.key]) * best.n);
      const cat = i >= 0 && i < best.n && j >= 0 && j < best.n ? info.categories[best.cells[j * best.n + i]] : null;
      return cat ? `; the current set lies in "${cat[0]}"` : "; the current set lies outside the map";
    })();
    const law = modelLaw(state.law).label;
    setText($("map-status"), `Regimes of the ${law}, ${best.n}×${best.n} cells: horizontally ${range(xp, info.x.range)}, vertically ${range(yp, info.y.range)}${here}.`);
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
    startWorkers();
    probe.mapAt = () => new Promise((resolve) => { mapWaiting = resolve; scheduleMap(); });
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
