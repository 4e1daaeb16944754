//! LaTeX to MathML for the HTML pages (pulldown-latex); the Markdown pages keep the LaTeX
//! between `$…$`, which GitHub renders.

use pulldown_latex::{push_mathml, Parser, RenderConfig, Storage};

/// MathML of an inline LaTeX formula; the escaped source in a `<code>` when it does not parse.
pub fn mathml(latex: &str) -> String {
    let storage = Storage::new();
    let parser = Parser::new(latex, &storage);
    let mut out = String::new();
    match push_mathml(&mut out, parser, RenderConfig::default()) {
        Ok(()) => out,
        Err(_) => format!("<code>{}</code>", escape(latex)),
    }
}

/// Minimal HTML escaping for text placed in markup.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::{pulled_mass::quantity as pm, woodpecker::quantity as wp};
    use crate::results::quantity::Registry;

    #[test]
    fn every_formula_and_symbol_of_the_registries_renders_to_mathml() {
        let quantities = pm::Key::ENTRIES
            .iter()
            .map(|e| &e.quantity)
            .chain(wp::Key::ENTRIES.iter().map(|e| &e.quantity));
        for q in quantities {
            for tex in [q.latex, q.tex] {
                let m = mathml(tex);
                assert!(m.starts_with("<math"), "{}: {m}", q.id);
                assert!(!m.contains("merror"), "{}: {m}", q.id);
            }
        }
    }
}
