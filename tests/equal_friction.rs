//! μd = μs is valid input: at a slip onset from rest the acceleration is (μs − μd)N_f/M = 0,
//! and the slip must go on (the acceleration grows from 0), not stop where it started. Random
//! sets of both models and both laws integrate without error, and each slip of the linear pulled
//! mass starts at τ_SL of (13), not a few ulps later.

#[path = "common/random_sets.rs"]
mod random_sets;

use rand::{rngs::StdRng, Rng, SeedableRng};
use stickslip::engine::{integrate, EventKind, RunOptions};
use stickslip::models::pulled_mass::formula as cf;
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::woodpecker::formula::Counterpart;
use stickslip::models::woodpecker::{OmegaMode, WoodpeckerParams};
use stickslip::models::{pulled_mass, woodpecker, LawKind};

const SETS: usize = 400;
const OPTS: RunOptions = RunOptions {
    periods: 12,
    record_segments: false,
    dissipation: false,
};

fn pulled_mass_set(rng: &mut StdRng, i: usize) -> PulledMassParams {
    let mu = rng.gen_range(0.05..1.2);
    // Half of the sets just below the immediate-slip bound 2μ (the slip starts next to t = 0,
    // where the onset is ill-conditioned), the others log-uniform from 1e-9 up.
    let phi = if i.is_multiple_of(2) {
        2.0 * mu * (1.0 - random_sets::log_uniform(rng, 1e-15, 1e-2))
    } else {
        random_sets::log_uniform(rng, 1e-9, 2.0 * mu)
    };
    let (mass, g) = (rng.gen_range(0.005..2.0), rng.gen_range(1.0..25.0));
    PulledMassParams {
        mu_s: mu,
        mu_d: mu,
        mass,
        k: rng.gen_range(0.5..2000.0),
        force: phi * mass * g,
        g,
    }
}

/// The set: `eval pulled-mass --mu-s 0.4 --mu-d 0.4 --force 0.470879999999999` stalled
/// ("too many transitions") at t = 3.4e-9 s.
#[test]
fn the_reported_set_integrates() {
    let p = PulledMassParams {
        mu_s: 0.4,
        mu_d: 0.4,
        force: 0.470879999999999,
        ..PulledMassParams::default()
    };
    for law in [LawKind::Harmonic, LawKind::Linear] {
        let run = integrate(
            &pulled_mass::body(&p),
            &pulled_mass::force_law(&p, law).unwrap(),
            &OPTS,
        )
        .unwrap_or_else(|e| panic!("{law:?}: {e}"));
        assert!(run.first_slip.unwrap() < 1e-8, "{law:?}");
    }
}

#[test]
fn pulled_mass_sets_with_equal_coefficients_integrate() {
    let mut rng = StdRng::seed_from_u64(4_470_880);
    for i in 0..SETS {
        let p = pulled_mass_set(&mut rng, i);
        let body = pulled_mass::body(&p);
        for law in [LawKind::Harmonic, LawKind::Linear] {
            let run = integrate(&body, &pulled_mass::force_law(&p, law).unwrap(), &OPTS)
                .unwrap_or_else(|e| panic!("{law:?} {p:?}: {e}"));
            let period = run.period;
            let t_sl = cf::tau_slip(p.phi(), p.mu_s) * period;
            // (An onset within the event resolution 8 eps T of the period start is at t = 0.)
            if law != LawKind::Linear || t_sl < 8.0 * f64::EPSILON * period {
                continue;
            }
            // Every slip from rest starts where F = μs N, at τ_SL (mod 1); the absolute event
            // time is rounded to its own ulp.
            for e in &run.events {
                if let EventKind::Slip { .. } = e.kind {
                    let local = e.t - f64::from(e.period) * period;
                    assert!(
                        (local - t_sl).abs() <= 4.0 * f64::EPSILON * (period + e.t),
                        "slip at {local} s, τ_SL T = {t_sl} s for {p:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn woodpecker_sets_with_equal_coefficients_integrate() {
    let mut rng = StdRng::seed_from_u64(4_470_881);
    let mut done = 0;
    while done < SETS {
        let mu = rng.gen_range(0.2..1.0);
        let d0 = rng.gen_range(0.002..0.02);
        let p = WoodpeckerParams {
            mu_s: mu,
            mu_d: mu,
            k: rng.gen_range(2.0..60.0),
            m_sleeve: random_sets::log_uniform(&mut rng, 1e-8, 0.03),
            m_bird: rng.gen_range(0.003..0.05),
            l: 0.016,
            h: 0.007,
            z0: d0 * rng.gen_range(-0.2..0.999),
            d0,
            g: 9.81,
            lever: Some(rng.gen_range(0.8..5.0)),
            omega: [OmegaMode::Bird, OmegaMode::Reduced, OmegaMode::Total][rng.gen_range(0..3)],
            counterpart: [
                Counterpart::Extremes,
                Counterpart::Zeros,
                Counterpart::Tangent,
            ][rng.gen_range(0..3)],
        };
        if p.validate().is_err() {
            continue;
        }
        done += 1;
        let body = woodpecker::body(&p);
        for law in [LawKind::Harmonic, LawKind::Linear] {
            let Ok(force_law) = woodpecker::force_law(&p, law) else {
                continue;
            };
            integrate(&body, &force_law, &OPTS).unwrap_or_else(|e| panic!("{law:?} {p:?}: {e}"));
        }
    }
}
