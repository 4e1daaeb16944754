//! The questions a worksheet can ask, per model: the quantity asked for (whose derivation step
//! answers it, whose check of the exact integration confirms it, and whose symbol and unit the
//! registry gives), what is asked, and the regimes in which its closed form can describe the
//! motion. Also the regimes a teacher can ask for and the inequalities that decide them.

use super::exercise::Exercise;
use crate::models::{with_capability, Model};
use crate::results::quantity::AnyKey;

/// A regime a worksheet can ask for: a closed-form regime of its model, by id.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Regime(&'static str);

impl Regime {
    /// The regime with this id (a model's closed-form regime id, in const context).
    pub const fn new(id: &'static str) -> Self {
        Self(id)
    }

    /// The id (`--regime`, answer-key.json).
    pub fn id(self) -> &'static str {
        self.0
    }
}

impl std::fmt::Display for Regime {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}

/// How a question is answered; each names the quantity it asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Compute a closed form: its derivation step, confirmed by its check of the exact
    /// integration of the linearized law.
    ClosedForm(AnyKey),
    /// Compute the least μd for a stick before T/2 (its derivation step), confirmed by
    /// searching that μd on the exact integration.
    Threshold(AnyKey),
    /// Decide the regime from the inequalities, confirmed by the check of the regime.
    Regime(AnyKey),
    /// Read the first speed maximum off the student's v(t) figure (the step and check of the
    /// closed form that gives it).
    ReadFigure(AnyKey),
}

impl Kind {
    /// The quantity asked for.
    pub fn quantity(self) -> AnyKey {
        match self {
            Kind::ClosedForm(k) | Kind::Threshold(k) | Kind::Regime(k) | Kind::ReadFigure(k) => k,
        }
    }
}

/// One question of the catalogue.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Question {
    pub kind: Kind,
    /// Regimes in which the answer can exist.
    pub regimes: &'static [Regime],
}

impl Question {
    /// Key used by `--questions` and in answer-key.json: the JSON key (guide §14) of the quantity, `read_`
    /// before it for the figure.
    pub fn key(&self) -> String {
        match self.kind {
            Kind::ReadFigure(k) => format!("read_{}", k.id()),
            kind => kind.quantity().id().to_string(),
        }
    }

    /// LaTeX symbol of the answer ("" for the regime).
    pub fn symbol(&self) -> &'static str {
        match self.kind {
            Kind::Regime(_) => "",
            kind => kind.quantity().quantity().tex,
        }
    }

    /// SI unit expected ("" when dimensionless or a name).
    pub fn unit(&self) -> &'static str {
        self.kind.quantity().quantity().unit
    }
}

/// The question catalogue of a model.
pub fn catalogue(model: Model) -> &'static [Question] {
    fn of<M: Exercise>(_: &M) -> &'static [Question] {
        M::catalogue()
    }
    // A model without worksheets asks no questions (`generate` refuses it first).
    with_capability!(&model, exercise, p => of(p), else &[])
}

/// Regimes a worksheet can ask for (closed-form regimes), the default first. The others
/// (immediate slip, no slip, outside the closed-form domain) leave no closed form to compute.
pub fn regimes(model: Model) -> &'static [Regime] {
    fn of<M: Exercise>(_: &M) -> &'static [Regime] {
        M::regimes()
    }
    with_capability!(&model, exercise, p => of(p), else &[])
}

/// The rules that decide the regime, as (regime, condition in LaTeX), shown with the regime
/// question (guide §9, guide §8.2, guide §8.6).
pub fn regime_rules(model: Model) -> &'static [(Regime, &'static str)] {
    fn of<M: Exercise>(_: &M) -> &'static [(Regime, &'static str)] {
        M::regime_rules()
    }
    with_capability!(&model, exercise, p => of(p), else &[])
}

/// The option of the motion question that names the closed-form regime `regime` of `model`.
pub fn regime_option(model: Model, regime: &str) -> &'static str {
    fn of<M: Exercise>(_: &M, regime: &str) -> Option<&'static str> {
        // The model's own id, so that the option is `'static`.
        let id = M::regimes()
            .iter()
            .chain(M::regime_rules().iter().map(|r| &r.0))
            .map(|r| r.id())
            .find(|id| *id == regime)?;
        Some(M::regime_option(id))
    }
    with_capability!(&model, exercise, p => of(p, regime), else None).unwrap_or("")
}
