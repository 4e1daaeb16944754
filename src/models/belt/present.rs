//! The belt for the presentation layer ([`Present`]): its part of the report, its built-in
//! scenes, figures, sketch, tables, worked derivation, handout notes, terminal tables and CSV
//! files. Its one law is the exact integration of the autonomous system; its closed forms are
//! exact for it (docs/belt.md), not those of a linearization.

use std::fmt::Write as _;

use super::formula::{self as cf, Regime};
use super::quantity::Key;
use super::results::{self, Evaluation};
use super::{scene, scenes, sketch, BeltParams};
use crate::derivation::expr::{arctan, given, int, pi, pow, sqrt};
use crate::derivation::{Param, Step, StepKey, Steps};
use crate::engine::autonomous::SurfaceRun;
use crate::error::Result;
use crate::export::num as csv_num;
use crate::models::Physics;
use crate::output::format::short;
use crate::output::text::{checks_table, closed_form_table, DIGITS as TEXT_DIGITS};
use crate::present::vocab::{
    Builtin, Figure, FigureKinds, LawName, LawPoint, LawWords, Note, OutFile, PartStory, Phase,
    RegimeRow, Scene, SceneCtx,
};
use crate::present::{DefaultSweep, Laws, Present, StandardScene};
use crate::report::context::{blank, count, fill_checks, input, row};
use crate::results::quantity::AnyKey;
use crate::results::summary::kind_name;

crate::present::vocab::figure_kinds! {
    /// What a scene of the belt draws.
    pub enum BeltFigure {
        /// x(t) and v(t) over some cycles with the belt's speed and the closed forms' times.
        Motion { cycles: f64 } = "belt-motion",
        /// v(x): the harmonic arc about x_d closed by the stick at v = v_b.
        PhasePortrait = "belt-phase-portrait",
    }
}

/// The belt's one law: the exact integration of the autonomous system.
const LAWS: &[LawName] = &[LawName {
    id: "exact",
    name: "exact integration",
}];

/// The derived parameters with a step (the `params` keys of `eval --json`).
mod param {
    use crate::derivation::Param;

    /// ω = √(k/m) (B1).
    pub const OMEGA: Param = Param {
        id: "omega",
        tex: r"\omega",
        equation: "(B1)",
        unit: "rad/s",
    };
    /// x_s = μs m g / k (B2).
    pub const X_S: Param = Param {
        id: "x_s",
        tex: "x_s",
        equation: "(B2)",
        unit: "m",
    };
    /// x_d = μd m g / k (B3).
    pub const X_D: Param = Param {
        id: "x_d",
        tex: "x_d",
        equation: "(B3)",
        unit: "m",
    };
    /// Δ = x_s − x_d (B4).
    pub const DELTA: Param = Param {
        id: "delta",
        tex: r"\Delta",
        equation: "(B4)",
        unit: "m",
    };
}

/// (LaTeX, sentence) lines of the belt's equation of motion (docs/belt.md).
const EQUATION_OF_MOTION: &[(&str, &str)] = &[
    (
        r"m\,\ddot x = -k\,x + \mu_d\,m g \quad (\dot x < v_b)",
        "while slipping back: the spring pulls towards the wall, dynamic friction drags the \
         block along the belt",
    ),
    (
        r"\dot x = v_b \quad \text{while}\quad k\,x \le \mu_s\,m g",
        "stuck: the block rides with the belt while static friction can hold the spring",
    ),
    (
        r"x(t) = x_d + A\cos(\omega t + \theta), \quad \omega = \sqrt{k/m}",
        "each slip is one harmonic arc about x_d = μd m g/k; it ends when v returns to v_b",
    ),
];

/// How the handout explains each step.
fn note(key: StepKey) -> Option<Note> {
    let quantity = |k: Key| StepKey::Quantity(AnyKey::from(k)) == key;
    Some(match key {
        StepKey::Param(p) if p == param::OMEGA => Note::Label("angular frequency of the slip"),
        StepKey::Param(p) if p == param::X_S => Note::Label("where static friction lets go"),
        StepKey::Param(p) if p == param::X_D => Note::Label("centre of the slip arc"),
        StepKey::Param(p) if p == param::DELTA => Note::Label("how far the slip swings past x_d"),
        _ if quantity(Key::FirstSlipTime) => {
            Note::Sentence("carried from x = 0 at the belt's speed until the spring holds μs m g")
        }
        _ if quantity(Key::Amplitude) => {
            Note::Sentence("the arc starts at x_s with the belt's speed: both set its amplitude")
        }
        _ if quantity(Key::TSlip) => {
            Note::Sentence("the arc runs until the speed is back to v_b, past its turning point")
        }
        _ if quantity(Key::TStick) => {
            Note::Sentence("carried from x_e = x_d − Δ back to x_s at the belt's speed")
        }
        _ if quantity(Key::Period) => Note::Sentence("one slip and one stick: the cycle repeats"),
        _ if quantity(Key::EnergyPerCycle) => {
            Note::Sentence("friction μd m g over the distance slid relative to the belt")
        }
        StepKey::Quantity(_) => Note::Numbers,
        StepKey::Param(_) => return None,
    })
}

impl Present for BeltParams {
    const SKETCH_WHAT: &'static str =
        "the block held by the spring to the wall, on the belt moving at v_b";
    const SKETCH_WHEN: &'static str =
        "in the middle of the slip (x = x_d, the fastest backward motion)";
    /// The belt's speed from 0.01 to 0.6 m/s in 0.01 m/s steps: the stick shrinks as the belt
    /// speeds up while the slip's amplitude grows.
    const SWEEP: DefaultSweep = DefaultSweep {
        param: "v_b",
        from: 0.01,
        to: 0.6,
        steps: 60,
    };
    const PART: PartStory = PartStory {
        title: "The textbook oscillator",
        story: "A block on a belt moving at constant speed v_b, held to a wall by a spring: \
                the same stick condition as the paper's, friction holding up to μs N, with a \
                different forcing, a spring force that depends on the position and a surface \
                that moves. The pages follow one cycle (carried with the belt, one harmonic \
                slip back, stuck again), then μd = μs and a fast belt; every closed form is \
                exact and checked against the integration.",
    };
    const LAWS: &'static [LawName] = LAWS;
    const LAW_WORDS: LawWords = LawWords {
        closed_form_law: "exact for the autonomous system",
        checked_against: "exact integration of the same autonomous system",
        numeric_from: "exact event-driven integration of the same system (one harmonic arc per \
                       slip, the stick at the belt's speed), its last cycle",
    };
    type Figure = BeltFigure;
    type Apparatus = ();

    /// The belt is not on the explorer page: nothing to draw there.
    fn apparatus() {}

    fn words(code: &str) -> Option<&'static str> {
        match code {
            "en" => Some(include_str!("lang/en.toml")),
            "it" => Some(include_str!("lang/it.toml")),
            _ => None,
        }
    }

    fn builtin_scenes() -> Vec<Builtin> {
        scenes::builtins()
    }

    fn standard_scene(&self) -> StandardScene {
        StandardScene {
            figures: vec![
                BeltFigure::Motion { cycles: 3.0 }.kind(),
                BeltFigure::PhasePortrait.kind(),
            ],
            claims: Vec::new(),
            caption: "Motion of the block on the belt and its phase portrait: carried at the \
                      belt's speed, one harmonic slip back, stuck again.",
        }
    }

    fn figures(&self, scene_id: &str, kind: BeltFigure) -> Result<Vec<Figure>> {
        Ok(vec![match kind {
            BeltFigure::Motion { cycles } => scene::motion(scene_id, self, cycles)?,
            BeltFigure::PhasePortrait => scene::phase_portrait(scene_id, self)?,
        }])
    }

    fn scene_tables(&self, scene: &Scene) -> Result<SceneCtx> {
        let e = results::evaluate(self, scene.periods)?;
        let c = &e.closed_form;
        let mut ctx = blank(scene, "belt");
        ctx.params = vec![
            input("m (block)", self.mass, "kg"),
            input("k (spring)", self.k, "N/m"),
            input("v_b (belt speed)", self.v_b, "m/s"),
            input("μs (static friction)", self.mu_s, ""),
            input("μd (dynamic friction)", self.mu_d, ""),
            input("g", self.g, "m/s²"),
            row("ω = √(k/m)", c.omega, "rad/s"),
            row("x_s = μs m g/k", c.x_s, "m"),
            row("x_d = μd m g/k", c.x_d, "m"),
            row("Δ = x_s − x_d", c.delta, "m"),
            count("cycles integrated", e.params.cycles),
        ];
        let measured = e.integration.regime.unwrap_or("no complete cycle");
        ctx.regimes = vec![
            RegimeRow {
                law: "closed forms".to_string(),
                regime: c.regime.words().to_string(),
                why: regime_reason(c.delta),
            },
            RegimeRow {
                law: "exact integration".to_string(),
                regime: Self::regime_words(measured).unwrap_or(measured).to_string(),
                why: format!("its last cycle of {}", e.params.cycles),
            },
        ];
        fill_checks(&mut ctx, |k: Key| c.value(k).number(), &e.checks, &[]);
        Ok(ctx)
    }

    fn derivation(&self) -> Vec<Step> {
        derivation(self)
    }

    fn handout_note(key: StepKey) -> Option<(Note, Option<&'static str>)> {
        note(key).map(|n| (n, None))
    }

    fn equation_of_motion() -> &'static [(&'static str, &'static str)] {
        EQUATION_OF_MOTION
    }

    fn sketch(&self, phase: Phase) -> String {
        sketch::belt(self, phase)
    }

    /// One cycle: a slip and a stick (none in a touching oscillation); the block comes back
    /// to where the cycle started, so its mean speed over a cycle is zero.
    fn laws(e: &Evaluation) -> Laws {
        let run = e.integration.regime.map(|regime| LawPoint {
            v_avg: Some(0.0),
            slips: 1,
            sticks: u32::from(regime == Regime::StickSlip.id()),
            regime,
        });
        Laws {
            runs: vec![run],
            closed_form_regime: e.closed_form.regime.id(),
        }
    }

    fn text(e: &Evaluation) -> String {
        text(e)
    }

    fn evaluate_with_csv(&self, periods: u32) -> Result<(Evaluation, Vec<OutFile>)> {
        let (evaluation, run) = results::evaluate_with_run(self, periods)?;
        let files = csv_files(LAWS[0].id, &run);
        Ok((evaluation, files))
    }
}

/// Why the closed forms' regime is what it is.
fn regime_reason(delta: f64) -> String {
    if delta > 0.0 {
        format!(
            "Δ = x_s − x_d = {} mm > 0: the slip ends short of x_s and the belt carries the \
             block back",
            short(Some(delta * 1e3), 6)
        )
    } else {
        "Δ = 0 (μd = μs): the arc returns to x_s at the belt's speed, no stick".to_string()
    }
}

/// Every closed form of the belt with `p`'s numbers, in the order a derivation reads
/// (docs/belt.md (B1)–(B17)).
fn derivation(p: &BeltParams) -> Vec<Step> {
    let c = cf::evaluate(p);
    let mut s = Steps::<Key>::new(&[]);
    let (m, k, g, v_b) = (
        given("m", p.mass),
        given("k", p.k),
        given("g", p.g),
        given("v_b", p.v_b),
    );
    let (mu_s, mu_d) = (given(r"\mu_s", p.mu_s), given(r"\mu_d", p.mu_d));
    let step = |s: &mut Steps<Key>, param: Param, e, v| s.push_param(param, e, Some(v));
    let omega = step(&mut s, param::OMEGA, sqrt(k.clone() / m.clone()), c.omega);
    let x_s = step(
        &mut s,
        param::X_S,
        mu_s * m.clone() * g.clone() / k.clone(),
        c.x_s,
    );
    let x_d = step(
        &mut s,
        param::X_D,
        mu_d.clone() * m.clone() * g.clone() / k,
        c.x_d,
    );
    let delta = step(&mut s, param::DELTA, x_s.clone() - x_d.clone(), c.delta);
    s.push(
        Key::FirstSlipTime,
        x_s / v_b.clone(),
        Some(c.first_slip_time),
    );
    let a = s.push(
        Key::Amplitude,
        sqrt(pow(delta.clone(), 2) + pow(v_b.clone() / omega.clone(), 2)),
        Some(c.amplitude),
    );
    let t_slip = s.push(
        Key::TSlip,
        int(2) / omega.clone() * (pi() - arctan(omega.clone() * delta.clone() / v_b.clone())),
        Some(c.t_slip),
    );
    s.push(
        Key::XSlipEnd,
        x_d.clone() - delta.clone(),
        Some(c.x_slip_end),
    );
    let t_stick = s.push(
        Key::TStick,
        int(2) * delta.clone() / v_b.clone(),
        Some(c.t_stick),
    );
    let period = s.push(
        Key::Period,
        t_slip.clone() + t_stick.clone(),
        Some(c.period),
    );
    s.push(Key::XMax, x_d.clone() + a.clone(), Some(c.x_max));
    s.push(Key::XMin, x_d - a.clone(), Some(c.x_min));
    s.push(Key::VMin, int(0) - omega.clone() * a.clone(), Some(c.v_min));
    s.push(
        Key::SlipSpeedMax,
        v_b.clone() + omega * a,
        Some(c.slip_speed_max),
    );
    let energy = s.push(
        Key::EnergyPerCycle,
        mu_d * m * g * (int(2) * delta + v_b * t_slip.clone()),
        Some(c.energy_per_cycle),
    );
    s.push(
        Key::PowerFriction,
        energy.clone() / period.clone(),
        Some(c.power),
    );
    s.push(Key::PowerBelt, energy / period.clone(), Some(c.power));
    s.push(
        Key::StickShare,
        t_stick / period.clone(),
        Some(c.stick_share),
    );
    s.push(Key::SlipShare, t_slip / period, Some(c.slip_share));
    s.steps
}

/// The evaluation as terminal tables: parameters, closed forms, checks, the integration.
fn text(e: &Evaluation) -> String {
    let p = &e.params;
    let i = &p.input;
    let c = &e.closed_form;
    let mut out = String::new();
    let _ = writeln!(out, "stickslip eval belt");
    let _ = writeln!(
        out,
        "parameters: m = {} kg, k = {} N/m, v_b = {} m/s, mu_s = {}, mu_d = {}, g = {} m/s², \
         cycles = {}",
        csv_num(i.mass),
        csv_num(i.k),
        csv_num(i.v_b),
        csv_num(i.mu_s),
        csv_num(i.mu_d),
        csv_num(i.g),
        p.cycles
    );
    let _ = writeln!(
        out,
        "derived:    omega = {} rad/s, x_s = {} m, x_d = {} m, delta = {} m",
        short(Some(p.omega), TEXT_DIGITS),
        short(Some(p.x_s), TEXT_DIGITS),
        short(Some(p.x_d), TEXT_DIGITS),
        short(Some(p.delta), TEXT_DIGITS)
    );
    let _ = writeln!(
        out,
        "\nregime (closed forms): {} ({}); {}",
        c.regime.words(),
        c.regime.id(),
        regime_reason(c.delta)
    );
    let words = <BeltParams as Present>::LAW_WORDS;
    closed_form_table(&mut out, &words, |k: Key| c.value(k).number());
    checks_table(&mut out, &words, &e.checks);
    let m = &e.integration;
    let _ = writeln!(
        out,
        "\nexact integration: the last of {} cycles ({})",
        m.cycles,
        m.regime
            .and_then(BeltParams::regime_words)
            .unwrap_or("no complete cycle")
    );
    for (name, value, unit) in [
        ("first slip", m.first_slip_time, "s"),
        ("slip time", m.t_slip, "s"),
        ("stick time", m.t_stick, "s"),
        ("period", m.period, "s"),
        ("amplitude", m.amplitude, "m"),
        ("friction power", m.power_friction, "W"),
        ("belt power", m.power_belt, "W"),
    ] {
        let _ = writeln!(out, "  {name:<26} {:>22} {unit}", short(value, TEXT_DIGITS));
    }
    out
}

/// `timeseries_<law>.csv` (t, x, v, a on a uniform grid with the events) and
/// `events_<law>.csv` (every slip and stick with its cycle) of the exact run.
fn csv_files(law: &str, run: &SurfaceRun) -> Vec<OutFile> {
    let end = run.events.last().map_or(0.0, |e| e.t);
    let n = 200 * run.events.len().max(1);
    let mut times: Vec<f64> = (0..=n)
        .map(|j| end * j as f64 / n as f64)
        .chain(run.events.iter().map(|e| e.t))
        .collect();
    times.sort_by(f64::total_cmp);
    times.dedup();
    let mut series = String::from("t_s,x_m,v_m_s,a_m_s2\n");
    for t in times {
        if let Some((x, v, a)) = run.state_at(t) {
            let _ = writeln!(
                series,
                "{},{},{},{}",
                csv_num(t),
                csv_num(x),
                csv_num(v),
                csv_num(a)
            );
        }
    }
    let mut events = String::from("t_s,kind,cycle,x_m,v_m_s\n");
    for e in &run.events {
        let _ = writeln!(
            events,
            "{},{},{},{},{}",
            csv_num(e.t),
            kind_name(e.kind),
            e.period,
            csv_num(e.x),
            csv_num(e.v)
        );
    }
    vec![
        OutFile::new(format!("timeseries_{law}.csv"), series),
        OutFile::new(format!("events_{law}.csv"), events),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every worked step reproduces its closed form, the arctan of (B8) included.
    #[test]
    fn the_derivation_reproduces_every_closed_form() {
        for p in super::super::test_sets() {
            let steps = p.derivation();
            assert!(steps.len() >= 18, "{}", steps.len());
            for step in &steps {
                let (Some(value), evaluated) = (step.value, step.expr.eval()) else {
                    continue;
                };
                let scale = value.abs().max(1e-300);
                assert!(
                    (evaluated - value).abs() <= 1e-12 * scale,
                    "{}: {evaluated} vs {value}",
                    step.symbol
                );
            }
            let t_slip = StepKey::Quantity(AnyKey::from(Key::TSlip));
            let t_slip = steps.iter().find(|s| s.key == t_slip).unwrap();
            assert!(
                t_slip.formula().contains(r"\arctan"),
                "{}",
                t_slip.formula()
            );
        }
    }

    /// The terminal tables name the belt's law, never the paper's two.
    #[test]
    fn the_text_tables_name_the_belts_own_law() {
        let e = results::evaluate(&BeltParams::default(), 5).unwrap();
        let text = BeltParams::text(&e);
        assert!(text.contains("exact integration of the same autonomous system"));
        for word in ["lineari", "harmonic law", "pulled", "woodpecker"] {
            assert!(!text.contains(word), "{word}: {text}");
        }
        let (_, files) = BeltParams::default().evaluate_with_csv(3).unwrap();
        let events = String::from_utf8(files[1].bytes.clone()).unwrap();
        assert!(events.starts_with("t_s,kind,cycle,x_m,v_m_s\n"));
        assert!(events.contains("slip") && events.contains("stick"));
    }
}
