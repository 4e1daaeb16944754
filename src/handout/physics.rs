//! The words of the handout: the equation of motion of each model in symbols (physics.md §1,
//! §2–3), and for each step of the chain of formulas (by its §7 key) what it means: a label for
//! a definition, a sentence of physics for a step of the motion. Keys not named here stay out of
//! the handout's chain (thresholds such as μd,MIN; the report shows them).

use crate::models::{with_model, Model};
use crate::present::Present;

/// (LaTeX, sentence) lines of the pulled mass: physics.md §1.1–1.2.
pub(crate) const PULLED_MASS: &[(&str, &str)] = &[
    (
        r"(m + m')\,\ddot x = 2m\,\ddot x = F - \mu_d\,N(t) \quad (\dot x > 0)",
        "while slipping: both masses move (14), friction opposes F (5)",
    ),
    (
        r"N(t) = W\,(1 + \cos\omega t), \quad W = mg, \quad \omega = \sqrt{k/m'}",
        "the hanging mass oscillates: N from 2W (t = 0) to 0 (t = T/2) (8)",
    ),
    (
        r"N(\tau) = 2W\,|1 - 2\tau|, \quad \tau = t/T\;\text{mod}\;1",
        "linearized law, same extremes; the closed forms are exact for it",
    ),
    (
        r"\ddot x = g\left[\frac{\varphi}{2} - \mu_d\,|1 - 2\tau|\right], \quad \varphi = F/W",
        "divided by 2m: the acceleration while slipping (15)",
    ),
    (
        r"F \le \mu_s\,N(t) \;\Rightarrow\;\dot x = 0",
        "stuck while the pull is within the static capacity; stuck again when v returns to 0",
    ),
];

/// (LaTeX, sentence) lines of the woodpecker: physics.md §2–3.1.
pub(crate) const WOODPECKER: &[(&str, &str)] = &[
    (
        r"m_S\,\ddot y = W_S + F_e(t) - 2\lambda\mu_d\,|F_e(t)| \quad (\dot y > 0)",
        "sleeve, y down: weight and spring force drive, friction at two contacts brakes",
    ),
    (
        r"F_e(t) = k\,(z_0 + d_0\cos\omega t), \quad \omega = \sqrt{k/m_W}",
        "the bird oscillates on the spring: a prescribed force on the sleeve",
    ),
    (
        r"F_e(t) = k\,(\delta_0 + \zeta(t)), \quad \zeta(t) = \zeta_0\,(1 - t/\tau)\;\;(0 \le t \le 2\tau), \quad \tau = T/4",
        "linearized law (37), the closed forms are exact for it",
    ),
    (
        r"|W_S + F_e| \le 2\lambda\mu_s\,|F_e| \;\Rightarrow\;\dot y = 0",
        "stuck while the drive is within the static capacity; stuck again when v returns to 0",
    ),
];

/// How a step of the chain is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Note {
    /// A definition or a shorthand with a few words: the step takes half a row.
    Label(&'static str),
    /// A step of the motion with a sentence of physics: the step takes a whole row.
    Sentence(&'static str),
    /// Only the numbers (symbol = substituted = result), half a row: the woodpecker's phase
    /// II, whose formulas are those of phase I with u^(−) ↔ u^(+), η ↔ η' (physics.md §3.4).
    Numbers,
}

use Note::{Label, Numbers, Sentence};

pub(crate) const PULLED_MASS_STEPS: &[(&str, Note)] = &[
    ("W", Label("weight of each mass")),
    ("omega", Label("of the hanging mass")),
    ("T", Label("period of N(t)")),
    ("phi", Label("pull in units of W")),
    (
        "tau_slip",
        Sentence("slip condition F = μs N, N falling: the slip starts"),
    ),
    ("t_slip", Label("slip time")),
    (
        "a_slip",
        Sentence("friction drops from μs N to μd N: a jumps from 0"),
    ),
    (
        "tau_max_speed",
        Sentence("largest speed where a = 0: F = μd N, N rising"),
    ),
    ("t_max_speed", Label("time of the largest speed")),
    (
        "v_max",
        Sentence("area under a(t) from the slip to the maximum"),
    ),
    ("theta", Label("D = μs² + 2μsμd − μd²")),
    (
        "tau_stick",
        Sentence("the area under a(t) since the slip is zero again: stick"),
    ),
    ("t_stick", Label("stick time")),
    ("slip_duration", Label("duration of the slip")),
    (
        "phi_stick_max",
        Label("largest φ that sticks in the same period"),
    ),
    (
        "phi_continuous",
        Label("above φ_c the mass never sticks again"),
    ),
    ("mu_min_equal", Label("least μ for (20) when μs = μd")),
    ("gamma", Label("coefficient 1 before D^3/2 (claim 2)")),
    (
        "v_avg",
        Sentence("mean speed: area under v(t) over a period, / T"),
    ),
    ("advance_per_period", Label("advance per period")),
    (
        "power",
        Sentence("work of the pull per time = friction dissipation"),
    ),
    (
        "tau_stick_late",
        Sentence("beyond (20): stops early in the next period, before the next slip"),
    ),
];

pub(crate) const WOODPECKER_STEPS: &[(&str, Note)] = &[
    ("W_S", Label("sleeve weight")),
    ("T", Label("period of F_e(t)")),
    ("lambda", Label("torque balance: N = λ|F_e|")),
    ("tau_quarter", Label("quarter period")),
    ("zeta0", Label("linear counterpart of d0")),
    ("delta0", Label("linear counterpart of z0")),
    ("u_s_minus", Label("F_e > 0")),
    ("u_s_plus", Label("F_e < 0")),
    ("u_d_minus", Label("F_e > 0")),
    ("u_d_plus", Label("F_e < 0")),
    ("t0_1", Label("F_e = 0, a = g")),
    ("delta_1", Label("lead of the slip")),
    (
        "t_slip_1",
        Sentence("slip condition W_S + F_e = 2λμs|F_e|, F_e falling"),
    ),
    (
        "t_max_speed_1",
        Sentence("largest speed where a = 0, after F_e = 0"),
    ),
    (
        "v_max_1",
        Sentence("area under a(t) from the slip to the maximum"),
    ),
    ("s_1", Label("shorthand of (49)")),
    (
        "t_stick_1",
        Sentence("the area under a(t) since the slip is zero again: stick"),
    ),
    ("gamma_1", Label("shorthand of (55)")),
    ("distance_1", Sentence("distance slid in phase I")),
    ("t0_2", Numbers),
    ("delta_2", Numbers),
    ("t_slip_2", Numbers),
    ("t_max_speed_2", Numbers),
    ("v_max_2", Numbers),
    ("t_stick_2", Numbers),
    ("distance_2", Numbers),
    ("gamma", Label("both phases")),
    (
        "v_avg",
        Sentence("mean speed y_S(T)/T; independent of δ0 (claim 6)"),
    ),
    (
        "power_weight",
        Sentence("power of the weight, ∝ W_S³; not the dissipation (claim 7)"),
    ),
];

/// Headings before the step of a key: the woodpecker's two phases.
const HEADINGS: &[(&str, &str)] = &[
    ("t0_1", "Phase I: F_e falls through zero (0 ≤ t ≤ T/2)"),
    (
        "t0_2",
        "Phase II: F_e rises through zero (T/2 ≤ t ≤ T); the formulas of phase I with \
         u^(−) ↔ u^(+), η ↔ η', the numbers",
    ),
];

/// How the step of `key` is shown in the chain of `setup`'s model, and the heading before it;
/// `None`: not in the chain.
pub fn note(setup: &Model, key: &str) -> Option<(Note, Option<&'static str>)> {
    fn note_of<M: Present>(_: &M, key: &str) -> Option<Note> {
        M::handout_note(key)
    }
    let heading = HEADINGS.iter().find(|(k, _)| *k == key).map(|(_, h)| *h);
    with_model!(setup, p => note_of(p, key)).map(|n| (n, heading))
}

/// The equation of motion of the scene's model, line by line.
pub fn equation_of_motion(setup: &Model) -> &'static [(&'static str, &'static str)] {
    fn lines<M: Present>(_: &M) -> &'static [(&'static str, &'static str)] {
        M::equation_of_motion()
    }
    with_model!(setup, p => lines(p))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::math::mathml;

    #[test]
    fn every_line_renders_to_mathml() {
        for (tex, _) in PULLED_MASS.iter().chain(WOODPECKER) {
            let m = mathml(tex);
            assert!(m.starts_with("<math"), "{tex}: {m}");
            assert!(!m.contains("merror") && !m.contains("&amp;"), "{tex}: {m}");
        }
    }
}
