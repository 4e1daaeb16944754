//! The belt for the presentation layer ([`Present`]): its part of the report, its built-in
//! scenes, figures, sketch, tables, worked derivation, handout notes, terminal tables and CSV
//! files. Its one law is the exact integration of the autonomous system; its closed forms are
//! exact for it (docs/belt.md), not those of a linearization.

use std::fmt::Write as _;

use super::formula::Regime;
use super::quantity::Key;
use super::results::{self, Evaluation};
use super::{derivation, scene, scenes, sketch, teaching, BeltParams};
use crate::derivation::{Step, StepKey, Value};
use crate::engine::autonomous::SurfaceRun;
use crate::error::Result;
use crate::export::num as csv_num;
use crate::format::short;
use crate::models::Physics;
use crate::output::text::{checks_table, closed_form_table, DIGITS as TEXT_DIGITS};
use crate::present::vocab::{
    Builtin, Column, Figure, FigureKinds, LawName, LawPoint, LawWords, Note, OutFile, PartStory,
    Phase, RegimeRow, Scene, SceneCtx, SweepColumn,
};
use crate::present::{DefaultSweep, Laws, Present, StandardScene};
use crate::report::context::{blank, count, fill_checks, input, row};
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
    summary: "integration",
}];

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
        derivation::belt(self)
    }

    fn derivation_values(&self) -> Vec<Step<Value>> {
        derivation::belt_values(self)
    }

    fn handout_note(key: StepKey) -> Option<(Note, Option<&'static str>)> {
        teaching::STEPS
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, n)| (*n, None))
    }

    fn equation_of_motion() -> &'static [(&'static str, &'static str)] {
        teaching::EQUATION_OF_MOTION
    }

    fn sketch(&self, phase: Phase) -> String {
        sketch::belt(self, phase)
    }

    /// One cycle: a slip and a stick (none in a touching oscillation); the block comes back
    /// to where the cycle started, so its mean speed over a cycle is zero.
    fn laws(e: &Evaluation) -> Laws {
        // The block oscillates about a fixed point: no mean speed (the sweep's columns are
        // the belt's own, `sweep_columns`).
        let run = e.integration.regime.map(|regime| LawPoint {
            v_avg: None,
            slips: 1,
            sticks: u32::from(regime == Regime::StickSlip.id()),
            regime,
        });
        Laws {
            runs: vec![run],
            closed_form_regime: e.closed_form.regime.id(),
        }
    }

    /// The cycle the integration measured: its period, amplitude and stick share.
    fn sweep_columns() -> Vec<SweepColumn<Evaluation>> {
        vec![
            SweepColumn {
                head: Column {
                    column: "period_s",
                    label: "T (s)",
                    scale: 1.0,
                },
                value: |e| e.integration.period,
            },
            SweepColumn {
                head: Column {
                    column: "amplitude_m",
                    label: "A (mm)",
                    scale: 1e3,
                },
                value: |e| e.integration.amplitude,
            },
            SweepColumn {
                head: Column {
                    column: "stick_share",
                    label: "stick share",
                    scale: 1.0,
                },
                value: |e| e.integration.stick_share,
            },
        ]
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
    use crate::results::quantity::AnyKey;

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
