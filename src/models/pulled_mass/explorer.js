// The pulled mass in the explorer page's animation. src/report/explorer.rs inserts this
// file into templates/explorer.js as the body of a function that returns the drawing (the model's
// `Explore::apparatus` names it): its elements, made once (`parts`), their move to the state s
// (`draw`, which answers the words of the SVG's description) and the speed of the surface the
// body sticks to. The page's helpers are in scope there: svgEl, textEl, set, setText, points,
// springPoints, extent, fmt, geometry (this model's sketch geometry, px), INK, PURPLE, BLUE,
// FONT, DATA, view, state and probe.

/** The pulled mass as its sketch draws it: the block on the table, the spring under it
 *  through the slot (a groove along the motion, seen through the table's near edge), the
 *  hanging mass m′ and the pull F. */
function pulledMassParts(svg) {
  const g = geometry();
  const f = g.font;
  const top = 140;
  const body = { stroke: INK, "stroke-width": 1.6 };
  const parts = {
    top, width: g.width, height: top + g.hang + 18 + g.mass_height + 24,
    left: svgEl("rect", { y: top, height: g.table, fill: INK, "fill-opacity": 0.18, stroke: INK, "stroke-width": 1.2 }),
    right: svgEl("rect", { y: top, height: g.table, fill: INK, "fill-opacity": 0.18, stroke: INK, "stroke-width": 1.2 }),
    rail: svgEl("rect", { y: top, height: g.table, fill: INK, "fill-opacity": 0.06, stroke: INK, "stroke-width": 1, "stroke-dasharray": "5 4" }),
    spring: svgEl("polyline", { class: "spring", fill: "none", stroke: PURPLE, "stroke-width": 2.2, "stroke-linejoin": "round" }),
    block: svgEl("rect", { class: "block", y: top - g.block_height, width: g.block_width, height: g.block_height, ...body }),
    blockLabel: textEl({ y: top - g.block_height / 2 + 7, "text-anchor": "middle", "font-size": f }, "m"),
    mass: svgEl("rect", { class: "hanging", width: g.mass_width, height: g.mass_height, fill: INK, "fill-opacity": 0.12, ...body }),
    massLabel: textEl({ "font-size": f }, "m′ = m"),
    stub: svgEl("line", { stroke: INK, "stroke-width": 1.5 }),
    pull: svgEl("line", { stroke: BLUE, "stroke-width": 3 }),
    head: svgEl("polygon", { fill: BLUE }),
    pullLabel: textEl({ "text-anchor": "middle", "font-size": f }, "F"),
    time: textEl({ x: 10, y: 28, "font-size": f }, ""),
    words: textEl({ x: 10, y: 52, "font-size": f }, ""),
  };
  svg.append(parts.left, parts.right, parts.spring, parts.rail, parts.block, parts.blockLabel, parts.mass,
    parts.massLabel, parts.stub, parts.pull, parts.head, parts.pullLabel, parts.time, parts.words);
  return parts;
}

function drawPulledMass(parts, s, body, word, t) {
  const g = geometry();
  const [xlo, xhi] = extent(s.points, 1);
  const [zlo, zhi] = extent(s.points, 3);
  // The block's centre travels from `start` over `travel` px (the sketch has no length
  // scale along the table); the slot spans the spring's travel.
  const start = 20 + g.block_width / 2;
  const travel = g.width - start - g.block_width / 2 - g.pull_stub - g.pull_arrow - 30;
  const cx = start + (xhi > xlo ? ((s.x - xlo) / (xhi - xlo)) * travel : 0);
  const { top } = parts;
  const slotL = start - g.slot_half;
  const slotR = start + travel + g.slot_half;
  set(parts.left, { x: 10, width: slotL - 10 });
  set(parts.right, { x: slotR, width: g.width - 10 - slotR });
  set(parts.rail, { x: slotL, width: slotR - slotL });
  // The hanging mass, 18 px either side of its rest position (not to scale).
  const amp = Math.max(Math.abs(zlo), Math.abs(zhi), 1e-12);
  const hangY = top + g.hang + (s.z / amp) * 18;
  parts.spring.setAttribute("points", springPoints(cx, top, hangY, g.coils, g.coil_half));
  set(parts.block, { x: cx - g.block_width / 2, fill: body });
  parts.blockLabel.setAttribute("x", cx);
  set(parts.mass, { x: cx - g.mass_width / 2, y: hangY });
  set(parts.massLabel, { x: cx + g.mass_width / 2 + 8, y: hangY + 22 });
  const fy = top - g.block_height / 2;
  const face = cx + g.block_width / 2;
  const stub = face + g.pull_stub;
  const tip = stub + g.pull_arrow;
  set(parts.stub, { x1: face, x2: stub, y1: fy, y2: fy });
  set(parts.pull, { x1: stub, x2: tip - 12, y1: fy, y2: fy });
  parts.head.setAttribute("points", points([[tip, fy], [tip - 14, fy - 6], [tip - 14, fy + 6]]));
  set(parts.pullLabel, { x: tip - g.pull_arrow / 2, y: fy - 12 });
  setText(parts.time, t);
  setText(parts.words, `block ${word}, x = ${fmt(s.x * 1e3, 4)} mm, v = ${fmt(s.v * 1e3, 4)} mm/s`);
  return `The pulled mass at ${t}: the block is ${word} on the table, ${fmt(s.x * 1e3, 4)} mm from its start, pulled by F and pressed down by the spring of the mass m′ hanging under it through the slot.`;
}

return { parts: pulledMassParts, draw: drawPulledMass, surface: () => 0 };
