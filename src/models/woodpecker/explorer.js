// The woodpecker toy in the explorer page's animation. src/report/explorer.rs inserts this
// file into templates/explorer.js as the body of a function that returns the drawing (the model's
// `Explore::apparatus` names it): its elements, made once (`parts`), their move to the state s
// (`draw`, which answers the words of the SVG's description) and the speed of the surface the
// body sticks to. The page's helpers are in scope there: svgEl, textEl, set, setText, points,
// springPoints, extent, fmt, geometry (this model's sketch geometry, px), INK, PURPLE, BLUE,
// FONT, DATA, view, state and probe.

/** The woodpecker's drawn sizes for parameters `p` (SI), as the sketch's woodpecker_layout:
 *  scale (px/mm), l and h (px), the sleeve's tilt θ (rad) and its hole's half-height b (px). */
function woodpeckerLayout(p) {
  const g = geometry();
  const [l, h, z0, d0] = [p.l * 1e3, p.h * 1e3, p.z0 * 1e3, p.d0 * 1e3];
  const zLo = Math.min(z0 - Math.abs(d0), 0);
  const zHi = Math.max(z0 + Math.abs(d0), 0);
  let scale = [g.max_scale, g.l_span / l, g.h_span / h, g.z_span / (zHi - zLo)]
    .filter((v) => Number.isFinite(v) && v > 0).reduce((a, b) => Math.min(a, b), Infinity);
  if (!Number.isFinite(scale)) scale = g.max_scale;
  const hPx = Math.max(h * scale, g.h_min);
  // The sketch's sleeve_tilt: the hole's top-left inner corner on the pole's left face, the
  // contacts h apart vertically (a fixed point on b).
  const a = g.pole_half + g.clearance;
  let b = hPx / 2;
  let theta = 0;
  for (let i = 0; i < 50; i++) {
    theta = Math.atan(a / b) - Math.asin(g.pole_half / Math.hypot(a, b));
    b = (hPx / 2 - a * Math.sin(theta)) / Math.cos(theta);
  }
  return { scale, l_px: Math.max(l * scale, g.l_min), h_px: hPx, theta, b, zLo, zHi };
}

/** The woodpecker as its sketch draws it: the pole, the sleeve tilted on it (contacts h
 *  apart) with its arm l, the spring and the bird; the view follows the sleeve down the pole,
 *  whose marks move up as it falls. */
function woodpeckerParts(svg) {
  const f = geometry().font;
  const wall = { fill: INK, "fill-opacity": 0.25, stroke: INK, "stroke-width": 1.5 };
  const bird = svgEl("g", { class: "bird" });
  const r = geometry().bird_r;
  const [hx, hy] = [-r * 0.75, -r * 0.7];
  bird.append(
    svgEl("ellipse", { cx: 4, cy: 4, rx: r * 1.2, ry: r * 0.8, fill: DATA.palette[1], stroke: INK, "stroke-width": 1.6 }),
    svgEl("circle", { cx: hx, cy: hy, r: r * 0.5, fill: DATA.palette[1], stroke: INK, "stroke-width": 1.6 }),
    svgEl("polygon", { points: points([[hx - r * 0.45, hy - 3], [hx - r * 1.25, hy + 1], [hx - r * 0.45, hy + 4]]), fill: INK, "fill-opacity": 0.6, stroke: INK, "stroke-width": 1.2 }),
    svgEl("circle", { cx: hx - 2, cy: hy - 2, r: 1.8, fill: INK }),
    svgEl("path", { d: `M${hx - 2} ${hy - r * 0.5} q${r * 0.4} ${-r * 0.5} ${r * 0.8} ${r * 0.15}`, fill: "none", stroke: "#d55e00", "stroke-width": 3 }));
  const parts = {
    pole: svgEl("rect", { fill: INK, "fill-opacity": 0.1, stroke: INK, "stroke-width": 1.2 }),
    marks: [],
    marksGroup: svgEl("g", { stroke: INK, "stroke-width": 1.5 }),
    ring: svgEl("polygon", { fill: INK, "fill-opacity": 0.08, stroke: INK, "stroke-width": 0.8 }),
    leftWall: svgEl("polygon", { class: "sleeve", ...wall }),
    rightWall: svgEl("polygon", { class: "sleeve", ...wall }),
    c1: svgEl("circle", { r: 3.5, fill: INK }),
    c2: svgEl("circle", { r: 3.5, fill: INK }),
    band: svgEl("rect", { fill: PURPLE, "fill-opacity": 0.22 }),
    spring: svgEl("polyline", { class: "spring", fill: "none", stroke: PURPLE, "stroke-width": 2.2, "stroke-linejoin": "round" }),
    bird,
    time: textEl({ x: 20, y: 36, "font-size": f }, ""),
    words: textEl({ x: 20, y: 72, "font-size": f }, ""),
    speed: textEl({ x: 20, y: 108, "font-size": f }, ""),
  };
  for (let i = 0; i < 24; i++) parts.marks.push(parts.marksGroup.appendChild(svgEl("line", {})));
  svg.append(parts.ring, parts.pole, parts.marksGroup, parts.leftWall, parts.rightWall, parts.c1, parts.c2,
    parts.band, parts.spring, bird, parts.time, parts.words, parts.speed);
  return parts;
}

function drawWoodpecker(parts, s, body, word, t, svg) {
  const g = geometry();
  const p = view.evaluation.params;
  const L = woodpeckerLayout(p);
  probe.apparatus = { scale: L.scale, l_px: L.l_px, h_px: L.h_px, theta: L.theta, b: L.b };
  const { scale, b } = L;
  // The sleeve tilts with the spring's pull: clockwise while it pulls down (z > 0).
  const theta = s.z < 0 ? -L.theta : L.theta;
  const px = 300;
  const [cx, cy] = [px, 250];
  const a = g.pole_half + g.clearance;
  const [sn, cs] = [Math.sin(theta), Math.cos(theta)];
  const rot = (dx, dy) => [cx + dx * cs - dy * sn, cy + dx * sn + dy * cs];
  const armLen = L.l_px / Math.cos(L.theta);
  const armEnd = rot(armLen, g.arm_half);
  const springX = px + L.l_px;
  const zLo = Math.min(L.zLo, extent(s.points, 3)[0] * 1e3);
  const zHi = Math.max(L.zHi, extent(s.points, 3)[1] * 1e3);
  // z = 0 sits the spring's natural length below the arm's end as the sketch draws it
  // (tilted clockwise), whichever way the sleeve tilts now.
  const armY = cy + armLen * Math.sin(L.theta) + g.arm_half * Math.cos(L.theta);
  const zZero = armY + g.natural - Math.min(zLo, 0) * scale;
  const yOf = (zmm) => zZero + zmm * scale;
  const birdY = yOf(s.z * 1e3);
  const height = yOf(zHi) + g.bird_r + 40;
  // The sketch's canvas, cut right of the bird.
  svg.setAttribute("viewBox", `0 0 ${Math.min(g.width, springX + 200).toFixed(1)} ${height.toFixed(1)}`);
  const ring = [rot(-a - g.wall, -b), rot(a + g.wall, -b), rot(a + g.wall, b), rot(-a - g.wall, b)];
  parts.ring.setAttribute("points", points(ring));
  set(parts.pole, { x: px - g.pole_half, y: 130, width: 2 * g.pole_half, height: height - 130 });
  // Marks on the pole every 1, 2 or 5 × 10^k mm, at least 40 px apart, moving up as the
  // sleeve falls (y_S, downward positive).
  const steps = [1, 2, 5].flatMap((m) => [0.1, 1, 10, 100].map((k) => m * k)).sort((u, v) => u - v);
  const every = steps.find((m) => m * scale >= 40) || 1000;
  const yS = s.x * 1e3;
  const first = Math.ceil((yS + (130 - cy) / scale) / every);
  parts.marks.forEach((line, i) => {
    const y = cy + ((first + i) * every - yS) * scale;
    if (y > height) { line.setAttribute("display", "none"); return; }
    line.removeAttribute("display");
    set(line, { x1: px - g.pole_half, x2: px + g.pole_half, y1: y.toFixed(1), y2: y.toFixed(1) });
  });
  parts.leftWall.setAttribute("points", points([rot(-a - g.wall, -b), rot(-a, -b), rot(-a, b), rot(-a - g.wall, b)]));
  parts.rightWall.setAttribute("points", points([rot(a, -b), rot(a + g.wall, -b), rot(a + g.wall, -g.arm_half),
    rot(armLen, -g.arm_half), rot(armLen, g.arm_half), rot(a + g.wall, g.arm_half), rot(a + g.wall, b), rot(a, b)]));
  parts.leftWall.setAttribute("fill", body);
  parts.rightWall.setAttribute("fill", body);
  // The contacts: the hole's corners on the pole.
  const [c1, c2] = theta >= 0 ? [rot(-a, -b), rot(a, b)] : [rot(-a, b), rot(a, -b)];
  set(parts.c1, { cx: c1[0].toFixed(1), cy: c1[1].toFixed(1) });
  set(parts.c2, { cx: c2[0].toFixed(1), cy: c2[1].toFixed(1) });
  const [top, bot] = [yOf(p.z0 * 1e3 - Math.abs(p.d0 * 1e3)), yOf(p.z0 * 1e3 + Math.abs(p.d0 * 1e3))];
  set(parts.band, { x: springX - g.bird_r - 8, y: top.toFixed(1), width: 2 * g.bird_r + 16, height: Math.max(0, bot - top).toFixed(1) });
  parts.spring.setAttribute("points", springPoints(springX, armEnd[1], birdY - g.bird_r, g.coils, g.coil_half));
  parts.bird.setAttribute("transform", `translate(${springX.toFixed(1)} ${birdY.toFixed(1)})`);
  setText(parts.time, t);
  setText(parts.words, `sleeve ${word}, y_S = ${fmt(yS, 4)} mm`);
  setText(parts.speed, `v = ${fmt(s.v * 1e3, 4)} mm/s`);
  return `The woodpecker toy at ${t}: the sleeve, tilted on the pole and touching it at two points ${fmt(p.h * 1e3, 3)} mm apart, is ${word}, ${fmt(yS, 4)} mm below its start; the bird swings on its spring at the end of the sleeve's arm, l = ${fmt(p.l * 1e3, 3)} mm from the pole's axis. The view follows the sleeve: the marks on the pole move up as it falls.`;
}

return { parts: woodpeckerParts, draw: drawWoodpecker, surface: () => 0 };
