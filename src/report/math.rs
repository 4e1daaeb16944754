//! LaTeX to MathML Core for the HTML pages (math-core); the Markdown pages keep the LaTeX
//! between `$…$`, which GitHub renders. math-core writes μ as U+03BC (not the micro sign),
//! escapes `<` and `&` in its tokens and marks `\dot`/`\ddot`/`\bar` as accents.

use std::sync::OnceLock;

use math_core::{LatexToMathML, MathCoreConfig, MathDisplay};

/// The converter, built once (its configuration holds no macros, so building cannot fail).
fn converter() -> Option<&'static LatexToMathML> {
    static CONVERTER: OnceLock<Option<LatexToMathML>> = OnceLock::new();
    CONVERTER
        .get_or_init(|| LatexToMathML::new(MathCoreConfig::default()).ok())
        .as_ref()
}

/// MathML of an inline LaTeX formula; the escaped source in a `<code>` when it does not parse.
pub fn mathml(latex: &str) -> String {
    convert(latex, MathDisplay::Inline)
}

/// MathML of a displayed LaTeX formula (`display="block"`), or its escaped source in a `<code>`.
pub fn mathml_block(latex: &str) -> String {
    convert(latex, MathDisplay::Block)
}

fn convert(latex: &str, display: MathDisplay) -> String {
    converter()
        .and_then(|c| c.convert_with_local_state(latex, display).ok())
        .map_or_else(|| format!("<code>{}</code>", escape(latex)), |r| r.mathml)
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
