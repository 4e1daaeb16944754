//! The engine against a 40-digit integration that shares nothing with it:
//! tests/reference/mp_engine.py builds the forces from the parameters alone (guide §5.1, guide §5.2,
//! guide §5.2 in exact arithmetic on the given doubles: W, ω, T, the triangle waves, F_e and its zeros,
//! the counterparts, λ) and integrates the state machine of guide §4 at 40 digits or more; the engine's
//! numbers are those `stickslip eval … --json` prints (`evaluate`, both laws). The sets sample
//! where double precision is hard pressed, each on both laws:
//!
//! ```text
//! pulled mass   small φ with large μs (φ from 1e-9), near φ_c (late stick, a double root),
//!               μd → μs, the issue's example, ordinary sets
//! woodpecker    small ε = W_S/(k ζ0) (from 1e-9), μd = μs, ordinary sets
//!
//! v̄, advance per period, driving power, friction power, each speed maximum:
//!     relative error ≤ max(1e-10, 4·s)
//! steady event times:  |Δt|/T ≤ max(1e-12, 4·s)
//! ```
//!
//! where s, the truth's own sensitivity, is the largest change of the 40-digit value when one
//! input moves by one ulp (each input in turn): what the inputs' conditioning allows and no more.
//! Below the ε the tool can honour the woodpecker is refused, as the pulled mass is below φ = 1e-9.
//!
//! Skips (passes with a note on stderr) when python3 or mpmath is missing. The table of worst
//! errors per region is printed with `cargo test --release --test reference -- --nocapture`;
//! `STICKSLIP_REFERENCE=report` prints it without asserting; `STICKSLIP_REFERENCE_SETS=FILE`
//! writes the sets, on which tests/reference/compare_cli.py measures any built binary (an older
//! one included) against the same truth.

#[path = "common/random_sets.rs"]
mod random_sets;

use rand::{rngs::StdRng, Rng, SeedableRng};
use serde_json::{json, Value};
use stickslip::bench::independent::{run_script, ScriptError};
use stickslip::error::Error;
use stickslip::models::pulled_mass::formula as pm;
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::woodpecker::formula::Counterpart;
use stickslip::models::woodpecker::{OmegaMode, WoodpeckerParams};
use stickslip::models::{pulled_mass, woodpecker, LawKind};
use stickslip::results::summary::Summary;

const PERIODS: u32 = 10;
const VALUE_TOL: f64 = 1e-10;
const EVENT_TOL: f64 = 1e-12;
/// The tolerance's floor is this many times the truth's change under a one-ulp input change.
const SENSITIVITY_FACTOR: f64 = 4.0;

/// The next double above x (f64::next_up, stable after this crate's MSRV).
fn next_up(x: f64) -> f64 {
    match x {
        x if x > 0.0 => f64::from_bits(x.to_bits() + 1),
        x if x < 0.0 => f64::from_bits(x.to_bits() - 1),
        _ => f64::from_bits(1),
    }
}

/// The next double below a positive x.
fn next_down(x: f64) -> f64 {
    f64::from_bits(x.to_bits() - 1)
}

#[derive(Clone, Copy)]
enum Params {
    Pulled(PulledMassParams),
    Wood(WoodpeckerParams),
}

struct Set {
    region: &'static str,
    params: Params,
}

impl Params {
    fn json(&self) -> (&'static str, Value) {
        match self {
            Params::Pulled(p) => ("pulled-mass", serde_json::to_value(p).unwrap()),
            Params::Wood(p) => ("woodpecker", serde_json::to_value(p).unwrap()),
        }
    }

    /// φ (pulled mass) or ε = W_S/(k ζ0) of the law (woodpecker): the small parameter.
    fn small(&self, law: LawKind) -> f64 {
        match self {
            Params::Pulled(p) => p.phi(),
            Params::Wood(p) => {
                let zeta0 = match law {
                    LawKind::Harmonic => Some(p.d0),
                    LawKind::Linear => woodpecker::linear_amplitudes(p).map(|(z, _)| z),
                };
                zeta0.map_or(f64::NAN, |z| p.sleeve_weight() / (p.k * z))
            }
        }
    }

    /// The set with each input moved by one ulp, in turn: up, except μd, which moves down (it
    /// may equal μs, which it must not pass).
    fn nudged(&self) -> Vec<Params> {
        let up = next_up;
        match *self {
            Params::Pulled(p) => {
                let fields: [fn(&mut PulledMassParams) -> &mut f64; 5] = [
                    |p| &mut p.mu_s,
                    |p| &mut p.mass,
                    |p| &mut p.k,
                    |p| &mut p.force,
                    |p| &mut p.g,
                ];
                let mut out: Vec<Params> = fields
                    .iter()
                    .map(|f| {
                        let mut q = p;
                        let x = f(&mut q);
                        *x = up(*x);
                        Params::Pulled(q)
                    })
                    .collect();
                out.push(Params::Pulled(PulledMassParams {
                    mu_d: next_down(p.mu_d),
                    ..p
                }));
                out
            }
            Params::Wood(p) => {
                let fields: [fn(&mut WoodpeckerParams) -> &mut f64; 8] = [
                    |p| &mut p.mu_s,
                    |p| &mut p.k,
                    |p| &mut p.m_sleeve,
                    |p| &mut p.m_bird,
                    |p| &mut p.l,
                    |p| &mut p.z0,
                    |p| &mut p.d0,
                    |p| &mut p.g,
                ];
                let mut out: Vec<Params> = fields
                    .iter()
                    .map(|f| {
                        let mut q = p;
                        let x = f(&mut q);
                        *x = up(*x);
                        Params::Wood(q)
                    })
                    .collect();
                out.push(Params::Wood(WoodpeckerParams {
                    mu_d: next_down(p.mu_d),
                    ..p
                }));
                if let Some(lever) = p.lever {
                    out.push(Params::Wood(WoodpeckerParams {
                        lever: Some(up(lever)),
                        ..p
                    }));
                }
                out
            }
        }
    }

    /// The driving force whose power is reported: F (pulled mass) or W_S (woodpecker).
    fn drive(&self) -> f64 {
        match self {
            Params::Pulled(p) => p.force,
            Params::Wood(p) => p.sleeve_weight(),
        }
    }

    /// The engine's summary of `law`, as `eval --json` prints it.
    fn engine(&self, law: LawKind) -> Result<Option<Summary>, Error> {
        Ok(match self {
            Params::Pulled(p) => {
                let e = pulled_mass::results::evaluate(p, PERIODS)?;
                Some(match law {
                    LawKind::Linear => e.linear,
                    LawKind::Harmonic => e.harmonic,
                })
            }
            Params::Wood(p) => {
                let e = woodpecker::results::evaluate(p, PERIODS)?;
                match law {
                    LawKind::Linear => e.linear,
                    LawKind::Harmonic => Some(e.harmonic),
                }
            }
        })
    }
}

/// The numbers compared, from either side.
#[derive(Clone, Debug, Default)]
struct Numbers {
    v_avg: f64,
    advance: f64,
    power: f64,
    friction: f64,
    maxima: Vec<f64>,
    /// Steady transitions of the last period: (t/T, kind).
    events: Vec<(f64, String)>,
}

const QUANTITIES: [&str; 5] = ["v_avg", "advance", "power", "friction", "v_max"];

fn num(v: &Value) -> f64 {
    v.as_str().unwrap().parse().unwrap()
}

/// The truth of one script result: the last period of the run.
fn truth(r: &Value, drive: f64) -> Numbers {
    let period = num(&r["period"]);
    let n = PERIODS as usize;
    let advance = num(&r["advance"][n - 1]);
    let last = |key: &str| r[key][n - 1].as_array().unwrap().clone();
    Numbers {
        v_avg: advance / period,
        advance,
        power: drive * (advance / period),
        friction: num(&r["dissipation"][n - 1]) / period,
        maxima: last("speed_maxima").iter().map(|m| num(&m[1])).collect(),
        events: last("events")
            .iter()
            .map(|e| {
                (
                    (num(&e[0]) / period).rem_euclid(1.0),
                    e[1].as_str().unwrap().to_string(),
                )
            })
            .collect(),
    }
}

fn numbers(s: &Summary, period: f64) -> Option<Numbers> {
    Some(Numbers {
        v_avg: s.v_avg?,
        advance: s.advance_per_period?,
        power: s.power.driving?,
        friction: s.power.friction?,
        maxima: s.steady_speed_maxima.iter().map(|m| m.v).collect(),
        events: s
            .steady_events
            .iter()
            .map(|e| ((e.t / period).rem_euclid(1.0), e.kind.to_string()))
            .collect(),
    })
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / b.abs()
    }
}

/// Relative changes of each quantity (and the largest event shift, /T) between two truths.
fn changes(a: &Numbers, b: &Numbers) -> [f64; 6] {
    let maxima = a
        .maxima
        .iter()
        .zip(&b.maxima)
        .map(|(x, y)| rel(*x, *y))
        .fold(0.0, f64::max);
    let events = a
        .events
        .iter()
        .zip(&b.events)
        .map(|(x, y)| phase_gap(x.0, y.0))
        .fold(0.0, f64::max);
    [
        rel(a.v_avg, b.v_avg),
        rel(a.advance, b.advance),
        rel(a.power, b.power),
        rel(a.friction, b.friction),
        maxima,
        events,
    ]
}

/// |x − y| on the circle of phases [0, 1).
fn phase_gap(x: f64, y: f64) -> f64 {
    let d = (x - y).abs();
    d.min(1.0 - d)
}

fn pulled(mu_s: f64, mu_d: f64, mass: f64, k: f64, phi: f64) -> Params {
    let g = 9.81;
    Params::Pulled(PulledMassParams {
        mu_s,
        mu_d,
        mass,
        k,
        force: phi * mass * g,
        g,
    })
}

/// A woodpecker set whose sleeve is light enough for ε = W_S/(k d0) = `eps`.
fn wood(base: WoodpeckerParams, eps: f64) -> Params {
    Params::Wood(WoodpeckerParams {
        m_sleeve: eps * base.k * base.d0 / base.g,
        ..base
    })
}

fn sets() -> Vec<Set> {
    let mut rng = StdRng::seed_from_u64(40);
    let mut out = vec![
        // The issue's example: linear v̄ 2.6432100112133576e-22.
        Set {
            region: "pulled: issue example",
            params: Params::Pulled(PulledMassParams {
                mu_s: 0.16271620368428127,
                mu_d: 0.12294150043529245,
                mass: 0.0120664408736112,
                k: 73.49223195317268,
                force: 5.258863642352462e-09,
                g: 9.81,
            }),
        },
        Set {
            region: "pulled: ordinary",
            params: Params::Pulled(PulledMassParams {
                mu_s: 0.4,
                mu_d: 0.35,
                force: 0.1,
                ..PulledMassParams::default()
            }),
        },
    ];
    for (mu_s, ratio, phi) in [
        (0.5, 0.7, 1e-9),
        (44.7, 0.6, 1e-9),
        (100.0, 0.9, 1e-9),
        (5.0, 0.98, 3e-8),
        (2.0, 0.5, 1e-6),
    ] {
        let (mass, k) = (rng.gen_range(0.01..1.0), rng.gen_range(1.0..100.0));
        out.push(Set {
            region: "pulled: small φ, large μs",
            params: pulled(mu_s, mu_s * ratio, mass, k, phi),
        });
    }
    // Near φ_c (late stick; v̄ has a double root there) and just past 1/Θ.
    let (mu_s, mu_d) = (0.4, 0.35);
    for phi in [
        pm::phi_continuous(mu_s, mu_d) * (1.0 - 1e-9),
        pm::phi_continuous(mu_s, mu_d) * (1.0 - 1e-5),
        pm::phi_stick_max(mu_s, mu_d) * (1.0 + 1e-9),
    ] {
        out.push(Set {
            region: "pulled: near φ_c",
            params: pulled(mu_s, mu_d, 0.06, 45.0, phi),
        });
    }
    for (mu_d, phi) in [(0.3, 1e-5), (0.3 * (1.0 - 1e-12), 0.05), (0.3, 0.2)] {
        out.push(Set {
            region: "pulled: μd → μs",
            params: pulled(0.3, mu_d, 0.2, 10.0, phi),
        });
    }
    out.push(Set {
        region: "wood: ordinary",
        params: Params::Wood(WoodpeckerParams::default()),
    });
    let mut i = 0;
    for eps in [1e-9, 1e-9, 1e-8, 1e-7, 1e-6, 3e-6] {
        let base = loop {
            let p = random_sets::woodpecker(&mut rng, i);
            i += 1;
            let q = WoodpeckerParams {
                z0: p.d0 * rng.gen_range(0.1..0.9),
                mu_d: p.mu_s * rng.gen_range(0.5..0.9),
                counterpart: Counterpart::Zeros,
                omega: OmegaMode::Bird,
                ..p
            };
            if q.validate().is_ok() {
                break q;
            }
        };
        out.push(Set {
            region: "wood: small ε",
            params: wood(base, eps),
        });
    }
    for eps in [1e-9, 1e-4] {
        let base = WoodpeckerParams {
            mu_d: 0.65,
            ..WoodpeckerParams::default()
        };
        out.push(Set {
            region: "wood: μd = μs",
            params: wood(base, eps),
        });
    }
    out
}

#[derive(Default)]
struct Worst {
    cases: usize,
    skipped: usize,
    mismatches: usize,
    /// Per quantity and for the events: (error, tolerance, small parameter) of the worst
    /// error/tolerance ratio.
    worst: [(f64, f64, f64); 6],
}

#[test]
fn engine_matches_a_40_digit_integration_of_the_physics() {
    let sets = sets();
    // The sets, for measuring a built binary against the same truth (see the crate's notes).
    if let Ok(path) = std::env::var("STICKSLIP_REFERENCE_SETS") {
        let list: Vec<Value> = sets
            .iter()
            .map(|s| {
                let (model, params) = s.params.json();
                json!({"region": s.region, "model": model, "params": params})
            })
            .collect();
        std::fs::write(path, Value::Array(list).to_string()).unwrap();
    }
    let laws = [LawKind::Linear, LawKind::Harmonic];
    // Per set and law: the case itself, then each input nudged by one ulp.
    let mut cases = Vec::new();
    let mut index = Vec::new();
    for set in &sets {
        for law in laws {
            let variants: Vec<Params> = std::iter::once(set.params)
                .chain(set.params.nudged())
                .collect();
            index.push((cases.len(), variants.len()));
            for v in variants {
                let (model, params) = v.json();
                let law_id = match law {
                    LawKind::Linear => "linear",
                    LawKind::Harmonic => "harmonic",
                };
                cases.push(json!({"model": model, "law": law_id, "params": params,
                                  "periods": PERIODS}));
            }
        }
    }
    let reference = match run_script(cases) {
        Ok(r) => r,
        Err(ScriptError::Unavailable(reason)) => {
            eprintln!("skipped: {reason}");
            return;
        }
        Err(ScriptError::Failed(reason)) => panic!("reference failed: {reason}"),
    };

    let mut regions: Vec<(&str, Worst)> = Vec::new();
    let mut notes = Vec::new();
    let mut k = 0;
    for set in &sets {
        for law in laws {
            let (first, count) = index[k];
            k += 1;
            let label = format!("{} {law:?}", set.region);
            let slot = match regions.iter().position(|(r, _)| *r == label) {
                Some(i) => i,
                None => {
                    regions.push((Box::leak(label.clone().into_boxed_str()), Worst::default()));
                    regions.len() - 1
                }
            };
            let w = &mut regions[slot].1;
            w.cases += 1;
            let small = set.params.small(law);
            let drive = |p: &Params| p.drive();
            let nudged = set.params.nudged();
            let truths: Vec<Numbers> = std::iter::once(&set.params)
                .chain(&nudged)
                .zip(&reference[first..first + count])
                .map(|(p, r)| truth(r, drive(p)))
                .collect();
            let summary = match set.params.engine(law) {
                Ok(Some(s)) => s,
                Ok(None) => {
                    w.skipped += 1;
                    continue;
                }
                Err(e) => {
                    w.mismatches += 1;
                    notes.push(format!("{label} small {small:e}: refused: {e}"));
                    continue;
                }
            };
            let period = num(&reference[first]["period"]);
            let Some(mine) = numbers(&summary, period) else {
                // Continuous slip on both sides: no steady value to compare.
                let sliding = summary.regime.id() == "continuous_slip";
                if sliding && truths[0].events.is_empty() {
                    w.skipped += 1;
                    continue;
                }
                w.mismatches += 1;
                notes.push(format!(
                    "{label} small {small:e}: the engine found no steady value ({})",
                    summary.regime.id()
                ));
                continue;
            };
            let truth = &truths[0];
            let same_pattern = mine.maxima.len() == truth.maxima.len()
                && mine.events.len() == truth.events.len()
                && mine
                    .events
                    .iter()
                    .zip(&truth.events)
                    .all(|(a, b)| a.1 == b.1);
            if !same_pattern {
                w.mismatches += 1;
                notes.push(format!(
                    "{label} small {small:e}: engine {:?} {:?}, reference {:?} {:?}",
                    mine.events, mine.maxima, truth.events, truth.maxima
                ));
                continue;
            }
            // The truth's own sensitivity to one ulp of any input.
            let mut sensitivity = [0.0f64; 6];
            for t in &truths[1..] {
                for (s, c) in sensitivity.iter_mut().zip(changes(t, truth)) {
                    *s = s.max(c);
                }
            }
            let errors = changes(&mine, truth);
            for (q, slot) in w.worst.iter_mut().enumerate() {
                let floor = if q == 5 { EVENT_TOL } else { VALUE_TOL };
                let tol = floor.max(SENSITIVITY_FACTOR * sensitivity[q]);
                if errors[q].is_nan() || errors[q] / tol > slot.0 / slot.1.max(f64::MIN_POSITIVE) {
                    *slot = (errors[q], tol, small);
                }
            }
        }
    }

    eprintln!(
        "{:<34} {:>5} {:>4} {:>8} {:>23} {:>23} {:>23} {:>23} {:>23} {:>23}",
        "region law",
        "cases",
        "skip",
        "mismatch",
        "v_avg err (tol)",
        "advance err (tol)",
        "power err (tol)",
        "friction err (tol)",
        "v_max err (tol)",
        "event |dt|/T (tol)"
    );
    let cell = |(e, t, s): (f64, f64, f64)| format!("{e:.1e} ({t:.0e}) @{s:.0e}");
    for (label, w) in &regions {
        eprintln!(
            "{label:<34} {:>5} {:>4} {:>8} {:>23} {:>23} {:>23} {:>23} {:>23} {:>23}",
            w.cases,
            w.skipped,
            w.mismatches,
            cell(w.worst[0]),
            cell(w.worst[1]),
            cell(w.worst[2]),
            cell(w.worst[3]),
            cell(w.worst[4]),
            cell(w.worst[5]),
        );
    }
    eprintln!("(@: φ of the pulled-mass set, ε = W_S/(k ζ0) of the woodpecker set)");
    for n in &notes {
        eprintln!("{n}");
    }
    if std::env::var("STICKSLIP_REFERENCE").as_deref() == Ok("report") {
        return;
    }
    for (label, w) in &regions {
        assert_eq!(
            w.mismatches, 0,
            "{label}: refused, unsettled or pattern differs"
        );
        for (q, (e, t, _)) in w.worst.iter().enumerate() {
            let name = QUANTITIES.get(q).copied().unwrap_or("event time");
            assert!(e <= t, "{label}: {name} error {e:e} > {t:e}");
        }
    }
}

/// The woodpecker below the range of ε it can honour is refused with a one-line reason naming
/// the parameters, as the pulled mass is below φ = 1e-9; just inside, it computes.
#[test]
fn woodpecker_slips_too_short_for_double_precision_are_refused() {
    let base = WoodpeckerParams::default();
    let Params::Wood(tiny) = wood(base, 1e-13) else {
        unreachable!()
    };
    let err = woodpecker::results::evaluate(&tiny, PERIODS).unwrap_err();
    let text = err.to_string();
    assert!(matches!(err, Error::InvalidParam { .. }), "{text}");
    assert!(
        text.contains("m_sleeve") && text.contains("W_S/(k"),
        "{text}"
    );
    let Params::Wood(inside) = wood(base, 1.5e-9) else {
        unreachable!()
    };
    assert!(woodpecker::results::evaluate(&inside, PERIODS).is_ok());
}
