//! What every sketch of an apparatus is drawn with: the canvas ([`Svg`]), arrows, labels with
//! subscripts, the colours of the forces and the short numbers of the labels. Each model draws
//! its own apparatus in its folder (`src/models/<name>/sketch.rs`) from these. Pure functions
//! returning a self-contained SVG string: hand-written elements, no plotters, coordinates
//! rounded to 0.1 px, so the same parameters give the same bytes.
//!
//! ```text
//! params + phase → geometry (px, from m, N, mm) → elements (lines, arrows, labels) → <svg>
//! ```
//!
//! Every sketch has `role="img"`, a `<title>`, a `<desc>` with the key numbers, a `viewBox`
//! (it fills the width it is given), a generic font and colours that read on white and on a
//! dark page: outlines and text are `currentColor` (an inline SVG takes the page's text colour;
//! a standalone file declares `color-scheme: light dark`), bodies are `currentColor` at low
//! opacity, and the forces use the Okabe–Ito colours of the charts.

use std::fmt::Write as _;

pub use crate::present::vocab::Phase;

/// Arrowhead length and half-width (px).
pub(crate) const HEAD_LEN: f64 = 11.0;
const HEAD_HALF: f64 = 5.0;

/// Okabe & Ito colours, as in the charts (`figures::style::PALETTE`).
pub(crate) const BLUE: &str = "#0072B2"; // pulling force F
pub(crate) const VERMILLION: &str = "#D55E00"; // friction
pub(crate) const GREEN: &str = "#009E73"; // normal / contact forces
pub(crate) const PURPLE: &str = "#CC79A7"; // spring and its force
pub(crate) const ORANGE: &str = "#E69F00"; // velocity
pub(crate) const INK: &str = "currentColor"; // outlines, text, weights

/// Which values the labels of a sketch show.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Labels {
    /// Given and derived values (W, T, N, …).
    Computed,
    /// Given values only; derived ones by their symbols.
    Givens,
}

impl Labels {
    /// `symbolic`, then ` = value` unless only givens are shown.
    pub(crate) fn derived(self, symbolic: &str, value: String) -> String {
        match self {
            Labels::Computed => format!("{symbolic} = {value}"),
            Labels::Givens => symbolic.to_string(),
        }
    }
}

/// A coordinate rounded to 0.1 px, without a trailing ".0" and never "-0".
pub(crate) fn c(v: f64) -> String {
    let r = (v * 10.0).round() / 10.0;
    let r = if r == 0.0 { 0.0 } else { r };
    let t = format!("{r:.1}");
    t.strip_suffix(".0").map(str::to_string).unwrap_or(t)
}

/// A number to four significant digits, trailing zeros dropped, with a true minus sign.
pub(crate) fn num(v: f64) -> String {
    if !v.is_finite() {
        return "—".to_string();
    }
    if v == 0.0 {
        return "0".to_string();
    }
    let exponent = v.abs().log10().floor() as i32;
    let decimals = (3 - exponent).clamp(0, 12) as usize;
    let mut t = format!("{v:.decimals$}");
    if t.contains('.') {
        t = t.trim_end_matches('0').trim_end_matches('.').to_string();
    }
    if t == "-0" {
        return "0".to_string();
    }
    t.replace('-', "\u{2212}")
}

/// A value with its unit, separated by a space.
pub(crate) fn plain(v: f64, unit: &str) -> String {
    format!("{} {unit}", num(v))
}

/// A force in N, shown in mN.
pub(crate) fn mn(newton: f64) -> String {
    plain(newton * 1e3, "mN")
}

/// A mass in kg, shown in g.
pub(crate) fn grams(kg: f64) -> String {
    plain(kg * 1e3, "g")
}

/// A time in s, shown in ms.
pub(crate) fn ms(s: f64) -> String {
    plain(s * 1e3, "ms")
}

/// A length already in mm.
pub(crate) fn mm_text(mm: f64) -> String {
    plain(mm, "mm")
}

/// XML escaping of text content and attribute values.
pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A point of the SVG user space (px).
type Point = (f64, f64);

/// The SVG being written: its size, the smallest subscript (px; 0: subscripts at 75 % of
/// their label), and the elements so far.
pub(crate) struct Svg {
    width: f64,
    height: f64,
    sub_min: f64,
    out: String,
}

impl Svg {
    /// A canvas `width` × `height` px whose subscripts print at no less than `sub_min` px
    /// (a sketch drawn for a given printed width keeps every glyph at the legible size).
    pub(crate) fn sized(width: f64, height: f64, sub_min: f64) -> Self {
        Self {
            width,
            height,
            sub_min,
            out: String::new(),
        }
    }

    /// The root element with its title and description.
    pub(crate) fn open(&mut self, title: &str, desc: &str) {
        let _ = write!(
            self.out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {w} {h}\" width=\"{w}\" \
             height=\"{h}\" preserveAspectRatio=\"xMidYMid meet\" role=\"img\" \
             style=\"max-width:100%;height:auto;color-scheme:light dark\" \
             font-family=\"sans-serif\" fill=\"{INK}\">\n<title>{title}</title>\n<desc>{desc}</desc>\n",
            w = c(self.width),
            h = c(self.height),
            title = escape(title),
            desc = escape(desc),
        );
    }

    pub(crate) fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }

    /// Like [`Svg::finish`], for a canvas whose height is known only once it is drawn: the
    /// root written by [`Svg::open`] gets `height` (px).
    pub(crate) fn finish_at(mut self, height: f64) -> String {
        let old = format!(
            " {} {}\" width=\"{}\" height=\"{}\"",
            c(self.width),
            c(self.height),
            c(self.width),
            c(self.height)
        );
        let new = format!(
            " {} {}\" width=\"{}\" height=\"{}\"",
            c(self.width),
            c(height),
            c(self.width),
            c(height)
        );
        self.out = self.out.replacen(&old, &new, 1);
        self.height = height;
        self.finish()
    }

    pub(crate) fn raw(&mut self, element: &str) {
        self.out.push_str(element);
        self.out.push('\n');
    }

    pub(crate) fn line(&mut self, x1: f64, y1: f64, x2: f64, y2: f64, stroke: &str, width: f64) {
        let _ = writeln!(
            self.out,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{stroke}\" stroke-width=\"{}\"/>",
            c(x1),
            c(y1),
            c(x2),
            c(y2),
            c(width)
        );
    }

    pub(crate) fn dashed(&mut self, x1: f64, y1: f64, x2: f64, y2: f64, stroke: &str, width: f64) {
        let _ = writeln!(
            self.out,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{stroke}\" stroke-width=\"{}\" \
             stroke-dasharray=\"5 4\" stroke-opacity=\"0.7\"/>",
            c(x1),
            c(y1),
            c(x2),
            c(y2),
            c(width)
        );
    }

    /// A body: outlined and filled in the ink at low opacity.
    pub(crate) fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, opacity: f64, stroke: f64) {
        let _ = writeln!(
            self.out,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{INK}\" fill-opacity=\"{}\" \
             stroke=\"{INK}\" stroke-width=\"{}\"/>",
            c(x),
            c(y),
            c(w),
            c(h),
            opacity,
            c(stroke)
        );
    }

    /// A translucent band without outline (a range of positions).
    pub(crate) fn band(&mut self, x: f64, y: f64, w: f64, h: f64, fill: &str) {
        let _ = writeln!(
            self.out,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{fill}\" fill-opacity=\"0.22\"/>",
            c(x),
            c(y),
            c(w),
            c(h)
        );
    }

    pub(crate) fn polygon(&mut self, points: &[(f64, f64)], ink: &str, opacity: f64, stroke: f64) {
        let pts: Vec<String> = points
            .iter()
            .map(|(x, y)| format!("{},{}", c(*x), c(*y)))
            .collect();
        let _ = writeln!(
            self.out,
            "<polygon points=\"{}\" fill=\"{ink}\" fill-opacity=\"{}\" stroke=\"{ink}\" \
             stroke-width=\"{}\" stroke-linejoin=\"round\"/>",
            pts.join(" "),
            opacity,
            c(stroke)
        );
    }

    pub(crate) fn circle(&mut self, x: f64, y: f64, r: f64, fill: &str) {
        let _ = writeln!(
            self.out,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{fill}\"/>",
            c(x),
            c(y),
            c(r)
        );
    }

    pub(crate) fn circle_styled(
        &mut self,
        x: f64,
        y: f64,
        r: f64,
        ink: &str,
        opacity: f64,
        stroke: f64,
    ) {
        let _ = writeln!(
            self.out,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{ink}\" fill-opacity=\"{}\" \
             stroke=\"{ink}\" stroke-width=\"{}\"/>",
            c(x),
            c(y),
            c(r),
            opacity,
            c(stroke)
        );
    }

    /// An arrow from `from` to its head at `to`: a shaft and a filled head; in a
    /// `<g class="…">` when given a class, so that tests and stylesheets can find it.
    pub(crate) fn arrow(
        &mut self,
        class: Option<&str>,
        from: Point,
        to: Point,
        color: &str,
        width: f64,
    ) {
        let ((x1, y1), (x2, y2)) = (from, to);
        let (dx, dy) = (x2 - x1, y2 - y1);
        let len = dx.hypot(dy);
        if len == 0.0 {
            return;
        }
        let (ux, uy) = (dx / len, dy / len);
        let head = (HEAD_LEN + width).min(len);
        let half = HEAD_HALF + width / 2.0;
        let (bx, by) = (x2 - ux * head, y2 - uy * head);
        if let Some(class) = class {
            let _ = writeln!(self.out, "<g class=\"{class}\">");
        }
        self.line(x1, y1, bx + ux * 0.5, by + uy * 0.5, color, width);
        self.head(to, (bx, by), half, color);
        if class.is_some() {
            self.out.push_str("</g>\n");
        }
    }

    /// A filled triangular head with its tip at `tip` and its base centred on `base`.
    fn head(&mut self, tip: Point, base: Point, half: f64, color: &str) {
        let len = (tip.0 - base.0).hypot(tip.1 - base.1);
        let (ux, uy) = ((tip.0 - base.0) / len, (tip.1 - base.1) / len);
        let _ = writeln!(
            self.out,
            "<polygon points=\"{},{} {},{} {},{}\" fill=\"{color}\"/>",
            c(tip.0),
            c(tip.1),
            c(base.0 - uy * half),
            c(base.1 + ux * half),
            c(base.0 + uy * half),
            c(base.1 - ux * half)
        );
    }

    /// A dimension line: thin, a head at each end, in a `<g>` (class `dimension` unless
    /// given) whose `data-length` is the distance measured (px).
    pub(crate) fn dimension(
        &mut self,
        class: Option<&str>,
        from: Point,
        to: Point,
        color: &str,
        width: f64,
    ) {
        let ((x1, y1), (x2, y2)) = (from, to);
        let (dx, dy) = (x2 - x1, y2 - y1);
        let len = dx.hypot(dy);
        if len == 0.0 {
            return;
        }
        let (ux, uy) = (dx / len, dy / len);
        let head = 8.0_f64.min(len / 2.0);
        let _ = writeln!(
            self.out,
            "<g class=\"{}\" data-length=\"{}\">",
            class.unwrap_or("dimension"),
            c(len)
        );
        self.line(
            x1 + ux * head,
            y1 + uy * head,
            x2 - ux * head,
            y2 - uy * head,
            color,
            width,
        );
        self.head(from, (x1 + ux * head, y1 + uy * head), 3.5, color);
        self.head(to, (x2 - ux * head, y2 - uy * head), 3.5, color);
        self.out.push_str("</g>\n");
    }

    /// A vertical coil spring from y1 down to y2: straight ends, `coils` zigzags.
    pub(crate) fn spring(
        &mut self,
        x: f64,
        y1: f64,
        y2: f64,
        coils: usize,
        half: f64,
        color: &str,
    ) {
        let end = 10.0_f64.min((y2 - y1) / 4.0);
        let (a, b) = (y1 + end, y2 - end);
        let n = 2 * coils.max(1);
        let step = (b - a) / n as f64;
        let mut pts = vec![(x, y1), (x, a)];
        for i in 0..n {
            let side = if i % 2 == 0 { -half } else { half };
            pts.push((x + side, a + step * (i as f64 + 0.5)));
        }
        pts.push((x, b));
        pts.push((x, y2));
        let pts: Vec<String> = pts
            .iter()
            .map(|(x, y)| format!("{},{}", c(*x), c(*y)))
            .collect();
        let _ = writeln!(
            self.out,
            "<polyline class=\"spring\" points=\"{}\" fill=\"none\" stroke=\"{color}\" \
             stroke-width=\"2.2\" stroke-linejoin=\"round\"/>",
            pts.join(" ")
        );
    }

    /// A text label. `_{…}` writes a subscript.
    pub(crate) fn text(&mut self, x: f64, y: f64, anchor: &str, size: f64, label: &str) {
        let _ = write!(
            self.out,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"{anchor}\" font-size=\"{}\" xml:space=\"preserve\">",
            c(x),
            c(y),
            c(size)
        );
        let shift = c(size * 0.3);
        let sub = if self.sub_min > 0.0 {
            c((0.85 * size).max(self.sub_min))
        } else {
            "75%".to_string()
        };
        let mut rest = label;
        let mut lowered = false;
        while !rest.is_empty() {
            match rest.find("_{") {
                Some(i) => {
                    let (before, after) = rest.split_at(i);
                    push_run(&mut self.out, before, &mut lowered, false, &shift, &sub);
                    let close = after.find('}').unwrap_or(after.len());
                    push_run(
                        &mut self.out,
                        &after[2..close],
                        &mut lowered,
                        true,
                        &shift,
                        &sub,
                    );
                    rest = after.get(close + 1..).unwrap_or("");
                }
                None => {
                    push_run(&mut self.out, rest, &mut lowered, false, &shift, &sub);
                    rest = "";
                }
            }
        }
        self.out.push_str("</text>\n");
    }
}

/// Writes one run of a label: plain, or a subscript (smaller, lowered); the baseline comes back
/// with the first plain run after a subscript.
fn push_run(out: &mut String, run: &str, lowered: &mut bool, sub: bool, shift: &str, size: &str) {
    if run.is_empty() {
        return;
    }
    let text = escape(run);
    match (sub, *lowered) {
        (true, false) => {
            let _ = write!(
                out,
                "<tspan dy=\"{shift}\" font-size=\"{size}\">{text}</tspan>"
            );
            *lowered = true;
        }
        (true, true) => {
            let _ = write!(out, "<tspan font-size=\"{size}\">{text}</tspan>");
        }
        (false, true) => {
            let _ = write!(out, "<tspan dy=\"-{shift}\">{text}</tspan>");
            *lowered = false;
        }
        (false, false) => out.push_str(&text),
    }
}

/// The (class without `force-`, signed dx, signed dy) of each force arrow of a sketch, from its
/// shaft's start to its tip (px; right and up positive): for the tests that check the forces
/// of a free-body diagram balance.
#[cfg(test)]
pub(crate) fn force_arrows(svg: &str) -> Vec<(String, f64, f64)> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("g"))
        .filter_map(|g| {
            let class = g.attribute("class")?.strip_prefix("force-")?.to_string();
            let line = g.children().find(|c| c.has_tag_name("line"))?;
            let at = |a| line.attribute(a).unwrap().parse::<f64>().unwrap();
            let poly = g.children().find(|c| c.has_tag_name("polygon"))?;
            let tip: Vec<f64> = poly
                .attribute("points")
                .unwrap()
                .split([' ', ','])
                .take(2)
                .map(|v| v.parse().unwrap())
                .collect();
            Some((class, tip[0] - at("x1"), at("y1") - tip[1]))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_use_a_true_minus() {
        assert_eq!(num(0.18 * 1e3), "180");
        assert_eq!(num(588.6), "588.6");
        assert_eq!(num(1177.2), "1177");
        assert_eq!(num(16.0 / 7.0), "2.286");
        assert_eq!(num(-40.000_000_000_01), "−40");
        assert_eq!(num(0.0), "0");
        assert_eq!(c(-0.04), "0");
        assert_eq!(c(12.34), "12.3");
        assert_eq!(c(12.0), "12");
        assert_eq!(mn(0.05886), "58.86 mN");
    }
}
