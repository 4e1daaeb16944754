//! The belt's evaluation: the closed forms, the exact integration of the same system
//! ([`crate::engine::autonomous`]) with its cycle found from its events, and the checks of every
//! closed form against the integration's cycle (docs/belt.md, "Machine-readable output"),
//! measured in the cycle's local time: the period, the offsets and the ledger over a cycle
//! keep their relative precision however late the cycle starts.

use serde::Serialize;

use super::body::{body, surface_law};
use super::formula::{self as cf, ClosedForm, Regime};
use super::params::BeltParams;
use super::quantity::Key;
use crate::engine::autonomous::{Ending, SurfaceMotion, SurfaceOptions, SurfaceRun};
use crate::engine::{integrate_surface_with, EventKind, Replay};
use crate::error::{Error, Result};
use crate::params::validate_periods;
use crate::results::checks::{Check, BOUNDARY_BAND};
use crate::results::ensure_in_range;

/// A stick shorter than this fraction of the period is the rounding of a touch (Δ = 0): the
/// time from the arc's end back to x_s, a difference of positions of size A.
const TOUCH: f64 = 64.0 * f64::EPSILON;

/// Input parameters, the number of cycles integrated, and the scales ω, x_s, x_d, Δ (B1)–(B4).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ParamsOut {
    #[serde(flatten)]
    pub input: BeltParams,
    pub cycles: u32,
    pub omega: f64,
    pub x_s: f64,
    pub x_d: f64,
    pub delta: f64,
}

/// The closed forms' quantities measured on the exact integration's cycle (the one every later
/// cycle repeats); `null` where the run has no complete cycle.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Integration {
    pub cycles: u32,
    pub first_slip_time: Option<f64>,
    pub t_slip: Option<f64>,
    pub t_stick: Option<f64>,
    pub period: Option<f64>,
    pub amplitude: Option<f64>,
    pub x_slip_end: Option<f64>,
    pub x_max: Option<f64>,
    pub x_min: Option<f64>,
    pub v_min: Option<f64>,
    pub slip_speed_max: Option<f64>,
    pub energy_per_cycle: Option<f64>,
    pub power_friction: Option<f64>,
    pub power_belt: Option<f64>,
    pub stick_share: Option<f64>,
    pub slip_share: Option<f64>,
    /// `stick_slip` or `touching_oscillation` (a stick of zero duration), `null` without a
    /// cycle.
    pub regime: Option<&'static str>,
}

impl Integration {
    /// The measured value of a closed form's quantity.
    pub fn value(&self, key: Key) -> Option<f64> {
        match key {
            Key::FirstSlipTime => self.first_slip_time,
            Key::TSlip => self.t_slip,
            Key::TStick => self.t_stick,
            Key::Period => self.period,
            Key::Amplitude => self.amplitude,
            Key::XSlipEnd => self.x_slip_end,
            Key::XMax => self.x_max,
            Key::XMin => self.x_min,
            Key::VMin => self.v_min,
            Key::SlipSpeedMax => self.slip_speed_max,
            Key::EnergyPerCycle => self.energy_per_cycle,
            Key::PowerFriction => self.power_friction,
            Key::PowerBelt => self.power_belt,
            Key::StickShare => self.stick_share,
            Key::SlipShare => self.slip_share,
            Key::Regime => None,
        }
    }
}

/// The belt's evaluation object.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Evaluation {
    pub model: &'static str,
    pub params: ParamsOut,
    pub closed_form: ClosedForm,
    pub integration: Integration,
    pub checks: Vec<Check>,
}

/// Validates `p`, evaluates the closed forms and integrates `cycles` slip-stick cycles.
pub fn evaluate(p: &BeltParams, cycles: u32) -> Result<Evaluation> {
    // The replayed cycles are not stored: memory stays bounded for 10⁶ cycles.
    Ok(evaluate_replayed(p, cycles, Replay::Compact)?.0)
}

/// As [`evaluate`], also returning the run (with the segments of every cycle).
pub fn evaluate_with_run(p: &BeltParams, cycles: u32) -> Result<(Evaluation, SurfaceRun)> {
    evaluate_replayed(p, cycles, Replay::Segments)
}

/// As [`evaluate_with_run`], with the repeated cycles treated as `replay` says.
pub fn evaluate_replayed(
    p: &BeltParams,
    cycles: u32,
    replay: Replay,
) -> Result<(Evaluation, SurfaceRun)> {
    p.validate()?;
    validate_periods(cycles)?;
    let c = cf::evaluate(p);
    ensure_in_range(
        [
            ("T", c.period),
            ("E", c.energy_per_cycle),
            ("A", c.amplitude),
        ],
        "v_b, k and m",
    )?;
    let opts = SurfaceOptions {
        x0: 0.0,
        slips: cycles,
        record_segments: true,
    };
    let run = integrate_surface_with(&body(p), &surface_law(p)?, &opts, replay)?;
    let integration = measure(p, &run, cycles)?;
    let checks = checks(p, &c, &integration);
    let evaluation = Evaluation {
        model: super::ID,
        params: ParamsOut {
            input: *p,
            cycles,
            omega: c.omega,
            x_s: c.x_s,
            x_d: c.x_d,
            delta: c.delta,
        },
        closed_form: c,
        integration,
        checks,
    };
    Ok((evaluation, run))
}

/// The quantities of the cycle of `run`, from its local times and ledger.
fn measure(p: &BeltParams, run: &SurfaceRun, cycles: u32) -> Result<Integration> {
    let out = Integration {
        cycles,
        first_slip_time: run.events.first().map(|e| e.t),
        ..Integration::default()
    };
    if run.ending != Ending::Slips {
        return Err(Error::Stalled {
            t: run.end,
            reason: "the belt's run ended without completing its cycles",
        });
    }
    let Some(cycle) = &run.cycle else {
        return Ok(out);
    };
    let events = &cycle.events;
    let Some((slip, arc)) = cycle.segments.iter().find_map(|s| match s.motion {
        SurfaceMotion::Slip(arc) => Some((s, arc)),
        SurfaceMotion::Carried { .. } => None,
    }) else {
        return Ok(out);
    };
    let stick = cycle
        .segments
        .iter()
        .find(|s| matches!(s.motion, SurfaceMotion::Carried { .. }));
    let t_slip = slip.duration;
    // A stick of zero duration (a touch) has no segment.
    let t_stick = stick.map_or(0.0, |s| s.duration);
    let period = cycle.period;
    let angle = t_slip * arc.omega;
    let xs = arc
        .turns(angle)
        .into_iter()
        .map(|d| arc.at_angle(d).x)
        .chain([arc.x_c, arc.at_angle(angle).x]);
    let (x_min, x_max) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    let fastest = events
        .iter()
        .filter(|e| e.kind == EventKind::SpeedMax)
        .map(|e| e.v)
        .fold(f64::INFINITY, f64::min);
    let (heat, work) = (cycle.ledger.heat, cycle.ledger.surface_work);
    let x_slip_end = events
        .iter()
        .find(|e| matches!(e.kind, EventKind::Stick { .. }))
        .map(|e| e.x);
    Ok(Integration {
        t_slip: Some(t_slip),
        t_stick: Some(t_stick),
        period: Some(period),
        amplitude: Some(0.5 * (x_max - x_min)),
        x_slip_end,
        x_max: Some(x_max),
        x_min: Some(x_min),
        v_min: fastest.is_finite().then_some(fastest),
        slip_speed_max: fastest.is_finite().then_some(p.v_b - fastest),
        energy_per_cycle: Some(heat),
        power_friction: Some(heat / period),
        power_belt: Some(work / period),
        stick_share: Some(t_stick / period),
        slip_share: Some(t_slip / period),
        // A stick within the rounding of the touch's time is a touch.
        regime: Some(if t_stick > TOUCH * period {
            Regime::StickSlip.id()
        } else {
            Regime::TouchingOscillation.id()
        }),
        ..out
    })
}

/// Every closed form against its measurement. Times are compared on the scale of the period
/// (the stick's end x_e carries the rounding of the arc's amplitude A, and t_stick = 2Δ/v_b is
/// its difference with x_s); positions, and the amplitude measured as half the distance
/// between the extremes, on the scale of the positions they are computed from (A or x_s); the
/// shares on 1; the belt's power on the static capacity dragged at the belt's speed, μs m g v_b
/// (its work over a stick is ½k(x_s² − x_e²), whose factor x_s + x_e = 2x_d is a difference
/// of positions of size x_s: with μd ≪ μs it carries eps·x_s, not eps·x_d).
fn checks(p: &BeltParams, c: &ClosedForm, m: &Integration) -> Vec<Check> {
    let scale = |key: Key| match key {
        Key::TSlip | Key::TStick | Key::Period => c.period,
        Key::XSlipEnd | Key::XMax | Key::XMin | Key::Amplitude => c.amplitude.max(c.x_s),
        Key::StickShare | Key::SlipShare => 1.0,
        Key::PowerBelt => p.mu_s * p.mass * p.g * p.v_b,
        _ => 0.0,
    };
    let mut out: Vec<Check> = super::quantity::ALL
        .iter()
        .filter_map(|&key| {
            let closed = c.value(key).number()?;
            Some(Check::measured_on_scale(
                key,
                closed,
                m.value(key),
                scale(key),
            ))
        })
        .collect();
    let regime = m.regime.unwrap_or("not observed");
    // Δ within the band of a touch: the stick's duration is rounding, either regime agrees.
    let near_touch = c.delta <= BOUNDARY_BAND * c.amplitude;
    out.push(Check::label_agreeing(
        Key::Regime,
        c.regime.id(),
        regime,
        c.regime.id() == regime || (near_touch && m.regime.is_some()),
    ));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_set_passes_every_check_at_1e_12() {
        let e = evaluate(&BeltParams::default(), 8).unwrap();
        for check in &e.checks {
            assert!(check.passed(), "{check:?}");
            assert!(check.rel_error.is_none_or(|r| r <= 1e-12), "{check:?}");
        }
        assert_eq!(e.integration.regime, Some("stick_slip"));
    }

    #[test]
    fn equal_coefficients_are_a_touching_oscillation() {
        let p = BeltParams {
            mu_d: 0.6,
            ..BeltParams::default()
        };
        let e = evaluate(&p, 8).unwrap();
        for check in &e.checks {
            assert!(check.passed(), "{check:?}");
        }
        assert_eq!(e.integration.regime, Some("touching_oscillation"));
    }
}
