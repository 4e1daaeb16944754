//! The benchmark problems and their exact references: the pulled mass of worked set B
//! (guide §13) and the woodpecker of Fig. 15, each under both force laws, over
//! [`PERIODS`] periods; and the boundary cases of the regime-classification study.
//!
//! ```text
//! pulled mass set B:   μs 0.4, μd 0.35, m 0.06 kg, k 45 N/m, F 0.10 N   (one slip-stick per period)
//! woodpecker Fig. 15:  the paper's default set, λ = l/h, counterpart `zeros` (two per period)
//! ```
//! The reference of every comparison is the exact engine on the same force law. The sweep
//! also takes the belt ([`super::belt`]): a [`SweepProblem`] is one of the paper's problems or
//! the belt's, and [`SweepProblem::solve`] hands each to a method as it takes it.

use serde::Serialize;

use super::belt::BeltBench;
use crate::engine::{Body, ForceLaw};
use crate::error::{Error, Result};
use crate::models::pulled_mass::formula::phi_continuous;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{LawKind, Model};
use crate::solver::exact::Exact;
use crate::solver::{Method, MethodEvent, Problem, Setting, Solution};

/// Periods integrated by every method on every problem.
pub const PERIODS: u32 = 20;
/// The intermediate halt of the harmonic woodpecker disappears above this z0 (m): the Fig. 16
/// threshold found by bisection (guide §11, claim 8).
pub const HALT_THRESHOLD_Z0: f64 = 7.0746e-3;
/// Offset of the two woodpecker boundary cases from the threshold (m).
pub const HALT_OFFSET_Z0: f64 = 1e-5;
/// Relative offset of the two pulled-mass boundary cases from φ_c.
pub const PHI_C_OFFSET: f64 = 1e-3;

/// One problem of the benchmark: a force law on a body over [`PERIODS`] periods.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchProblem {
    /// Identifier, e.g. "pulled_mass_b_linear".
    pub id: String,
    /// "pulled-mass" or "woodpecker".
    pub model: &'static str,
    pub law: LawKind,
    /// Human-readable title for tables and charts.
    pub title: String,
    pub params: Model,
    pub problem: Problem,
}

impl BenchProblem {
    /// Period T (s).
    pub fn period(&self) -> f64 {
        self.problem.law.period
    }

    /// "linear" or "harmonic".
    pub fn law_id(&self) -> &'static str {
        law_id(self.law)
    }

    /// The same problem ending one period earlier (for the mean speed of the last period).
    pub fn one_period_shorter(&self) -> Problem {
        Problem {
            t_end: self.problem.t_end - self.period(),
            ..self.problem.clone()
        }
    }
}

/// "linear" or "harmonic".
pub fn law_id(law: LawKind) -> &'static str {
    match law {
        LawKind::Linear => "linear",
        LawKind::Harmonic => "harmonic",
    }
}

/// Worked set B of guide §13.
pub fn set_b() -> PulledMassParams {
    PulledMassParams {
        mu_s: 0.4,
        mu_d: 0.35,
        force: 0.10,
        ..PulledMassParams::default()
    }
}

fn problem(body: Body, law: ForceLaw) -> Problem {
    let t_end = f64::from(PERIODS) * law.period;
    Problem { body, law, t_end }
}

/// The problem of `model` under `law`.
pub fn of(id: &str, title: &str, model: Model, law: LawKind) -> Result<BenchProblem> {
    model.validate()?;
    Ok(BenchProblem {
        id: format!("{id}_{}", law_id(law)),
        model: model.id(),
        law,
        title: format!("{title}, {} law", law_id(law)),
        params: model,
        problem: problem(model.body(), model.force_law(law)?),
    })
}

/// A pulled-mass problem under the given law.
pub fn pulled(id: &str, title: &str, p: PulledMassParams, law: LawKind) -> Result<BenchProblem> {
    of(id, title, Model::PulledMass(p), law)
}

/// A woodpecker problem under the given law.
pub fn wood(id: &str, title: &str, p: WoodpeckerParams, law: LawKind) -> Result<BenchProblem> {
    of(id, title, Model::Woodpecker(p), law)
}

/// A problem of the work-precision sweep: one of the paper's (forces of time only, a
/// [`Problem`]) or the belt (a force of the position on a moving surface, a
/// [`crate::solver::surface::SurfaceProblem`]).
#[derive(Clone, Debug, PartialEq)]
pub enum SweepProblem {
    Paper(BenchProblem),
    Belt(BeltBench),
}

impl SweepProblem {
    /// Identifier, e.g. "pulled_mass_b_linear" or "belt_default".
    pub fn id(&self) -> &str {
        match self {
            SweepProblem::Paper(bp) => &bp.id,
            SweepProblem::Belt(_) => super::belt::ID,
        }
    }

    /// Human-readable title for tables and charts.
    pub fn title(&self) -> String {
        match self {
            SweepProblem::Paper(bp) => bp.title.clone(),
            SweepProblem::Belt(_) => super::belt::TITLE.to_string(),
        }
    }

    /// The model's id ("pulled-mass", "woodpecker", "belt").
    pub fn model(&self) -> &'static str {
        self.params().id()
    }

    /// "linear" or "harmonic" for the paper's force laws, "spring" for the belt (its force is
    /// the spring's −k x, with no forcing law).
    pub fn law_id(&self) -> &'static str {
        match self {
            SweepProblem::Paper(bp) => bp.law_id(),
            SweepProblem::Belt(_) => super::belt::LAW,
        }
    }

    pub fn params(&self) -> Model {
        match self {
            SweepProblem::Paper(bp) => bp.params,
            SweepProblem::Belt(b) => Model::Belt(b.params),
        }
    }

    /// The period T (s): of the forcing, or of the belt's stick-slip cycle.
    pub fn period(&self) -> f64 {
        match self {
            SweepProblem::Paper(bp) => bp.period(),
            SweepProblem::Belt(b) => b.closed.period,
        }
    }

    /// Final time (s).
    pub fn t_end(&self) -> f64 {
        match self {
            SweepProblem::Paper(bp) => bp.problem.t_end,
            SweepProblem::Belt(b) => b.problem.t_end,
        }
    }

    /// The paper's problem, `None` for the belt (the studies defined on the paper's problems).
    pub fn paper(&self) -> Option<&BenchProblem> {
        match self {
            SweepProblem::Paper(bp) => Some(bp),
            SweepProblem::Belt(_) => None,
        }
    }

    /// Why the mean speed of the last period is not compared, `None` where it is.
    pub fn vbar_not_applicable(&self) -> Option<&'static str> {
        match self {
            SweepProblem::Paper(_) => None,
            SweepProblem::Belt(_) => Some(super::belt::VBAR_NOT_APPLICABLE),
        }
    }

    /// The one dispatch of the sweep: [`Method::solve`] on a paper problem,
    /// [`Method::solve_surface`] on the belt (refused by a method that takes forces of time
    /// only: see [`is_refusal`]).
    pub fn solve(&self, method: &dyn Method, setting: Setting) -> Result<Solution> {
        match self {
            SweepProblem::Paper(bp) => method.solve(&bp.problem, setting),
            SweepProblem::Belt(b) => method.solve_surface(&b.problem, setting),
        }
    }

    /// The work the sweep times: [`Method::solve_timed`] on a paper problem,
    /// [`Method::solve_surface`] on the belt.
    pub fn solve_timed(&self, method: &dyn Method, setting: Setting) -> Result<()> {
        match self {
            SweepProblem::Paper(bp) => method.solve_timed(&bp.problem, setting),
            SweepProblem::Belt(b) => method.solve_surface(&b.problem, setting).map(drop),
        }
    }

    /// The run one period shorter (for the mean speed of the last period), `None` where that
    /// speed is not compared.
    pub fn solve_one_period_shorter(
        &self,
        method: &dyn Method,
        setting: Setting,
    ) -> Option<Result<Solution>> {
        self.paper()
            .map(|bp| method.solve(&bp.one_period_shorter(), setting))
    }
}

/// True for a method's refusal of a problem it does not take (a force depending on the
/// position, for a method of forces of time only): the error names the parameter "method".
pub fn is_refusal(e: &Error) -> bool {
    matches!(e, Error::InvalidParam { name: "method", .. })
}

/// The problems of the work-precision sweep: the paper's four, then the belt.
pub fn sweep() -> Result<Vec<SweepProblem>> {
    let mut out: Vec<SweepProblem> = sweep_problems()?
        .into_iter()
        .map(SweepProblem::Paper)
        .collect();
    out.push(SweepProblem::Belt(super::belt::bench()?));
    Ok(out)
}

/// The four problems of the paper in the work-precision sweep.
pub fn sweep_problems() -> Result<Vec<BenchProblem>> {
    let laws = [LawKind::Linear, LawKind::Harmonic];
    let mut out = Vec::with_capacity(4);
    for law in laws {
        out.push(pulled("pulled_mass_b", "Pulled mass, set B", set_b(), law)?);
    }
    for law in laws {
        let p = WoodpeckerParams::default();
        out.push(wood("woodpecker_fig15", "Woodpecker, Fig. 15", p, law)?);
    }
    Ok(out)
}

/// The boundary cases of the regime-classification study: the pulled mass (set B friction,
/// linear law) just below and just above φ_c, where the speed touches zero tangentially, and the
/// harmonic woodpecker just below and just above the Fig. 16 threshold of the intermediate halt.
pub fn boundary_problems() -> Result<Vec<BenchProblem>> {
    let b = set_b();
    let phi_c = phi_continuous(b.mu_s, b.mu_d);
    let mut out = Vec::with_capacity(4);
    for (tag, sign) in [("below", -1.0), ("above", 1.0)] {
        let phi = phi_c * (1.0 + sign * PHI_C_OFFSET);
        let p = PulledMassParams {
            force: phi * b.weight(),
            ..b
        };
        let title = format!("Pulled mass, φ = φ_c (1 {} 10⁻³)", sign_char(sign));
        out.push(pulled(
            &format!("pulled_mass_phi_c_{tag}"),
            &title,
            p,
            LawKind::Linear,
        )?);
    }
    for (tag, sign) in [("below", -1.0), ("above", 1.0)] {
        let z0 = HALT_THRESHOLD_Z0 + sign * HALT_OFFSET_Z0;
        let p = WoodpeckerParams {
            z0,
            ..WoodpeckerParams::default()
        };
        let title = format!("Woodpecker, z0 = {:.4} mm", z0 * 1e3);
        out.push(wood(
            &format!("woodpecker_halt_{tag}"),
            &title,
            p,
            LawKind::Harmonic,
        )?);
    }
    Ok(out)
}

/// The title of the sweep or boundary problem `id` ("Pulled mass, set B, linear law"), for the
/// tables a person reads; an unknown id is returned as it is.
pub fn title(id: &str) -> String {
    static TITLES: std::sync::OnceLock<Vec<(String, String)>> = std::sync::OnceLock::new();
    let titles = TITLES.get_or_init(|| {
        let all = [sweep_problems(), boundary_problems()];
        let mut titles: Vec<(String, String)> = all
            .into_iter()
            .flatten()
            .flatten()
            .map(|bp| (bp.id, bp.title))
            .collect();
        titles.push((super::belt::ID.to_string(), super::belt::TITLE.to_string()));
        titles
    });
    titles
        .iter()
        .find(|(k, _)| k == id)
        .map_or_else(|| id.to_string(), |(_, t)| t.clone())
}

fn sign_char(sign: f64) -> char {
    if sign < 0.0 {
        '−'
    } else {
        '+'
    }
}

/// What the exact engine gives on a problem: the reference of every error.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Reference {
    /// Slip and stick events over the whole run.
    pub events: Vec<MethodEvent>,
    /// Position (m) and velocity (m/s) at t_end.
    pub x_end_m: f64,
    pub v_end_m_s: f64,
    /// Mean speed over the last period (m/s); `None` where it is not compared (the belt:
    /// [`SweepProblem::vbar_not_applicable`]).
    pub vbar_m_s: Option<f64>,
}

/// Slip and stick events only: reversals are counted apart (see [`super::sweep`]).
pub fn transitions(events: &[MethodEvent]) -> Vec<MethodEvent> {
    events
        .iter()
        .filter(|e| e.kind == "slip" || e.kind == "stick")
        .copied()
        .collect()
}

/// Runs the exact engine on `bp` (and one period shorter, for the mean speed).
pub fn reference(bp: &BenchProblem) -> Result<Reference> {
    let setting = Setting::Tolerance(REFERENCE_TOLERANCE);
    let full = Exact.solve(&bp.problem, setting)?;
    let shorter = Exact.solve(&bp.one_period_shorter(), setting)?;
    Ok(Reference {
        events: transitions(&full.events),
        x_end_m: full.x_end,
        v_end_m_s: full.v_end,
        vbar_m_s: Some((full.x_end - shorter.x_end) / bp.period()),
    })
}

/// The exact reference of a problem of the sweep.
pub fn sweep_reference(sp: &SweepProblem) -> Result<Reference> {
    match sp {
        SweepProblem::Paper(bp) => reference(bp),
        SweepProblem::Belt(b) => super::belt::reference(b),
    }
}

/// The setting handed to the exact engine (which ignores it).
pub const REFERENCE_TOLERANCE: f64 = 1e-15;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_read_as_titles() {
        assert_eq!(
            title("pulled_mass_b_linear"),
            "Pulled mass, set B, linear law"
        );
        assert_eq!(
            title("woodpecker_halt_below_harmonic"),
            "Woodpecker, z0 = 7.0646 mm, harmonic law"
        );
        assert_eq!(title("belt_default"), super::super::belt::TITLE);
        assert_eq!(title("no_such_problem"), "no_such_problem");
    }

    #[test]
    fn set_b_references_have_one_slip_and_one_stick_per_period() {
        let problems = sweep_problems().unwrap();
        assert_eq!(problems.len(), 4);
        for bp in &problems[..2] {
            let r = reference(bp).unwrap();
            assert_eq!(r.events.len(), 2 * PERIODS as usize, "{}", bp.id);
            assert!(r.vbar_m_s.unwrap() > 0.0);
        }
        // Set B, linear law: v̄ = 5.396971 mm/s (guide §13).
        let r = reference(&problems[0]).unwrap();
        let vbar = r.vbar_m_s.unwrap();
        assert!((vbar - 5.396971e-3).abs() < 1e-8, "{vbar}");
    }

    #[test]
    fn boundary_cases_straddle_their_thresholds() {
        let cases = boundary_problems().unwrap();
        let last_period = |bp: &BenchProblem| {
            let r = reference(bp).unwrap();
            let t0 = bp.problem.t_end - bp.period();
            r.events.iter().filter(|e| e.t >= t0).count()
        };
        let counts: Vec<usize> = cases.iter().map(last_period).collect();
        assert_eq!(counts, [2, 0, 4, 2], "{:?}", counts);
    }
}
