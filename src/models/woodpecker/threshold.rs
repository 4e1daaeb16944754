//! The numeric counterpart of μd,MIN^(I) (eq. 51): the dynamic coefficient at which the exact
//! integration of the linearized sleeve, from rest, first sticks exactly at T/2, found by
//! bisection on the engine.

use crate::engine::{integrate, EventKind, RunOptions};
use crate::error::Result;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker as wp_model, LawKind};

/// Relative bracket around the closed-form μd,MIN for the search.
const BRACKET: f64 = 1e-3;

/// Whether the first slip from rest of the linearized sleeve with dynamic coefficient `mu_d`
/// sticks by T/2; `None` when the slip starts at t = 0 or the set is invalid.
pub fn sticks_by_half_period(p: &WoodpeckerParams, mu_d: f64) -> Result<Option<bool>> {
    let q = WoodpeckerParams { mu_d, ..*p };
    if q.validate().is_err() {
        return Ok(None);
    }
    let opts = RunOptions {
        periods: 1,
        record_segments: false,
        dissipation: false,
    };
    let run = integrate(
        &wp_model::body(&q),
        &wp_model::force_law(&q, LawKind::Linear)?,
        &opts,
    )?;
    if run.immediate_slip {
        return Ok(None);
    }
    let stick = run
        .events
        .iter()
        .find(|e| matches!(e.kind, EventKind::Stick { .. }));
    Ok(Some(stick.is_some_and(|e| e.t <= 0.5 * run.period)))
}

/// The μd near `guess` at which the phase-I slip from rest sticks exactly at T/2, by bisection
/// on the exact integration; `None` when no bracket of ±[`BRACKET`] around `guess` (within
/// 0 < μd ≤ μs) changes the outcome.
pub fn mu_d_sticking_at_half_period(p: &WoodpeckerParams, guess: f64) -> Result<Option<f64>> {
    let (mut lo, mut hi) = (
        guess * (1.0 - BRACKET),
        (guess * (1.0 + BRACKET)).min(p.mu_s),
    );
    if sticks_by_half_period(p, lo)? != Some(false) || sticks_by_half_period(p, hi)? != Some(true) {
        return Ok(None);
    }
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return Ok(Some(mid));
        }
        match sticks_by_half_period(p, mid)? {
            Some(true) => hi = mid,
            Some(false) => lo = mid,
            None => return Ok(None),
        }
    }
}
