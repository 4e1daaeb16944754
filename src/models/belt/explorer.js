// The block on a belt in the explorer page's animation. src/report/explorer.rs inserts this
// file into templates/explorer.js as the body of a function that returns the drawing (the model's
// `Explore::apparatus` names it): its elements, made once (`parts`), their move to the state s
// (`draw`, which answers the words of the SVG's description) and the speed of the surface the
// body sticks to. The page's helpers are in scope there: svgEl, textEl, set, setText, points,
// springPoints, extent, fmt, geometry (this model's sketch geometry, px), INK, PURPLE, BLUE,
// FONT, DATA, view, state and probe.

/** The block on a belt as its sketch draws it: the wall, the spring k, the block on the belt
 *  that runs right at v_b (its marks move with it, to the block's scale), the belt's speed. */
function beltParts(svg) {
  const g = geometry();
  const f = g.font;
  // The belt's top: the wall stands on it, below the two lines of text.
  const top = 76 + g.wall_height;
  const right = g.width - 20;
  const marks = svgEl("g", { class: "belt-marks", stroke: INK, "stroke-width": 1.5 });
  const parts = {
    top, right, width: g.width, height: top + g.belt_height + 64, marks: [],
    wall: svgEl("rect", { class: "wall", x: g.wall_x, y: top - g.wall_height, width: g.wall_width, height: g.wall_height, fill: INK, "fill-opacity": 0.3, stroke: INK, "stroke-width": 1.4 }),
    spring: svgEl("polyline", { class: "spring", fill: "none", stroke: PURPLE, "stroke-width": 2.2, "stroke-linejoin": "round" }),
    block: svgEl("rect", { class: "block", y: top - g.block_height, width: g.block_width, height: g.block_height, stroke: INK, "stroke-width": 1.6 }),
    blockLabel: textEl({ y: top - g.block_height / 2 + 7, "text-anchor": "middle", "font-size": f }, "m"),
    belt: svgEl("rect", { class: "belt", x: g.belt_left, y: top, width: right - g.belt_left, height: g.belt_height, fill: INK, "fill-opacity": 0.18, stroke: INK, "stroke-width": 1.2 }),
    rollers: [g.belt_left + g.roller_r, right - g.roller_r].map((cx) => svgEl("circle", { cx, cy: top + g.roller_r, r: g.roller_r, fill: INK, "fill-opacity": 0.15, stroke: INK, "stroke-width": 1.2 })),
    speed: svgEl("line", { x1: g.belt_left + 20, x2: g.belt_left + 98, y1: top + g.belt_height + 22, y2: top + g.belt_height + 22, stroke: "#e69f00", "stroke-width": 3 }),
    head: svgEl("polygon", { fill: "#e69f00", points: points([[g.belt_left + 110, top + g.belt_height + 22], [g.belt_left + 96, top + g.belt_height + 16], [g.belt_left + 96, top + g.belt_height + 28]]) }),
    speedLabel: textEl({ x: g.belt_left + 118, y: top + g.belt_height + 29, "font-size": f }, ""),
    time: textEl({ x: 10, y: 28, "font-size": f }, ""),
    words: textEl({ x: 10, y: 52, "font-size": f }, ""),
  };
  for (let i = 0; i * BELT_MARKS < right - g.belt_left + BELT_MARKS; i++) parts.marks.push(marks.appendChild(svgEl("line", {})));
  svg.append(parts.belt, marks, ...parts.rollers, parts.wall, parts.spring, parts.block, parts.blockLabel,
    parts.speed, parts.head, parts.speedLabel, parts.time, parts.words);
  return parts;
}

/** The belt's marks: this far apart (px). */
const BELT_MARKS = 40;

/** The belt: the block's left face at the sketch's position plus x to scale (the spring is
 *  relaxed at x = 0), the belt's marks moved by its travel v_b t to the same scale. */
function drawBelt(parts, s, body, word, t) {
  const g = geometry();
  const p = view.evaluation.params;
  const [xlo, xhi] = extent(s.points, 1);
  const wallFace = g.wall_x + g.wall_width;
  // The block's travel to the right of its drawn position, and to the left down to a spring
  // of 30 px.
  const room = [parts.right - g.block_width - g.block_x, g.block_x - wallFace - 30];
  const scale = Math.min(xhi > 0 ? room[0] / xhi : Infinity, xlo < 0 ? room[1] / -xlo : Infinity);
  const k = Number.isFinite(scale) ? scale : 1;
  const left = g.block_x + s.x * k;
  const y = parts.top - g.block_height / 2;
  parts.spring.setAttribute("points", points(zigzag(wallFace, left, y, g.coils, g.coil_half)));
  set(parts.block, { x: left.toFixed(1), fill: body });
  parts.blockLabel.setAttribute("x", (left + g.block_width / 2).toFixed(1));
  const shift = (s.z * k) % BELT_MARKS;
  const [y1, y2] = [parts.top + 2, parts.top + g.belt_height - 2];
  parts.marks.forEach((line, i) => {
    const x = g.belt_left + shift + (i - 1) * BELT_MARKS;
    if (x < g.belt_left + 2 || x > parts.right - 2) { line.setAttribute("display", "none"); return; }
    line.removeAttribute("display");
    set(line, { x1: x.toFixed(1), x2: x.toFixed(1), y1, y2 });
  });
  probe.apparatus = { time: state.time, scale: k, origin: g.block_x, block: left, x: s.x, z: s.z, shift };
  setText(parts.speedLabel, `v_b = ${fmt(p.v_b * 1e3, 4)} mm/s`);
  setText(parts.time, t);
  setText(parts.words, `block ${word}, x = ${fmt(s.x * 1e3, 4)} mm, v = ${fmt(s.v * 1e3, 4)} mm/s`);
  return `The block on the belt at ${t}: the belt runs right at v_b = ${fmt(p.v_b * 1e3, 4)} mm/s; the block, held to the wall by the spring k = ${fmt(p.k, 4)} N/m, is ${word}, ${fmt(s.x * 1e3, 4)} mm right of where the spring is relaxed, at v = ${fmt(s.v * 1e3, 4)} mm/s.`;
}

/** The sketch's horizontal coil spring (src/models/belt/sketch.rs, zigzag) from x1 to x2 at
 *  y: straight ends, `coils` zigzags of half-width `half`; its points. */
function zigzag(x1, x2, y, coils, half) {
  const end = Math.min(10, (x2 - x1) / 4);
  const a = x1 + end;
  const b = x2 - end;
  const n = 2 * Math.max(1, coils);
  const step = (b - a) / n;
  const pts = [[x1, y], [a, y]];
  for (let i = 0; i < n; i++) pts.push([a + step * (i + 0.5), y + (i % 2 === 0 ? -half : half)]);
  pts.push([b, y], [x2, y]);
  return pts;
}

return { parts: beltParts, draw: drawBelt, surface: () => view.evaluation.params.v_b };
