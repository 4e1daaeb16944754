//! The engine against a 40-digit integration of the same force laws: tests/reference/mp_engine.py
//! (mpmath) integrates the pieces and the body exactly as the engine serializes them, and the
//! engine's event times, advance per period (v̄ = Δx/T) and friction dissipation per period
//! (power = E/T) must agree with it on random sets of both models and both laws, μd = μs
//! included, φ from 1e-9 up to the immediate-slip bound:
//!
//! ```text
//! event times        |Δt| ≤ 1e-12 T
//! v̄ and power        relative 1e-10   (pulled mass: φ ≥ 1e-8; woodpecker: all sets)
//! ```
//!
//! Skips (passes with a note on stderr) when python3 or mpmath is missing. The table of worst
//! errors is printed with `cargo test --release --test reference -- --nocapture`;
//! `STICKSLIP_REFERENCE=report` prints it without asserting (to measure an older engine).

#[path = "common/random_sets.rs"]
mod random_sets;

use rand::{rngs::StdRng, Rng, SeedableRng};
use serde_json::Value;
use stickslip::bench::independent::{integrate_40_digits, ScriptError};
use stickslip::engine::{integrate, Body, EventKind, ForceLaw, Run, RunOptions};
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::{pulled_mass, woodpecker, LawKind};

const PERIODS: u32 = 12;
const SETS_PER_GROUP: usize = 40;
const EVENT_TOL: f64 = 1e-12;
const VALUE_TOL: f64 = 1e-10;
/// Pulled mass: v̄ and power are held to `VALUE_TOL` from this φ up.
const PHI_MIN_FOR_VALUES: f64 = 1e-8;

struct Case {
    group: &'static str,
    /// φ = F/W (pulled mass) or ε = W_S/(k d0) (woodpecker): the small parameter of short slips.
    small: f64,
    law: ForceLaw,
    body: Body,
}

fn pulled_mass_cases(rng: &mut StdRng, law: LawKind, group: &'static str) -> Vec<Case> {
    (0..SETS_PER_GROUP)
        .map(|i| {
            let mu_s = rng.gen_range(0.1..1.0);
            let mu_d = if i % 3 == 0 {
                mu_s
            } else {
                mu_s * rng.gen_range(0.3..1.0)
            };
            // φ log-uniform from 1e-9 to just below 2μs (the immediate-slip bound), and every
            // fourth set within 1e-14..1e-2 (relative) of that bound: the slip starts near t = 0.
            let phi = if i % 4 == 1 {
                2.0 * mu_s * (1.0 - random_sets::log_uniform(rng, 1e-14, 1e-2))
            } else {
                random_sets::log_uniform(rng, 1e-9, 2.0 * mu_s * 0.9999)
            };
            let (mass, k, g) = (rng.gen_range(0.01..1.0), rng.gen_range(1.0..100.0), 9.81);
            let p = PulledMassParams {
                mu_s,
                mu_d,
                mass,
                k,
                force: phi * mass * g,
                g,
            };
            Case {
                group,
                small: p.phi(),
                law: pulled_mass::force_law(&p, law).unwrap(),
                body: pulled_mass::body(&p),
            }
        })
        .collect()
}

fn woodpecker_cases(rng: &mut StdRng, law: LawKind, group: &'static str) -> Vec<Case> {
    let mut out = Vec::new();
    while out.len() < SETS_PER_GROUP {
        let p = random_sets::woodpecker(rng, out.len());
        if p.validate().is_err() {
            continue;
        }
        let Ok(law) = woodpecker::force_law(&p, law) else {
            continue;
        };
        out.push(Case {
            group,
            small: p.sleeve_weight() / (p.k * p.d0),
            law,
            body: woodpecker::body(&p),
        });
    }
    out
}

fn cases() -> Vec<Case> {
    let mut rng = StdRng::seed_from_u64(40);
    let mut all = Vec::new();
    // The set of the issue that stalled: μd = μs, F 1e-15 N below 2μsW.
    let stalled = PulledMassParams {
        mu_s: 0.4,
        mu_d: 0.4,
        force: 0.470879999999999,
        ..PulledMassParams::default()
    };
    for (law, group) in [
        (LawKind::Harmonic, "pulled-mass harmonic"),
        (LawKind::Linear, "pulled-mass linear"),
    ] {
        all.push(Case {
            group,
            small: stalled.phi(),
            law: pulled_mass::force_law(&stalled, law).unwrap(),
            body: pulled_mass::body(&stalled),
        });
    }
    all.extend(pulled_mass_cases(
        &mut rng,
        LawKind::Harmonic,
        "pulled-mass harmonic",
    ));
    all.extend(pulled_mass_cases(
        &mut rng,
        LawKind::Linear,
        "pulled-mass linear",
    ));
    all.extend(woodpecker_cases(
        &mut rng,
        LawKind::Harmonic,
        "woodpecker harmonic",
    ));
    all.extend(woodpecker_cases(
        &mut rng,
        LawKind::Linear,
        "woodpecker linear",
    ));
    all
}

/// Runs the mpmath script on the cases; `None` when python3 or mpmath is missing.
fn reference(cases: &[Case]) -> Option<Vec<Value>> {
    let problems: Vec<_> = cases.iter().map(|c| (&c.law, &c.body)).collect();
    match integrate_40_digits(&problems, PERIODS) {
        Ok(results) => Some(results),
        Err(ScriptError::Unavailable(reason)) => {
            eprintln!("skipped: {reason}");
            None
        }
        Err(ScriptError::Failed(reason)) => panic!("reference failed: {reason}"),
    }
}

fn num(v: &Value) -> f64 {
    v.as_str().unwrap().parse().unwrap()
}

/// Transitions of period n as (t, kind, dir).
fn engine_events(run: &Run, n: u32) -> Vec<(f64, &'static str, i64)> {
    run.events
        .iter()
        .filter(|e| e.period == n && e.is_transition())
        .map(|e| match e.kind {
            EventKind::Slip { dir } => (e.t, "slip", i64::from(dir)),
            EventKind::Stick { dir } => (e.t, "stick", i64::from(dir)),
            EventKind::Reversal { to, .. } => (e.t, "reversal", i64::from(to)),
            EventKind::SpeedMax => unreachable!(),
        })
        .collect()
}

/// Worst errors of one group.
#[derive(Default)]
struct Worst {
    sets: usize,
    failed_runs: usize,
    pattern_mismatches: usize,
    event: (f64, f64),
    /// (error, small parameter) over the sets held to the value tolerance, and over all sets.
    advance: (f64, f64),
    power: (f64, f64),
    advance_all: (f64, f64),
    power_all: (f64, f64),
}

fn bump(slot: &mut (f64, f64), err: f64, small: f64) {
    if err > slot.0 || err.is_nan() {
        *slot = (err, small);
    }
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / b.abs()
    }
}

#[test]
fn engine_matches_a_40_digit_integration() {
    let cases = cases();
    let Some(reference) = reference(&cases) else {
        return;
    };
    let groups = [
        "pulled-mass harmonic",
        "pulled-mass linear",
        "woodpecker harmonic",
        "woodpecker linear",
    ];
    let mut worst: Vec<Worst> = groups.iter().map(|_| Worst::default()).collect();
    let mut notes = Vec::new();
    for (case, r) in cases.iter().zip(&reference) {
        let w = &mut worst[groups.iter().position(|g| *g == case.group).unwrap()];
        w.sets += 1;
        let opts = RunOptions {
            periods: PERIODS,
            record_segments: false,
            dissipation: true,
        };
        let run = match integrate(&case.body, &case.law, &opts) {
            Ok(run) => run,
            Err(e) => {
                w.failed_runs += 1;
                notes.push(format!("{} small {:e}: {e}", case.group, case.small));
                continue;
            }
        };
        let period = case.law.period;
        for n in 0..PERIODS {
            let mine = engine_events(&run, n);
            let theirs: Vec<(f64, String, i64)> = r["events"][n as usize]
                .as_array()
                .unwrap()
                .iter()
                .map(|e| {
                    (
                        num(&e[0]),
                        e[1].as_str().unwrap().to_string(),
                        e[2].as_i64().unwrap(),
                    )
                })
                .collect();
            let same = mine.len() == theirs.len()
                && mine
                    .iter()
                    .zip(&theirs)
                    .all(|(a, b)| a.1 == b.1 && a.2 == b.2);
            if !same {
                w.pattern_mismatches += 1;
                notes.push(format!(
                    "{} small {:e} period {n}: engine {mine:?} reference {theirs:?}",
                    case.group, case.small
                ));
                break;
            }
            for (a, b) in mine.iter().zip(&theirs) {
                bump(&mut w.event, (a.0 - b.0).abs() / period, case.small);
            }
        }
        let xs: Vec<f64> = r["x_at_period_start"]
            .as_array()
            .unwrap()
            .iter()
            .map(num)
            .collect();
        let diss: Vec<f64> = r["dissipation"]
            .as_array()
            .unwrap()
            .iter()
            .map(num)
            .collect();
        let k = PERIODS as usize;
        let advance = rel(
            run.x_at_period_start[k] - run.x_at_period_start[k - 1],
            xs[k] - xs[k - 1],
        );
        let power = rel(run.dissipation[k - 1], diss[k - 1]);
        bump(&mut w.advance_all, advance, case.small);
        bump(&mut w.power_all, power, case.small);
        if case.group.starts_with("woodpecker") || case.small >= PHI_MIN_FOR_VALUES {
            bump(&mut w.advance, advance, case.small);
            bump(&mut w.power, power, case.small);
        }
    }
    eprintln!(
        "{:<22} {:>4} {:>6} {:>8} {:>18} {:>18} {:>18} {:>18} {:>18}",
        "group",
        "sets",
        "failed",
        "patterns",
        "event |dt|/T",
        "v_avg rel",
        "power rel",
        "v_avg rel (all)",
        "power rel (all)"
    );
    let cell = |(e, s): (f64, f64)| format!("{e:.1e} @{s:.0e}");
    for (g, w) in groups.iter().zip(&worst) {
        eprintln!(
            "{g:<22} {:>4} {:>6} {:>8} {:>18} {:>18} {:>18} {:>18} {:>18}",
            w.sets,
            w.failed_runs,
            w.pattern_mismatches,
            cell(w.event),
            cell(w.advance),
            cell(w.power),
            cell(w.advance_all),
            cell(w.power_all)
        );
    }
    eprintln!("(@: φ of the pulled-mass set, ε = W_S/(k d0) of the woodpecker set)");
    for n in &notes {
        eprintln!("{n}");
    }
    if std::env::var("STICKSLIP_REFERENCE").as_deref() == Ok("report") {
        return;
    }
    for (g, w) in groups.iter().zip(&worst) {
        assert_eq!(w.failed_runs, 0, "{g}: integration failed");
        assert_eq!(w.pattern_mismatches, 0, "{g}: event pattern differs");
        assert!(
            w.event.0 <= EVENT_TOL,
            "{g}: event time error {:e}",
            w.event.0
        );
        assert!(w.advance.0 <= VALUE_TOL, "{g}: v̄ error {:e}", w.advance.0);
        assert!(w.power.0 <= VALUE_TOL, "{g}: power error {:e}", w.power.0);
    }
}
