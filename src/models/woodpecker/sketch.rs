//! The sketch of the falling woodpecker (paper Sec. 3, Fig. 13): the sleeve on the vertical
//! pole, tilted so that it touches the pole at two contacts h apart, the spring hanging the bird
//! at lever arm l, and the forces of the stated phase; drawn with the shared helpers of
//! [`crate::report::sketch`].

use serde::Serialize;

use super::WoodpeckerParams;
use crate::report::sketch::*;

/// Width of the sketch (px of the SVG user space).
const WIDTH: f64 = 900.0;
/// The woodpecker's label size and smallest glyph, subscripts included (px): 29 px of 900
/// print at 8.3 pt across a 90.5 mm column (A4, two columns), the width it is printed at.
const W_FONT: f64 = 30.0;
const W_SUB: f64 = 29.0;

/// The falling woodpecker of Sec. 3 (paper Fig. 13): the sleeve on the vertical pole, tilted
/// (greatly exaggerated) so that it touches the pole at two points h apart; the spring hangs
/// the bird at lever arm l from the pole's axis; its coordinate z = z0 + d0 cos ωt.
///
/// Lengths (h, l, z0, d0) are to one scale, 14 px/mm unless that would not fit; the pole's
/// width and the clearance of the hole are not. The spring force is drawn pushing the sleeve
/// down (F_e > 0, the spring stretched), so the contacts are top-left and bottom-right.
pub fn woodpecker(p: &WoodpeckerParams, phase: Phase) -> String {
    draw_woodpecker(p, phase, Labels::Computed)
}

/// The woodpecker at rest labelled with the given values only, for a worksheet (W_S, λ, T and
/// the spring force's range are the student's to work out).
pub fn woodpecker_givens(p: &WoodpeckerParams) -> String {
    draw_woodpecker(p, Phase::Stuck, Labels::Givens)
}

/// The woodpecker's apparatus as the sketch draws it (px of the sketch's user space, [`WIDTH`]
/// wide): the explorer's animation (src/report/explorer.rs serialises it) draws the same pole,
/// tilted sleeve with its arm l, spring and bird, to the same scale ([`woodpecker_layout`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WoodpeckerApparatus {
    /// Canvas width and label size (px).
    pub width: f64,
    pub font: f64,
    /// The largest scale (px/mm), and the px that l, h and the bird's range z0 ± d0 (with
    /// z = 0) may take at most; the smallest drawn l and h (px).
    pub max_scale: f64,
    pub l_span: f64,
    pub h_span: f64,
    pub z_span: f64,
    pub l_min: f64,
    pub h_min: f64,
    /// Pole half-width, the sleeve's clearance around it, its wall and the arm's half-thickness
    /// (px).
    pub pole_half: f64,
    pub clearance: f64,
    pub wall: f64,
    pub arm_half: f64,
    /// The bird's radius, the spring's length at z = 0, its zigzags and their half-width (px).
    pub bird_r: f64,
    pub natural: f64,
    pub coils: usize,
    pub coil_half: f64,
}

/// The woodpecker's apparatus, in the sketch and in the explorer.
pub const WOODPECKER_APPARATUS: WoodpeckerApparatus = WoodpeckerApparatus {
    width: WIDTH,
    font: W_FONT,
    max_scale: 14.0,
    l_span: 250.0,
    h_span: 130.0,
    z_span: 260.0,
    l_min: 70.0,
    h_min: 24.0,
    pole_half: 12.0,
    clearance: 2.5,
    wall: 14.0,
    arm_half: 6.0,
    bird_r: 19.0,
    natural: 44.0,
    coils: 8,
    coil_half: 11.0,
};

/// The drawn sizes of one parameter set: scale (px/mm), l and h (px), the sleeve's tilt θ
/// (rad, clockwise) and its hole's half-height b (px).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WoodpeckerLayout {
    pub scale: f64,
    pub l_px: f64,
    pub h_px: f64,
    pub theta: f64,
    pub b: f64,
}

/// The sizes [`woodpecker`] draws `p` at.
pub fn woodpecker_layout(p: &WoodpeckerParams) -> WoodpeckerLayout {
    let g = WOODPECKER_APPARATUS;
    let mm = 1e3;
    let (l_mm, h_mm, z0_mm, d0_mm) = (p.l * mm, p.h * mm, p.z0 * mm, p.d0 * mm);
    let z_lo = (z0_mm - d0_mm.abs()).min(0.0);
    let z_hi = (z0_mm + d0_mm.abs()).max(0.0);
    let scale = [
        g.max_scale,
        g.l_span / l_mm,
        g.h_span / h_mm,
        g.z_span / (z_hi - z_lo),
    ]
    .into_iter()
    .filter(|v| v.is_finite() && *v > 0.0)
    .fold(f64::INFINITY, f64::min);
    let scale = if scale.is_finite() {
        scale
    } else {
        g.max_scale
    };
    let h_px = (h_mm * scale).max(g.h_min);
    let (theta, b) = sleeve_tilt(g.pole_half + g.clearance, g.pole_half, h_px);
    WoodpeckerLayout {
        scale,
        l_px: (l_mm * scale).max(g.l_min),
        h_px,
        theta,
        b,
    }
}

fn draw_woodpecker(p: &WoodpeckerParams, phase: Phase, labels: Labels) -> String {
    let g = WOODPECKER_APPARATUS;
    let mm = 1e3;
    let (l_mm, h_mm, z0_mm, d0_mm) = (p.l * mm, p.h * mm, p.z0 * mm, p.d0 * mm);
    let z_lo = (z0_mm - d0_mm.abs()).min(0.0);
    let WoodpeckerLayout {
        scale,
        l_px,
        theta,
        b,
        ..
    } = woodpecker_layout(p);

    let lambda = p.lambda();
    let ws = p.sleeve_weight();
    let fe_max = p.k * (p.z0 + p.d0.abs());
    let fe_min = p.k * (p.z0 - p.d0.abs());
    let n_max = lambda * fe_max.abs().max(fe_min.abs());
    let period = p.period();

    let mut s = Svg::sized(WIDTH, 0.0, W_SUB);
    let title = format!(
        "Falling woodpecker, {}: sleeve on the pole, spring and bird",
        phase.words()
    );
    let friction_words = match phase {
        Phase::Stuck => "static friction, up to μs N at each contact, holds the sleeve",
        Phase::Slipping => "dynamic friction μd N at each contact brakes the falling sleeve",
    };
    let desc = if labels == Labels::Givens {
        format!(
            "A sleeve of mass m_S = {ms} slides down a vertical pole. The spring (k = {k}) \
             carrying the bird (m_W = {mw}) acts on the sleeve at lever arm l = {l} from the \
             pole's axis; the sleeve tilts and touches the pole at two contacts h = {h} apart. \
             The spring coordinate z = z0 + d0 cos ωt has offset z0 = {z0} and amplitude \
             d0 = {d0}. Friction coefficients μs = {mus}, μd = {mud}. The tilt is exaggerated; \
             lengths to scale.",
            ms = grams(p.m_sleeve),
            k = plain(p.k, "N/m"),
            mw = grams(p.m_bird),
            l = mm_text(l_mm),
            h = mm_text(h_mm),
            z0 = mm_text(z0_mm),
            d0 = mm_text(d0_mm),
            mus = num(p.mu_s),
            mud = num(p.mu_d),
        )
    } else {
        format!(
            "A sleeve of mass m_S = {ms} (weight W_S = {ws}) slides down a vertical pole. The \
         spring (k = {k}) carrying the bird (m_W = {mw}) acts on the sleeve at lever arm \
         l = {l} from the pole's axis; the sleeve tilts and touches the pole at two contacts \
         h = {h} apart, each pressing with N = λ|F_e|, λ = l/h = {lambda}. The spring \
         coordinate z = z0 + d0 cos ωt has offset z0 = {z0} and amplitude d0 = {d0} (period \
         T = {T}), so the spring force F_e = k z ranges from {femin} to {femax} and N reaches \
         {nmax}. Friction coefficients μs = {mus}, μd = {mud}: {friction_words}. The tilt is \
         exaggerated; lengths to scale.",
            ms = grams(p.m_sleeve),
            ws = mn(ws),
            k = plain(p.k, "N/m"),
            mw = grams(p.m_bird),
            l = mm_text(l_mm),
            h = mm_text(h_mm),
            lambda = num(lambda),
            z0 = mm_text(z0_mm),
            d0 = mm_text(d0_mm),
            T = ms(period),
            femin = mn(fe_min),
            femax = mn(fe_max),
            nmax = mn(n_max),
            mus = num(p.mu_s),
            mud = num(p.mu_d),
        )
    };
    s.open(&title, &desc);
    s.text(
        20.0,
        36.0,
        "start",
        W_FONT,
        &format!("Falling woodpecker, {}", phase.words()),
    );

    // The sleeve: a hole of half-width a (pole + clearance) and half-height b, walls of
    // thickness `wall`, tilted clockwise by θ until the hole's top-left and bottom-right inner
    // corners touch the pole, with the contacts h apart vertically.
    let px = 300.0;
    let pole_half = g.pole_half;
    let wall = g.wall;
    let a = pole_half + g.clearance;
    let (cx, cy) = (px, 250.0);
    let rot = |dx: f64, dy: f64| {
        let (sn, cs) = theta.sin_cos();
        (cx + dx * cs - dy * sn, cy + dx * sn + dy * cs)
    };
    let c1 = rot(-a, -b);
    let c2 = rot(a, b);
    let arm_half = g.arm_half;
    let arm_len = l_px / theta.cos();
    let arm_end = rot(arm_len, arm_half);
    // The line of action of F_e: l from the pole's axis.
    let spring_x = px + l_px;

    // The spring's geometry first: the bird at z = z0 and the band its centre sweeps decide
    // where the lines of numbers below begin.
    let bird_r = g.bird_r;
    let z_zero = arm_end.1 + g.natural - z_lo.min(0.0) * scale;
    let y_of = |z_mm: f64| z_zero + z_mm * scale;
    let bird_y = y_of(z0_mm);
    let (band_top, band_bot) = (y_of(z0_mm - d0_mm.abs()), y_of(z0_mm + d0_mm.abs()));
    let f_len = 52.0;
    let w_top = cy + b * 0.3;
    let vy = w_top + 130.0;
    let info_top = [
        band_bot + 60.0,
        bird_y + 130.0,
        vy + 110.0,
        c2.1 + f_len + 110.0,
    ]
    .into_iter()
    .fold(0.0, f64::max);

    // The ring behind the pole, the pole, then the ring's two walls cut open in front.
    let ring = [
        rot(-a - wall, -b),
        rot(a + wall, -b),
        rot(a + wall, b),
        rot(-a - wall, b),
    ];
    s.polygon(&ring, INK, 0.08, 0.8);
    s.rect(
        px - pole_half,
        cy - b - 110.0,
        2.0 * pole_half,
        info_top - 30.0 - (cy - b - 110.0),
        0.1,
        1.2,
    );
    s.text(
        px + pole_half + 8.0,
        info_top - 40.0,
        "start",
        W_FONT,
        "pole",
    );
    let left_wall = [
        rot(-a - wall, -b),
        rot(-a, -b),
        rot(-a, b),
        rot(-a - wall, b),
    ];
    let right_wall = [
        rot(a, -b),
        rot(a + wall, -b),
        rot(a + wall, -arm_half),
        rot(arm_len, -arm_half),
        rot(arm_len, arm_half),
        rot(a + wall, arm_half),
        rot(a + wall, b),
        rot(a, b),
    ];
    s.polygon(&left_wall, INK, 0.25, 1.5);
    s.polygon(&right_wall, INK, 0.25, 1.5);
    for c in [c1, c2] {
        s.circle(c.0, c.1, 3.5, INK);
    }

    // h, along the pole's axis between the contacts' heights.
    s.dashed(c1.0, c1.1, px, c1.1, INK, 1.0);
    s.dashed(c2.0, c2.1, px, c2.1, INK, 1.0);
    s.dimension(Some("dim-h"), (px, c1.1), (px, c2.1), INK, 1.2);
    let left_of_sleeve = cx - a - wall - 14.0;
    s.text(
        left_of_sleeve,
        cy + 12.0,
        "end",
        W_FONT,
        &format!("h = {}", mm_text(h_mm)),
    );

    // Contact forces N (horizontal, pushing the sleeve off the pole) and friction (up the pole).
    let n_len = 62.0;
    s.arrow(
        Some("force-n"),
        (c1.0, c1.1),
        (c1.0 - n_len, c1.1),
        GREEN,
        3.0,
    );
    s.arrow(
        Some("force-n"),
        (c2.0, c2.1),
        (c2.0 + n_len, c2.1),
        GREEN,
        3.0,
    );
    s.text(
        c1.0 - n_len - 8.0,
        c1.1 + 10.0,
        "end",
        W_FONT,
        "N = λ|F_{e}|",
    );
    s.text(c2.0 + 20.0, c2.1 + 38.0, "start", W_FONT, "N = λ|F_{e}|");
    let f_label = match phase {
        Phase::Stuck => "F_{f} ≤ μ_{s} N",
        Phase::Slipping => "F_{f} = μ_{d} N",
    };
    s.arrow(
        Some("force-friction"),
        (c1.0, c1.1),
        (c1.0, c1.1 - f_len),
        VERMILLION,
        3.0,
    );
    s.text(
        c1.0 - 12.0,
        c1.1 - f_len / 2.0 - 6.0,
        "end",
        W_FONT,
        f_label,
    );
    s.arrow(
        Some("force-friction"),
        (c2.0, c2.1 + f_len),
        (c2.0, c2.1),
        VERMILLION,
        3.0,
    );
    s.text(c2.0 + 10.0, c2.1 + f_len + 24.0, "start", W_FONT, f_label);

    // Weight of the sleeve, from the left wall.
    let wx = cx - a - wall / 2.0 - 2.0;
    s.arrow(Some("force-w"), (wx, w_top), (wx, w_top + 80.0), INK, 3.0);
    s.text(
        wx - 10.0,
        w_top + 78.0,
        "end",
        W_FONT,
        &labels.derived("W_{S}", mn(ws)),
    );

    // Velocity of the sleeve, or "v = 0".
    let vx = 150.0;
    match phase {
        Phase::Slipping => {
            s.arrow(None, (vx, vy), (vx, vy + 70.0), ORANGE, 6.0);
            s.text(vx - 14.0, vy + 46.0, "end", W_FONT, "v");
        }
        Phase::Stuck => s.text(vx, vy + 46.0, "middle", W_FONT, "v = 0"),
    }

    // l: from the pole's axis to the spring's line of action, above the sleeve.
    let l_y = c1.1 - f_len - 62.0;
    s.dashed(
        spring_x,
        arm_end.1 - 2.0 * arm_half,
        spring_x,
        l_y - 6.0,
        INK,
        1.0,
    );
    s.dimension(Some("lever"), (px, l_y), (spring_x, l_y), INK, 1.2);
    let l_mid = (px + spring_x) / 2.0;
    s.text(
        l_mid,
        l_y - 10.0,
        "middle",
        W_FONT,
        &format!("l = {}", mm_text(l_mm)),
    );
    s.text(
        l_mid + 20.0,
        l_y + 36.0,
        "middle",
        W_FONT,
        &labels.derived("λ = l/h", num(lambda)),
    );

    // The spring: natural length, then the coordinate z; the bird drawn at z = z0, and the band
    // its centre sweeps, z0 − d0 … z0 + d0.
    s.band(
        spring_x - bird_r - 8.0,
        band_top,
        2.0 * bird_r + 16.0,
        band_bot - band_top,
        PURPLE,
    );
    s.spring(
        spring_x,
        arm_end.1,
        bird_y - bird_r,
        g.coils,
        g.coil_half,
        PURPLE,
    );
    bird(&mut s, spring_x, bird_y, bird_r);
    let left_of_band = spring_x - bird_r - 14.0;
    let below_friction = c2.1 + f_len + 64.0;
    let mw_y = (bird_y + 40.0).max(below_friction);
    s.text(
        left_of_band,
        mw_y,
        "end",
        W_FONT,
        &format!("m_{{W}} = {}", grams(p.m_bird)),
    );
    s.text(
        left_of_band,
        mw_y + 36.0,
        "end",
        W_FONT,
        &format!("k = {}", plain(p.k, "N/m")),
    );

    // The spring force on the sleeve, along its line of action, beside the spring.
    let fe_x = spring_x + 22.0;
    s.arrow(
        Some("force-fe"),
        (fe_x, arm_end.1 - arm_half),
        (fe_x, arm_end.1 + 44.0),
        PURPLE,
        3.0,
    );
    s.text(
        fe_x + 10.0,
        arm_end.1 - 10.0,
        "start",
        W_FONT,
        "F_{e} = k z",
    );

    // z0 and d0 as a chain of dimensions right of the band.
    let dim_x = spring_x + bird_r + 36.0;
    let lx = dim_x + 16.0;
    s.dashed(spring_x + 12.0, y_of(0.0), lx + 190.0, y_of(0.0), INK, 1.0);
    s.dashed(
        spring_x + bird_r + 4.0,
        bird_y,
        dim_x + 8.0,
        bird_y,
        INK,
        1.0,
    );
    s.dashed(
        spring_x + bird_r + 12.0,
        band_bot,
        dim_x + 8.0,
        band_bot,
        INK,
        1.0,
    );
    let y0 = y_of(0.0);
    if z0_mm.abs() * scale > 12.0 {
        s.dimension(Some("dim-z0"), (dim_x, y0), (dim_x, bird_y), INK, 1.2);
    }
    s.dimension(Some("dim-d0"), (dim_x, bird_y), (dim_x, band_bot), INK, 1.2);
    // The z = 0 line's label goes on its side away from the bird (above it when z0 ≥ 0); the
    // z0 label at the middle of its dimension, or beside the bird's line when that is short.
    let bird_above = z0_mm < 0.0;
    let zero_y = if bird_above { y0 + 34.0 } else { y0 - 8.0 };
    s.text(lx, zero_y, "start", W_FONT, "z = 0: unstretched");
    let z0_y = if (y0 - bird_y).abs() >= 70.0 {
        (y0 + bird_y) / 2.0 + 10.0
    } else if bird_above {
        bird_y - 10.0
    } else {
        bird_y + 32.0
    };
    s.text(
        lx,
        z0_y,
        "start",
        W_FONT,
        &format!("z_{{0}} = {}", mm_text(z0_mm)),
    );
    let d0_y = ((bird_y + band_bot) / 2.0 + 10.0).max(z0_y + 36.0);
    s.text(
        lx,
        d0_y,
        "start",
        W_FONT,
        &format!("d_{{0}} = {}", mm_text(d0_mm)),
    );

    // The numbers that are not drawn, and the reading of the drawing, below it.
    let mut info = vec![format!(
        "sleeve m_{{S}} = {}, μ_{{s}} = {}, μ_{{d}} = {}",
        grams(p.m_sleeve),
        num(p.mu_s),
        num(p.mu_d)
    )];
    info.push(labels.derived("z = z_{0} + d_{0} cos ωt, T", ms(period)));
    if labels == Labels::Computed {
        info.push(format!(
            "F_{{e}} from {} to {}, N up to {}",
            mn(fe_min),
            mn(fe_max),
            mn(n_max)
        ));
    }
    info.push("shaded: the range of the bird's centre".to_string());
    info.push("h between the contacts; tilt exaggerated".to_string());
    for (i, line) in info.iter().enumerate() {
        s.text(20.0, info_top + 36.0 * i as f64, "start", W_FONT, line);
    }
    s.finish_at(info_top + 36.0 * (info.len() as f64 - 1.0) + 14.0)
}

/// The tilt θ (rad, clockwise) and the hole's half-height b of the sleeve: the hole's top-left
/// inner corner (−a, −b) lands on the pole's left face (x = −p) and the contacts are `h` apart
/// vertically. Fixed point on b; converges in a few steps for any a > p.
fn sleeve_tilt(a: f64, p: f64, h: f64) -> (f64, f64) {
    let mut b = h / 2.0;
    let mut theta = 0.0;
    for _ in 0..50 {
        // −a cos θ + b sin θ = −p  ⇔  R sin(θ − α) = −p with R = √(a²+b²), α = atan(a/b).
        let r = a.hypot(b);
        theta = (a / b).atan() - (p / r).asin();
        // The contacts' height difference is 2 (a sin θ + b cos θ) = h.
        b = (h / 2.0 - a * theta.sin()) / theta.cos();
    }
    (theta, b)
}

/// A small woodpecker: body, head with the beak towards the pole, an eye.
fn bird(s: &mut Svg, x: f64, y: f64, r: f64) {
    s.raw(&format!(
        "<ellipse cx=\"{}\" cy=\"{}\" rx=\"{}\" ry=\"{}\" fill=\"{INK}\" fill-opacity=\"0.15\" \
         stroke=\"{INK}\" stroke-width=\"1.6\"/>",
        c(x + 4.0),
        c(y + 4.0),
        c(r * 1.2),
        c(r * 0.8)
    ));
    let (hx, hy) = (x - r * 0.75, y - r * 0.7);
    s.circle_styled(hx, hy, r * 0.5, INK, 0.15, 1.6);
    s.polygon(
        &[
            (hx - r * 0.45, hy - 3.0),
            (hx - r * 1.25, hy + 1.0),
            (hx - r * 0.45, hy + 4.0),
        ],
        INK,
        0.6,
        1.2,
    );
    s.circle(hx - 2.0, hy - 2.0, 1.8, INK);
    // A red crest, the toy's colour.
    s.raw(&format!(
        "<path d=\"M{} {} q{} {} {} {}\" fill=\"none\" stroke=\"{VERMILLION}\" stroke-width=\"3\"/>",
        c(hx - 2.0),
        c(hy - r * 0.5),
        c(r * 0.4),
        c(-r * 0.5),
        c(r * 0.8),
        c(r * 0.15)
    ));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::pulled_mass::sketch::{pulled_mass, pulled_mass_givens};
    use crate::models::pulled_mass::PulledMassParams;
    use crate::report::sketch::{grams, mm_text, mn, ms, num, plain};

    fn both_models(phase: Phase) -> [String; 2] {
        [
            pulled_mass(&PulledMassParams::default(), phase),
            woodpecker(&WoodpeckerParams::default(), phase),
        ]
    }

    /// The text of an element and its descendants, tspans joined.
    fn text_of(node: roxmltree::Node) -> String {
        node.descendants()
            .filter(|n| n.is_text())
            .filter_map(|n| n.text())
            .collect()
    }

    /// Every `<text>` of the sketch, as read.
    fn texts(svg: &str) -> Vec<String> {
        let doc = roxmltree::Document::parse(svg).unwrap();
        doc.descendants()
            .filter(|n| n.has_tag_name("text"))
            .map(text_of)
            .collect()
    }

    fn child_text(svg: &str, tag: &str) -> String {
        let doc = roxmltree::Document::parse(svg).unwrap();
        let node = doc.root_element().children().find(|n| n.has_tag_name(tag));
        node.map(text_of).unwrap_or_default()
    }

    /// Length of the first arrow shaft in `<g class="{class}">`, plus its head.
    /// The length (px) of the force arrow of class `force-{force}`.
    fn arrow_length(svg: &str, force: &str) -> f64 {
        crate::report::sketch::force_arrows(svg)
            .into_iter()
            .find(|(class, _, _)| class == force)
            .map(|(_, dx, dy)| dx.hypot(dy))
            .unwrap_or_else(|| panic!("no force-{force}"))
    }

    fn dimension_length(svg: &str, class: &str) -> f64 {
        let doc = roxmltree::Document::parse(svg).unwrap();
        let g = doc
            .descendants()
            .find(|n| n.attribute("class") == Some(class))
            .unwrap_or_else(|| panic!("no {class}"));
        g.attribute("data-length").unwrap().parse().unwrap()
    }

    #[test]
    fn sketches_are_well_formed_accessible_and_responsive() {
        let odd = WoodpeckerParams {
            l: 0.025,
            h: 0.004,
            z0: -0.002,
            d0: 0.012,
            ..Default::default()
        };
        let immediate = PulledMassParams {
            force: 0.6,
            ..Default::default()
        };
        for phase in [Phase::Stuck, Phase::Slipping] {
            let mut all = both_models(phase).to_vec();
            all.push(woodpecker(&odd, phase));
            all.push(pulled_mass(&immediate, phase));
            for svg in all {
                let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("{e}\n{svg}"));
                let root = doc.root_element();
                assert!(root.has_tag_name("svg"));
                assert_eq!(root.attribute("role"), Some("img"));
                assert_eq!(root.attribute("font-family"), Some("sans-serif"));
                let view = root.attribute("viewBox").unwrap();
                assert!(view.starts_with("0 0 900 ") || view.starts_with("0 0 600 "));
                assert!(root.attribute("style").unwrap().contains("max-width:100%"));
                // <title> and <desc> come first, so that readers find them.
                let first: Vec<&str> = root
                    .children()
                    .filter(|n| n.is_element())
                    .take(2)
                    .map(|n| n.tag_name().name())
                    .collect();
                assert_eq!(first, ["title", "desc"]);
                assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
            }
        }
    }

    #[test]
    fn coordinates_are_rounded_to_a_tenth_of_a_pixel() {
        for svg in both_models(Phase::Slipping) {
            let doc = roxmltree::Document::parse(&svg).unwrap();
            for node in doc.descendants().filter(|n| n.is_element()) {
                for attr in node.attributes() {
                    let coordinate = matches!(
                        attr.name(),
                        "x" | "y"
                            | "x1"
                            | "y1"
                            | "x2"
                            | "y2"
                            | "cx"
                            | "cy"
                            | "r"
                            | "rx"
                            | "ry"
                            | "width"
                            | "height"
                            | "points"
                            | "d"
                            | "dy"
                            | "data-length"
                    );
                    if !coordinate {
                        continue;
                    }
                    for token in attr
                        .value()
                        .split(|ch: char| !(ch.is_ascii_digit() || ch == '.'))
                        .filter(|t| !t.is_empty())
                    {
                        let decimals = token.split('.').nth(1).map_or(0, str::len);
                        assert!(decimals <= 1, "{}={}", attr.name(), attr.value());
                    }
                }
            }
        }
    }

    #[test]
    fn title_and_description_carry_the_parameters() {
        let [pulled, wood] = both_models(Phase::Slipping);
        let desc = child_text(&pulled, "desc");
        for value in [
            "m = 60 g",
            "F = 180 mN",
            "k = 45 N/m",
            "T = 229.4 ms",
            "μs = 0.4",
            "μd = 0.25",
        ] {
            assert!(desc.contains(value), "{value}: {desc}");
        }
        // At the slip onset N = F/μs = 450 mN and the friction is μd N = 112.5 mN.
        assert!(desc.contains("N = 450 mN"), "{desc}");
        assert!(desc.contains("μd N = 112.5 mN"), "{desc}");
        assert!(child_text(&pulled, "title").contains("Pulled mass, slipping"));

        let desc = child_text(&wood, "desc");
        for value in [
            "m_S = 6 g",
            "W_S = 58.86 mN",
            "k = 20 N/m",
            "m_W = 14 g",
            "l = 16 mm",
            "h = 7 mm",
            "λ = l/h = 2.286",
            "z0 = 7 mm",
            "d0 = 9 mm",
            "from −40 mN to 320 mN",
            "N reaches 731.4 mN",
            "μs = 0.65",
            "μd = 0.32",
        ] {
            assert!(desc.contains(value), "{value}: {desc}");
        }
        assert!(child_text(&wood, "title").contains("Falling woodpecker, slipping"));
    }

    #[test]
    fn a_worksheet_sketch_shows_the_given_values_and_names_the_derived_ones() {
        let p = PulledMassParams::default();
        let svg = pulled_mass_givens(&p);
        for derived in [
            mn(p.weight()),
            ms(p.period()),
            mn(2.0 * p.weight()),
            num(p.phi()),
        ] {
            assert!(!svg.contains(&derived), "{derived} on a worksheet sketch");
        }
        for given in [grams(p.mass), mn(p.force), plain(p.k, "N/m")] {
            assert!(svg.contains(&given), "{given}");
        }
        assert!(svg.contains("oscillates: T = 2π√(m'/k)"));
        let w = WoodpeckerParams::default();
        let svg = woodpecker_givens(&w);
        for derived in [mn(w.sleeve_weight()), ms(w.period()), num(w.lambda())] {
            assert!(!svg.contains(&derived), "{derived} on a worksheet sketch");
        }
        assert!(svg.contains(&mm_text(w.l * 1e3)) && svg.contains(&mm_text(w.d0 * 1e3)));
        // The report's sketches keep their numbers.
        assert!(pulled_mass(&p, Phase::Stuck).contains(&ms(p.period())));
    }

    #[test]
    fn the_phase_decides_the_friction_law_on_the_labels() {
        for (phase, want, not) in [
            (Phase::Stuck, "≤ μs N", "= μd N"),
            (Phase::Slipping, "= μd N", "≤ μs N"),
        ] {
            for svg in both_models(phase) {
                let labels = texts(&svg);
                assert!(
                    labels.iter().any(|t| t.contains(want)),
                    "{phase:?}: {labels:?}"
                );
                assert!(
                    !labels.iter().any(|t| t.contains(not)),
                    "{phase:?}: {labels:?}"
                );
                let v0 = labels.iter().any(|t| t == "v = 0");
                assert_eq!(v0, phase == Phase::Stuck);
            }
        }
    }

    #[test]
    fn labels_show_subscripts_and_units_people_think_in() {
        let [pulled, wood] = both_models(Phase::Stuck);
        let labels = texts(&pulled);
        for want in [
            "m = 60 g",
            "F = 180 mN",
            "k = 45 N/m",
            "W = 588.6 mN",
            "N = 1177 mN",
            "S = 588.6 mN",
            "vertical: N = W + S: 1177 = 588.6 + 588.6 mN",
        ] {
            assert!(labels.iter().any(|t| t == want), "{want}: {labels:?}");
        }
        let labels = texts(&wood);
        for want in [
            "l = 16 mm",
            "h = 7 mm",
            "z0 = 7 mm",
            "d0 = 9 mm",
            "WS = 58.86 mN",
        ] {
            assert!(labels.iter().any(|t| t == want), "{want}: {labels:?}");
        }
        // The subscript is a lowered, smaller tspan, and the baseline comes back after it.
        assert!(wood.contains("W<tspan dy=\"9\" font-size=\"29\">S</tspan><tspan dy=\"-9\"> = "));
    }

    #[test]
    fn the_same_parameters_give_the_same_bytes() {
        for phase in [Phase::Stuck, Phase::Slipping] {
            assert_eq!(both_models(phase), both_models(phase));
        }
    }

    #[test]
    fn drawings_scale_with_the_parameters() {
        let short = WoodpeckerParams {
            l: 0.012,
            ..Default::default()
        };
        let base = woodpecker(&WoodpeckerParams::default(), Phase::Stuck);
        let lever = |svg: &str| dimension_length(svg, "lever");
        assert!(lever(&base) > lever(&woodpecker(&short, Phase::Stuck)) + 40.0);
        // 14 px/mm: l = 16 mm is 224 px, h = 7 mm is 98 px.
        assert!((lever(&base) - 224.0).abs() < 0.11, "{}", lever(&base));
        assert!((dimension_length(&base, "dim-h") - 98.0).abs() < 0.2);
        let taller = WoodpeckerParams {
            h: 0.009,
            ..Default::default()
        };
        let taller = woodpecker(&taller, Phase::Stuck);
        assert!(dimension_length(&taller, "dim-h") > dimension_length(&base, "dim-h") + 20.0);
        let wider = WoodpeckerParams {
            d0: 0.011,
            ..Default::default()
        };
        let d0 = |svg: &str| dimension_length(svg, "dim-d0");
        assert!(d0(&woodpecker(&wider, Phase::Stuck)) > d0(&base));

        // The pulled mass: forces to one scale, so twice the pull is a longer arrow, and N at
        // t = 0 (2W) is twice W.
        let pulled = pulled_mass(&PulledMassParams::default(), Phase::Stuck);
        let harder = PulledMassParams {
            force: 0.36,
            ..Default::default()
        };
        let harder = pulled_mass(&harder, Phase::Stuck);
        let f = |svg: &str| arrow_length(svg, "f");
        assert!((f(&harder) / f(&pulled) - 2.0).abs() < 0.02);
        let ratio = arrow_length(&pulled, "n") / arrow_length(&pulled, "w");
        assert!((ratio - 2.0).abs() < 0.01, "{ratio}");
    }

    #[test]
    fn the_sleeve_touches_the_pole_at_two_points_h_apart() {
        for (a, p, h) in [(14.5, 12.0, 98.0), (14.5, 12.0, 24.0), (14.5, 12.0, 40.0)] {
            let (theta, b) = sleeve_tilt(a, p, h);
            let (sn, cs) = theta.sin_cos();
            assert!(theta > 0.0 && theta < 0.5, "{theta}");
            // Top-left inner corner on the pole's left face; contacts h apart vertically.
            assert!((-a * cs + b * sn + p).abs() < 1e-9);
            assert!((2.0 * (a * sn + b * cs) - h).abs() < 1e-9);
        }
    }

    #[test]
    fn default_woodpecker_snapshot() {
        insta::assert_snapshot!(
            "woodpecker_stuck",
            woodpecker(&WoodpeckerParams::default(), Phase::Stuck)
        );
        insta::assert_snapshot!(
            "woodpecker_slipping",
            woodpecker(&WoodpeckerParams::default(), Phase::Slipping)
        );
    }
}
