//! The sketch of the pulled mass (paper Sec. 2): the apparatus on the left (the block resting
//! on the table, the spring through a slot narrower than the block, the hanging mass m′) and
//! the free-body diagram of the block on the right, every force on it drawn to one scale at
//! one stated instant, with values whose vertical components balance (N = W + S).
//!
//! ```text
//! S(t) = W cos ωt   force of the spring on the block, downward positive (N(t) − W)
//! N(t) = W + S(t) = W (1 + cos ωt)            normal reaction of the table (paper (1))
//! ```
//!
//! Drawn for a printed width of one A4 column (90.5 mm): the canvas is [`WIDTH`] px wide and
//! no glyph is smaller than [`SUB`] px, so every label prints at 8 pt or more.

use serde::Serialize;

use super::PulledMassParams;
use crate::report::sketch::{
    grams, mn, ms, num, plain, Labels, Phase, Svg, BLUE, GREEN, HEAD_LEN, INK, ORANGE, PURPLE,
    VERMILLION,
};

/// Canvas width (px of the SVG user space); the height follows the arrows.
const WIDTH: f64 = 600.0;
/// Label size and the smallest glyph, subscripts included (px): 19 px of 600 print at
/// 8.1 pt across a 90.5 mm column.
const FONT: f64 = 20.0;
const SUB: f64 = 19.0;
/// The longest force arrow (px).
const LONGEST: f64 = 110.0;

/// The apparatus as the sketch draws it (px of the sketch's user space, [`WIDTH`] wide): the
/// explorer's animation (src/report/explorer.rs serialises it) draws the same block, table,
/// slot, spring and hanging mass.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Apparatus {
    /// Canvas width and label size (px).
    pub width: f64,
    pub font: f64,
    /// The block (px).
    pub block_width: f64,
    pub block_height: f64,
    /// The table's thickness and the slot's half-width (px).
    pub table: f64,
    pub slot_half: f64,
    /// From the table's top to the hanging mass's top, and the hanging mass's size (px).
    pub hang: f64,
    pub mass_width: f64,
    pub mass_height: f64,
    /// The spring: zigzags and their half-width (px).
    pub coils: usize,
    pub coil_half: f64,
    /// The pull: a stub from the block's right face, then the arrow (px).
    pub pull_stub: f64,
    pub pull_arrow: f64,
}

/// The pulled mass's apparatus, in the sketch and in the explorer.
pub const APPARATUS: Apparatus = Apparatus {
    width: WIDTH,
    font: FONT,
    block_width: 120.0,
    block_height: 56.0,
    table: 16.0,
    slot_half: 16.0,
    hang: 78.0,
    mass_width: 60.0,
    mass_height: 30.0,
    coils: 6,
    coil_half: 8.0,
    pull_stub: 10.0,
    pull_arrow: 35.0,
};

/// The pulled mass with the forces of `phase` and their values (reports, handouts).
///
/// [`Phase::Stuck`] is drawn at t = 0 (N = 2W, static friction balances F);
/// [`Phase::Slipping`] at the slip onset, where F = μs N (or at t = 0 for an immediate slip,
/// F > 2μs W), with the friction μd N.
pub fn pulled_mass(p: &PulledMassParams, phase: Phase) -> String {
    draw(p, phase, Labels::Computed)
}

/// The pulled mass at rest at t = 0 labelled with the given values only, for a worksheet: the
/// derived values (W, T, N, S, φ) are the student's to work out, so they are named, not
/// numbered.
pub fn pulled_mass_givens(p: &PulledMassParams) -> String {
    draw(p, Phase::Stuck, Labels::Givens)
}

/// The drawn instant: its words, N, the spring's force S on the block (N, downward positive)
/// and the friction on the block (N).
struct Instant {
    words: &'static str,
    n: f64,
    spring: f64,
    friction: f64,
}

fn instant(p: &PulledMassParams, phase: Phase) -> Instant {
    let w = p.weight();
    let immediate = p.force > 2.0 * p.mu_s * w;
    let (n, friction, words) = match phase {
        Phase::Stuck if immediate => (2.0 * w, p.mu_s * 2.0 * w, "t = 0"),
        Phase::Stuck => (2.0 * w, p.force, "t = 0"),
        Phase::Slipping if immediate => (2.0 * w, p.mu_d * 2.0 * w, "t = 0"),
        Phase::Slipping => (
            p.force / p.mu_s,
            p.mu_d * p.force / p.mu_s,
            "the slip onset",
        ),
    };
    Instant {
        words,
        n,
        spring: n - w,
        friction,
    }
}

fn description(p: &PulledMassParams, phase: Phase, labels: Labels, at: &Instant) -> String {
    let w = p.weight();
    let immediate = p.force > 2.0 * p.mu_s * w;
    if labels == Labels::Givens {
        return format!(
            "A block of mass m = {m} rests on a table and is pulled to the right by a constant \
             force F = {F}. Under it, through a slot in the table narrower than the block, a \
             spring of stiffness k = {k} carries a second mass m' = m = {m} that oscillates, \
             so the spring's force on the block S(t) = W cos ωt and the table's normal force \
             N(t) = W + S(t) swing between 0 and twice the block's weight. Friction \
             coefficients μs = {mus}, μd = {mud}. Drawn at rest at t = 0, with the free-body \
             diagram of the block: weight W, spring force S, normal force N, friction F_f, \
             pull F.",
            m = grams(p.mass),
            F = mn(p.force),
            k = plain(p.k, "N/m"),
            mus = num(p.mu_s),
            mud = num(p.mu_d),
        );
    }
    let friction_words = match (phase, immediate) {
        (Phase::Stuck, false) => format!(
            "static friction F_f = F = {} balances the pull (it could reach μs N = {})",
            mn(at.friction),
            mn(p.mu_s * at.n)
        ),
        (Phase::Stuck, true) => format!(
            "the pull exceeds the static capacity μs N = {}: the block cannot stay at rest",
            mn(at.friction)
        ),
        (Phase::Slipping, _) => format!("dynamic friction F_f = μd N = {}", mn(at.friction)),
    };
    format!(
        "A block of mass m = {m} rests on a table and is pulled to the right by a constant force \
         F = {F}. Under it, through a slot in the table narrower than the block, a spring of \
         stiffness k = {k} carries a second mass m' = m = {m} that oscillates with period \
         T = {T}, so the spring's force on the block is S(t) = W cos ωt and the normal force \
         N(t) = W + S(t) = W (1 + cos ωt) swings between 0 and 2W = {N2}, with W = mg = {W}. \
         Friction coefficients μs = {mus}, μd = {mud}. Free-body diagram of the block at \
         {instant}: W = {W} down, the spring's force {S} {dir}, N = {N} up, so that the \
         vertical forces balance; {friction_words}. Force arrows to one scale.",
        m = grams(p.mass),
        F = mn(p.force),
        k = plain(p.k, "N/m"),
        T = ms(p.period()),
        N2 = mn(2.0 * w),
        W = mn(w),
        S = mn(at.spring.abs()),
        dir = if at.spring >= 0.0 { "down" } else { "up" },
        mus = num(p.mu_s),
        mud = num(p.mu_d),
        N = mn(at.n),
        instant = at.words,
    )
}

fn draw(p: &PulledMassParams, phase: Phase, labels: Labels) -> String {
    let w = p.weight();
    let f = p.force;
    let immediate = f > 2.0 * p.mu_s * w;
    let at = instant(p, phase);
    let biggest = [w, f, at.n, at.friction, at.spring.abs()]
        .into_iter()
        .fold(0.0, f64::max);
    let scale = LONGEST / biggest;
    let len = |force: f64| (force.abs() * scale).max(HEAD_LEN + 4.0);

    // Vertical room: the longest arrow up from the block's top and down from its bottom.
    let up = len(at.n).max(if at.spring < 0.0 { len(at.spring) } else { 0.0 });
    let down = len(w).max(if at.spring > 0.0 { len(at.spring) } else { 0.0 });
    let (half_w, half_h) = (40.0, 26.0);
    let upper = 70.0 + up;
    let (bx, by) = (430.0, upper + half_h);
    let lower = by + half_h;
    let y0 = lower + (down + 40.0).max(140.0);
    let height = y0 + 80.0;

    let mut s = Svg::sized(WIDTH, height, SUB);
    let title = format!(
        "Pulled mass, {}: the block on the table, spring and hanging mass, and the forces on \
         the block at {}",
        phase.words(),
        at.words
    );
    s.open(&title, &description(p, phase, labels, &at));

    // The apparatus, left: the block rests on both slabs of the table, level with the bottom
    // of the free-body diagram; the spring passes through the slot between them.
    let a = APPARATUS;
    let cx = 100.0;
    let top = lower;
    let slot = a.slot_half;
    s.text(10.0, 28.0, "start", FONT, &format!("{}:", phase.words()));
    s.text(10.0, 52.0, "start", FONT, &format!("drawn at {}", at.words));
    s.rect(10.0, top, cx - slot - 10.0, a.table, 0.18, 1.2);
    s.rect(cx + slot, top, 170.0 - cx - slot, a.table, 0.18, 1.2);
    let (bw, bh) = (a.block_width, a.block_height);
    s.rect(cx - bw / 2.0, top - bh, bw, bh, 0.12, 1.6);
    s.text(
        cx,
        top - bh / 2.0 + 7.0,
        "middle",
        FONT,
        &format!("m = {}", grams(p.mass)),
    );
    let hang_y = top + a.hang;
    s.spring(cx, top, hang_y, a.coils, a.coil_half, PURPLE);
    s.rect(
        cx - a.mass_width / 2.0,
        hang_y,
        a.mass_width,
        a.mass_height,
        0.12,
        1.6,
    );
    s.text(cx + 38.0, hang_y + 22.0, "start", FONT, "m' = m");
    s.text(
        cx + 16.0,
        top + 56.0,
        "start",
        FONT,
        &format!("k = {}", plain(p.k, "N/m")),
    );
    let fy = top - bh / 2.0;
    let stub = cx + bw / 2.0 + a.pull_stub;
    s.line(cx + bw / 2.0, fy, stub, fy, INK, 1.5);
    s.arrow(None, (stub, fy), (stub + a.pull_arrow, fy), BLUE, 3.0);
    s.text(190.0, fy - 12.0, "middle", FONT, "F");

    // The free-body diagram of the block, right.
    let (left, right) = (bx - half_w, bx + half_w);
    s.text(bx, 28.0, "middle", FONT, "forces on the block");
    s.rect(left, upper, 2.0 * half_w, 2.0 * half_h, 0.12, 1.6);
    s.text(bx, by + 7.0, "middle", FONT, "m");
    let (xl, xr) = (bx - 20.0, bx + 20.0);

    // Normal reaction of the table: up, left of the centre, its label left of its tip.
    let n_tip = upper - len(at.n);
    s.arrow(Some("force-n"), (xl, upper), (xl, n_tip), GREEN, 3.0);
    s.text(
        xl - 10.0,
        n_tip + 16.0,
        "end",
        FONT,
        &labels.derived("N", mn(at.n)),
    );
    // Weight: down, left of the centre.
    let w_tip = lower + len(w);
    s.arrow(Some("force-w"), (xl, lower), (xl, w_tip), INK, 3.0);
    let w_label = match labels {
        Labels::Computed => format!("W = {}", mn(w)),
        Labels::Givens => "W = mg".to_string(),
    };
    s.text(xl - 10.0, w_tip - 2.0, "end", FONT, &w_label);
    // The spring's force on the block: down while stretched (S > 0), else up; right of the
    // centre, its label right of its tip.
    let (s_from, s_tip) = if at.spring >= 0.0 {
        (lower, lower + len(at.spring))
    } else {
        (upper, upper - len(at.spring))
    };
    s.arrow(Some("force-spring"), (xr, s_from), (xr, s_tip), PURPLE, 3.0);
    let s_y = if at.spring >= 0.0 {
        s_tip - 2.0
    } else {
        s_tip + 16.0
    };
    s.text(
        xr + 10.0,
        s_y,
        "start",
        FONT,
        &labels.derived("S", mn(at.spring.abs())),
    );
    // The pull, from the right face.
    s.arrow(
        Some("force-f"),
        (right, by),
        (right + len(f), by),
        BLUE,
        3.0,
    );
    s.text(
        right + 6.0,
        by - 12.0,
        "start",
        FONT,
        &format!("F = {}", mn(f)),
    );
    // Friction along the bottom face, against the (coming) motion.
    let ff_y = lower - 5.0;
    s.arrow(
        Some("force-friction"),
        (left, ff_y),
        (left - len(at.friction), ff_y),
        VERMILLION,
        3.0,
    );
    let ff_label = match (phase, immediate) {
        (Phase::Stuck, false) => "F_{f} = F ≤ μ_{s} N".to_string(),
        (Phase::Stuck, true) => labels.derived("F_{f} = μ_{s} N", mn(at.friction)),
        (Phase::Slipping, _) => format!("F_{{f}} = μ_{{d}} N = {}", mn(at.friction)),
    };
    s.text(left - 6.0, lower + 24.0, "end", FONT, &ff_label);
    // Velocity (slipping) or v = 0 (stuck), under the pull.
    match phase {
        Phase::Slipping => {
            s.arrow(
                None,
                (right + 8.0, by + 22.0),
                (right + 58.0, by + 22.0),
                ORANGE,
                4.0,
            );
            s.text(right + 64.0, by + 29.0, "start", FONT, "v");
        }
        Phase::Stuck => s.text(right + 8.0, by + 34.0, "start", FONT, "v = 0"),
    }

    // Below: the vertical balance at the drawn instant, the law of S and N, the coefficients
    // and the force scale.
    let (ups, downs) = if at.spring >= 0.0 {
        ("N", "W + S")
    } else {
        ("N + S", "W")
    };
    let balance = match labels {
        Labels::Computed => {
            let (up, down) = if at.spring >= 0.0 {
                (
                    num(at.n * 1e3),
                    format!("{} + {}", num(w * 1e3), num(at.spring * 1e3)),
                )
            } else {
                (
                    format!("{} + {}", num(at.n * 1e3), num(-at.spring * 1e3)),
                    num(w * 1e3),
                )
            };
            format!("vertical: {ups} = {downs}: {up} = {down} mN")
        }
        Labels::Givens => format!("vertical: {ups} = {downs}"),
    };
    s.text(10.0, y0, "start", FONT, &balance);
    s.text(
        10.0,
        y0 + 24.0,
        "start",
        FONT,
        "S = W cos ωt, N(t) = W(1 + cos ωt)",
    );
    let coefficients = match labels {
        Labels::Computed => format!(
            "μ_{{s}} = {}, μ_{{d}} = {}, φ = F/W = {}, T = {}",
            num(p.mu_s),
            num(p.mu_d),
            num(f / w),
            ms(p.period())
        ),
        Labels::Givens => format!(
            "μ_{{s}} = {}, μ_{{d}} = {}; m' oscillates: T = 2π√(m'/k)",
            num(p.mu_s),
            num(p.mu_d)
        ),
    };
    s.text(10.0, y0 + 48.0, "start", FONT, &coefficients);
    let bar = 0.1 * scale;
    s.line(10.0, y0 + 70.0, 10.0 + bar, y0 + 70.0, INK, 3.0);
    s.text(18.0 + bar, y0 + 76.0, "start", FONT, "100 mN (force scale)");
    s.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The (class, x1, y1, x2, y2) of each force arrow's shaft.
    fn forces(svg: &str) -> Vec<(String, f64)> {
        let doc = roxmltree::Document::parse(svg).unwrap();
        doc.descendants()
            .filter(|n| n.has_tag_name("g"))
            .filter_map(|g| {
                let class = g.attribute("class")?.strip_prefix("force-")?.to_string();
                let line = g.children().find(|c| c.has_tag_name("line"))?;
                let y = |a| line.attribute(a).unwrap().parse::<f64>().unwrap();
                let poly = g.children().find(|c| c.has_tag_name("polygon"))?;
                let tip: Vec<f64> = poly
                    .attribute("points")
                    .unwrap()
                    .split([' ', ','])
                    .take(2)
                    .map(|v| v.parse().unwrap())
                    .collect();
                // Signed vertical length, up positive, from the shaft's start to the tip.
                Some((class, y("y1") - tip[1]))
            })
            .collect()
    }

    #[test]
    fn the_vertical_forces_on_the_block_balance_at_the_drawn_instant() {
        let slipping = PulledMassParams::default();
        let mut stuck = slipping;
        stuck.force = 0.05;
        for (p, phase) in [(&slipping, Phase::Slipping), (&stuck, Phase::Stuck)] {
            let svg = pulled_mass(p, phase);
            let arrows = forces(&svg);
            let vertical: f64 = arrows
                .iter()
                .filter(|(c, _)| ["n", "w", "spring"].contains(&c.as_str()))
                .map(|(_, dy)| dy)
                .sum();
            assert_eq!(arrows.len(), 5, "{arrows:?}");
            // Arrows to one scale: the sum of the vertical arrows is zero to the rounding of
            // the coordinates (0.1 px) and the minimum length of a tiny force.
            assert!(vertical.abs() < 0.5, "{phase:?}: {arrows:?}");
            let at = instant(p, phase);
            assert!((at.n - p.weight() - at.spring).abs() < 1e-12);
            let text = svg.replace(['\u{2212}'], "-");
            assert!(text.contains("vertical:"), "{svg}");
        }
    }

    #[test]
    fn the_block_rests_on_the_table_and_is_wider_than_the_slot() {
        let svg = pulled_mass(&PulledMassParams::default(), Phase::Stuck);
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let rects: Vec<[f64; 4]> = doc
            .descendants()
            .filter(|n| n.has_tag_name("rect"))
            .map(|r| {
                ["x", "y", "width", "height"].map(|a| r.attribute(a).unwrap().parse().unwrap())
            })
            .collect();
        let (slab_l, slab_r, block) = (rects[0], rects[1], rects[2]);
        // The block's bottom is the table's top, and it overlaps both slabs.
        assert_eq!(block[1] + block[3], slab_l[1]);
        assert!(block[0] < slab_l[0] + slab_l[2] && block[0] + block[2] > slab_r[0]);
    }

    #[test]
    fn every_glyph_is_at_least_the_legible_size() {
        for svg in [
            pulled_mass(&PulledMassParams::default(), Phase::Slipping),
            pulled_mass_givens(&PulledMassParams::default()),
        ] {
            let doc = roxmltree::Document::parse(&svg).unwrap();
            for n in doc
                .descendants()
                .filter(|n| n.attribute("font-size").is_some())
            {
                let size: f64 = n.attribute("font-size").unwrap().parse().unwrap();
                assert!(size >= SUB, "{size}");
            }
        }
    }
}
