//! The sketch of the belt (docs/belt.md): the apparatus on the left (a wall, the spring k, the
//! block of mass m on the belt moving at v_b) and the free-body diagram of the block on the
//! right, every force drawn to one scale at one stated instant, with values that balance.
//!
//! ```text
//! stuck:    at the end of the stick, x = x_s: the spring k x_s = μs m g left, the static
//!           friction at its limit μs N right (B2); v = v_b
//! slipping: at the middle of the slip, x = x_d: the spring k x_d = μd m g left, the dynamic
//!           friction μd N right (B3): the fastest backward motion, v = −ω A (B14)
//! vertical: N = W = m g in both
//! ```
//!
//! Drawn for a printed width of one A4 column (90.5 mm), as the pulled mass's: the canvas is
//! [`WIDTH`] px wide and no glyph is smaller than [`SUB`] px (8 pt or more in print).

use serde::Serialize;

use super::formula::{self, ClosedForm};
use super::BeltParams;
use crate::present::vocab::Phase;
use crate::report::sketch::{
    mm_text, num, plain, Svg, GREEN, HEAD_LEN, INK, ORANGE, PURPLE, VERMILLION,
};

/// Canvas width (px of the SVG user space).
const WIDTH: f64 = 600.0;
/// Label size and the smallest glyph, subscripts included (px).
const FONT: f64 = 20.0;
const SUB: f64 = 19.0;
/// The longest force arrow (px).
const LONGEST: f64 = 110.0;

/// The apparatus as the sketch draws it (px of the sketch's user space, [`WIDTH`] wide): the
/// explorer's animation (the belt's `Explore::apparatus`) draws the same wall, spring, block
/// and belt, the block moved by the computed motion and the belt's marks by v_b t.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BeltApparatus {
    /// Canvas width and label size (px).
    pub width: f64,
    pub font: f64,
    /// The wall: its left edge, width and height above the belt (px).
    pub wall_x: f64,
    pub wall_width: f64,
    pub wall_height: f64,
    /// The block: its size and the sketch's drawn position of its left face (px).
    pub block_width: f64,
    pub block_height: f64,
    pub block_x: f64,
    /// The belt: its left end, its length in the sketch, its thickness and its rollers'
    /// radius (px).
    pub belt_left: f64,
    pub belt_length: f64,
    pub belt_height: f64,
    pub roller_r: f64,
    /// The spring: zigzags and their half-width (px).
    pub coils: usize,
    pub coil_half: f64,
}

/// The belt's apparatus, in the sketch and in the explorer.
pub const APPARATUS: BeltApparatus = BeltApparatus {
    width: WIDTH,
    font: FONT,
    wall_x: 14.0,
    wall_width: 12.0,
    wall_height: 120.0,
    block_width: 90.0,
    block_height: 56.0,
    block_x: 150.0,
    belt_left: 40.0,
    belt_length: 250.0,
    belt_height: 14.0,
    roller_r: 7.0,
    coils: 5,
    coil_half: 8.0,
};

/// The drawn instant: its words, the position x (m), the speed v (m/s), the spring's force on
/// the block (N, toward the wall for x > 0) and the friction on it (N, in the belt's direction).
struct Instant {
    words: &'static str,
    x: f64,
    v: f64,
    spring: f64,
    friction: f64,
}

fn instant(p: &BeltParams, c: &ClosedForm, phase: Phase) -> Instant {
    match phase {
        Phase::Stuck => Instant {
            words: "the end of the stick (x = x_s)",
            x: c.x_s,
            v: p.v_b,
            spring: p.k * c.x_s,
            friction: p.k * c.x_s,
        },
        Phase::Slipping => Instant {
            words: "the middle of the slip (x = x_d)",
            x: c.x_d,
            v: c.v_min,
            spring: p.k * c.x_d,
            friction: p.mu_d * p.mass * p.g,
        },
    }
}

/// A force in N, to four significant digits.
fn newton(f: f64) -> String {
    plain(f, "N")
}

/// A speed in m/s, shown in mm/s.
fn mm_per_s(v: f64) -> String {
    plain(v * 1e3, "mm/s")
}

fn description(p: &BeltParams, c: &ClosedForm, phase: Phase, at: &Instant) -> String {
    let w = p.mass * p.g;
    let friction_words = match phase {
        Phase::Stuck => format!(
            "static friction F_f = k x = {} in the belt's direction balances the spring, at its \
             limit μs N = {}: the stick ends here",
            newton(at.friction),
            newton(p.mu_s * w)
        ),
        Phase::Slipping => format!(
            "dynamic friction F_f = μd N = {} in the belt's direction (the block moves slower \
             than the belt) balances the spring: the block is at its fastest backward speed",
            newton(at.friction)
        ),
    };
    format!(
        "A block of mass m = {m} lies on a belt moving to the right at v_b = {vb} and is held \
         back by a spring of stiffness k = {k} fixed to a wall; x is the stretch of the spring. \
         Friction coefficients μs = {mus}, μd = {mud}; the block sticks while |k x| ≤ μs m g, \
         the paper's stick condition with the spring as the drive. Free-body diagram of the \
         block at {instant}, x = {x}, v = {v}: W = m g = {W} down, N = {W} up; the spring's \
         force k x = {S} toward the wall; {friction_words}. Force arrows to one scale.",
        m = plain(p.mass, "kg"),
        vb = mm_per_s(p.v_b),
        k = plain(p.k, "N/m"),
        mus = num(p.mu_s),
        mud = num(p.mu_d),
        instant = at.words,
        x = mm_text(at.x * 1e3),
        v = mm_per_s(at.v),
        W = newton(w),
        S = newton(at.spring),
    ) + &format!(
        " The cycle: slip of {} s, stick of {} s, period {} s.",
        num(c.t_slip),
        num(c.t_stick),
        num(c.period)
    )
}

/// What the block does in `phase`: the block sticks to the moving belt, it is not at rest.
fn phase_words(phase: Phase) -> &'static str {
    match phase {
        Phase::Stuck => "sticking, carried by the belt",
        Phase::Slipping => "slipping on the belt",
    }
}

/// The belt with the forces of `phase` and their values (reports, handouts).
///
/// [`Phase::Stuck`] is drawn at the end of the stick, x = x_s (B2), where the static friction
/// reaches μs N; [`Phase::Slipping`] at the middle of the slip, x = x_d (B3), where the spring
/// and the dynamic friction balance and the block runs back fastest, v = −ω A (B14).
pub fn belt(p: &BeltParams, phase: Phase) -> String {
    let c = formula::evaluate(p);
    let w = p.mass * p.g;
    let at = instant(p, &c, phase);
    let biggest = [w, at.spring, at.friction].into_iter().fold(0.0, f64::max);
    let scale = LONGEST / biggest;
    let len = |force: f64| (force.abs() * scale).max(HEAD_LEN + 4.0);

    let (half_w, half_h) = (40.0, 26.0);
    let upper = 90.0 + len(w);
    let (bx, by) = (420.0, upper + half_h);
    let lower = by + half_h;
    let y0 = lower + len(w) + 60.0;
    let height = y0 + 110.0;

    let mut s = Svg::sized(WIDTH, height, SUB);
    let title = format!(
        "Block on a moving belt, {}: the wall, the spring, the block on the belt, and the \
         forces on the block at {}",
        phase_words(phase),
        at.words
    );
    s.open(&title, &description(p, &c, phase, &at));

    // The apparatus, left: the wall, the spring to the block, the block on the belt.
    s.text(
        10.0,
        28.0,
        "start",
        FONT,
        &format!("{}:", phase_words(phase)),
    );
    let drawn_at = at.words.replace("x_s", "x_{s}").replace("x_d", "x_{d}");
    s.text(10.0, 52.0, "start", FONT, &format!("drawn at {drawn_at}"));
    apparatus(&mut s, p, lower);

    // The free-body diagram of the block, right.
    let (left, right) = (bx - half_w, bx + half_w);
    s.text(bx, 28.0, "middle", FONT, "forces on the block");
    s.rect(left, upper, 2.0 * half_w, 2.0 * half_h, 0.12, 1.6);
    s.text(bx, by + 7.0, "middle", FONT, "m");
    // Normal force up and weight down, both at the centre line: N = W.
    let n_tip = upper - len(w);
    s.arrow(Some("force-n"), (bx, upper), (bx, n_tip), GREEN, 3.0);
    s.text(
        bx + 10.0,
        n_tip + 16.0,
        "start",
        FONT,
        &format!("N = {}", newton(w)),
    );
    let w_tip = lower + len(w);
    s.arrow(Some("force-w"), (bx, lower), (bx, w_tip), INK, 3.0);
    s.text(
        bx + 10.0,
        w_tip - 2.0,
        "start",
        FONT,
        &format!("W = {}", newton(w)),
    );
    // The spring's force toward the wall, from the left face.
    s.arrow(
        Some("force-spring"),
        (left, by - 10.0),
        (left - len(at.spring), by - 10.0),
        PURPLE,
        3.0,
    );
    s.text(
        left - 6.0,
        by - 22.0,
        "end",
        FONT,
        &format!("k x = {}", newton(at.spring)),
    );
    // Friction along the bottom face, in the belt's direction.
    let ff_y = lower - 5.0;
    s.arrow(
        Some("force-friction"),
        (right, ff_y),
        (right + len(at.friction), ff_y),
        VERMILLION,
        3.0,
    );
    let ff_label = match phase {
        Phase::Stuck => "F_{f} ≤ μ_{s} N",
        Phase::Slipping => "F_{f} = μ_{d} N",
    };
    s.text(right + 4.0, lower + 26.0, "start", FONT, ff_label);
    // The velocity: with the belt while stuck, back toward the wall at mid-slip.
    let v_y = upper - 14.0;
    let (v_from, v_to) = if at.v >= 0.0 {
        (right + 8.0, right + 58.0)
    } else {
        (right + 58.0, right + 8.0)
    };
    s.arrow(None, (v_from, v_y), (v_to, v_y), ORANGE, 4.0);
    let v_label = match phase {
        Phase::Stuck => "v = v_{b}",
        Phase::Slipping => "v = −ωA",
    };
    s.text(right + 8.0, v_y - 14.0, "start", FONT, v_label);

    // Below: the balance at the drawn instant, the stick condition and the cycle.
    s.text(
        10.0,
        y0,
        "start",
        FONT,
        &format!(
            "horizontal: k x = F_{{f}}: {} = {} N; vertical: N = W",
            num(at.spring),
            num(at.friction)
        ),
    );
    let limit = match phase {
        Phase::Stuck => format!(
            "static friction at its limit μ_{{s}} N = {}; v = v_{{b}} = {}",
            newton(p.mu_s * w),
            mm_per_s(p.v_b)
        ),
        Phase::Slipping => format!(
            "μ_{{d}} N = {}; v = −ωA = {}",
            newton(at.friction),
            mm_per_s(at.v)
        ),
    };
    s.text(10.0, y0 + 24.0, "start", FONT, &limit);
    s.text(
        10.0,
        y0 + 48.0,
        "start",
        FONT,
        "stick while |k x| ≤ μ_{s} m g; slip about x_{d} = μ_{d} m g/k",
    );
    s.text(
        10.0,
        y0 + 72.0,
        "start",
        FONT,
        &format!(
            "μ_{{s}} = {}, μ_{{d}} = {}, x_{{s}} = {}, x_{{d}} = {}",
            num(p.mu_s),
            num(p.mu_d),
            mm_text(c.x_s * 1e3),
            mm_text(c.x_d * 1e3)
        ),
    );
    // A round force (a power of ten) between a tenth of the longest arrow and the longest.
    let unit = 10f64.powf(biggest.log10().floor());
    let bar = unit * scale;
    s.line(10.0, y0 + 94.0, 10.0 + bar, y0 + 94.0, INK, 3.0);
    s.text(
        18.0 + bar,
        y0 + 100.0,
        "start",
        FONT,
        &format!("{} (force scale)", newton(unit)),
    );
    s.finish()
}

/// The belt at t = 0 labelled with the given values only, for a worksheet: the block on the
/// belt at x = 0 (the spring unstretched), the forces named, not numbered; ω, x_s, x_d, Δ and
/// the motion are the student's to work out.
pub fn belt_givens(p: &BeltParams) -> String {
    let belt_top = 190.0;
    let height = belt_top + 150.0;
    let mut s = Svg::sized(WIDTH, height, SUB);
    let description = format!(
        "A block of mass m = {m} lies on a belt moving to the right at v_b = {vb} and is held \
         back by a spring of stiffness k = {k} fixed to a wall; x is the stretch of the spring, \
         x = 0 at t = 0, when the block is carried by the belt. Friction coefficients μs = {mus}, \
         μd = {mud}, g = {g}. The forces on the block: weight W = m g, normal force N, the \
         spring's force k x toward the wall, friction F_f.",
        m = plain(p.mass, "kg"),
        vb = mm_per_s(p.v_b),
        k = plain(p.k, "N/m"),
        mus = num(p.mu_s),
        mud = num(p.mu_d),
        g = plain(p.g, "m/s²"),
    );
    s.open(
        "Block on a moving belt at t = 0: the wall, the spring, the block on the belt",
        &description,
    );
    s.text(
        10.0,
        28.0,
        "start",
        FONT,
        "at t = 0: x = 0, carried by the belt",
    );
    s.text(
        10.0,
        52.0,
        "start",
        FONT,
        &format!("m = {}", plain(p.mass, "kg")),
    );
    apparatus(&mut s, p, belt_top);
    let y0 = belt_top + 80.0;
    s.text(
        10.0,
        y0,
        "start",
        FONT,
        &format!(
            "μ_{{s}} = {}, μ_{{d}} = {}, g = {}",
            num(p.mu_s),
            num(p.mu_d),
            plain(p.g, "m/s²")
        ),
    );
    s.text(
        10.0,
        y0 + 24.0,
        "start",
        FONT,
        "forces on the block: W = m g, N, k x (toward the wall), F_{f}",
    );
    s.text(
        10.0,
        y0 + 48.0,
        "start",
        FONT,
        "stick while |k x| ≤ μ_{s} N; slipping, F_{f} = μ_{d} N",
    );
    s.finish()
}

/// The apparatus at the left of the sketch, its belt's top at `belt_top` (px): the wall, the
/// spring k to the block m on the belt, the belt's speed v_b.
fn apparatus(s: &mut Svg, p: &BeltParams, belt_top: f64) {
    let a = APPARATUS;
    let wall_face = a.wall_x + a.wall_width;
    s.rect(
        a.wall_x,
        belt_top - a.wall_height,
        a.wall_width,
        a.wall_height,
        0.3,
        1.4,
    );
    let (bw, bh) = (a.block_width, a.block_height);
    let block_x = a.block_x;
    s.rect(block_x, belt_top - bh, bw, bh, 0.12, 1.6);
    s.text(
        block_x + bw / 2.0,
        belt_top - bh / 2.0 + 7.0,
        "middle",
        FONT,
        "m",
    );
    zigzag(
        s,
        wall_face,
        block_x,
        belt_top - bh / 2.0,
        a.coils,
        a.coil_half,
    );
    s.text(
        (wall_face + block_x) / 2.0,
        belt_top - bh / 2.0 - 18.0,
        "middle",
        FONT,
        &format!("k = {}", plain(p.k, "N/m")),
    );
    // The belt: a band over two rollers, its speed along the top.
    let (r, belt_right) = (a.roller_r, a.belt_left + a.belt_length);
    s.rect(
        a.belt_left,
        belt_top,
        a.belt_length,
        a.belt_height,
        0.18,
        1.2,
    );
    s.circle_styled(a.belt_left + r, belt_top + r, r, INK, 0.15, 1.2);
    s.circle_styled(belt_right - r, belt_top + r, r, INK, 0.15, 1.2);
    s.arrow(
        Some("belt-speed"),
        (60.0, belt_top + 36.0),
        (150.0, belt_top + 36.0),
        ORANGE,
        3.0,
    );
    s.text(
        158.0,
        belt_top + 43.0,
        "start",
        FONT,
        &format!("v_{{b}} = {}", mm_per_s(p.v_b)),
    );
}

/// A horizontal coil spring from x1 to x2 at height y: straight ends, `coils` zigzags.
fn zigzag(s: &mut Svg, x1: f64, x2: f64, y: f64, coils: usize, half: f64) {
    let end = 10.0_f64.min((x2 - x1) / 4.0);
    let (a, b) = (x1 + end, x2 - end);
    let n = 2 * coils.max(1);
    let step = (b - a) / n as f64;
    let mut pts = vec![(x1, y), (a, y)];
    for i in 0..n {
        let side = if i % 2 == 0 { -half } else { half };
        pts.push((a + step * (i as f64 + 0.5), y + side));
    }
    pts.push((b, y));
    pts.push((x2, y));
    let pts: Vec<String> = pts
        .iter()
        .map(|(x, y)| {
            format!(
                "{},{}",
                crate::report::sketch::c(*x),
                crate::report::sketch::c(*y)
            )
        })
        .collect();
    s.raw(&format!(
        "<polyline class=\"spring\" points=\"{}\" fill=\"none\" stroke=\"{PURPLE}\" \
         stroke-width=\"2.2\" stroke-linejoin=\"round\"/>\n",
        pts.join(" ")
    ));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::belt::test_sets as sets;
    use crate::report::sketch::force_arrows as forces;

    #[test]
    fn the_forces_on_the_block_balance_at_the_drawn_instant() {
        for p in sets() {
            for phase in [Phase::Stuck, Phase::Slipping] {
                let svg = belt(&p, phase);
                let arrows = forces(&svg);
                assert_eq!(arrows.len(), 4, "{arrows:?}");
                let horizontal: f64 = arrows.iter().map(|(_, dx, _)| dx).sum();
                let vertical: f64 = arrows.iter().map(|(_, _, dy)| dy).sum();
                // Arrows to one scale, rounded to 0.1 px.
                assert!(horizontal.abs() < 0.3, "{phase:?} {p:?}: {arrows:?}");
                assert!(vertical.abs() < 0.3, "{phase:?} {p:?}: {arrows:?}");
            }
        }
    }

    #[test]
    fn the_sketch_is_well_formed_and_names_its_phase_law_and_speed() {
        for p in sets() {
            for (phase, want, not, v) in [
                (Phase::Stuck, "≤ μs N", "= μd N", "v = vb"),
                (Phase::Slipping, "= μd N", "≤ μs N", "v = −ωA"),
            ] {
                let svg = belt(&p, phase);
                let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("{e}"));
                let root = doc.root_element();
                assert_eq!(root.attribute("role"), Some("img"));
                assert!(root.attribute("viewBox").unwrap().starts_with("0 0 600 "));
                assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
                let texts: Vec<String> = doc
                    .descendants()
                    .filter(|n| n.has_tag_name("text"))
                    .map(|n| {
                        n.descendants()
                            .filter_map(|t| t.text().filter(|_| t.is_text()))
                            .collect()
                    })
                    .collect();
                assert!(texts.iter().any(|t| t.contains(want)), "{texts:?}");
                assert!(!texts.iter().any(|t| t.contains(not)), "{texts:?}");
                assert!(texts.iter().any(|t| t == v), "{texts:?}");
                assert!(texts.iter().any(|t| t.starts_with("vb = ")), "{texts:?}");
            }
        }
    }

    #[test]
    fn the_description_carries_the_parameters_and_the_drawn_instant() {
        let p = BeltParams::default();
        let svg = belt(&p, Phase::Slipping);
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let desc = doc
            .descendants()
            .find(|n| n.has_tag_name("desc"))
            .and_then(|n| n.text())
            .unwrap()
            .to_string();
        // x_d = μd m g / k = 0.4 · 0.5 · 9.81 / 50 m = 39.24 mm; μd m g = 1.962 N.
        for want in [
            "m = 0.5 kg",
            "v_b = 50 mm/s",
            "k = 50 N/m",
            "x = 39.24 mm",
            "1.962 N",
        ] {
            assert!(desc.contains(want), "{want}: {desc}");
        }
        assert_eq!(svg, belt(&p, Phase::Slipping));
    }
}
