//! The whole evaluation of the pulled mass: closed forms, both laws integrated exactly, and the
//! checks of every closed form against the linearized integration (guide §5.1, guide §14).

use serde::Serialize;

use crate::engine::{analyse, integrate_with, Event, EventKind, Replay, Run, RunOptions};
use crate::error::Result;
use crate::models::pulled_mass::formula::{self as cf, ClosedForm, Regime};
use crate::models::pulled_mass::quantity::Key;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::{pulled_mass, LawKind};
use crate::params::validate_periods;
use crate::results::checks::{unsettled, Check, BOUNDARY_BAND};
use crate::results::quantity::Registry;
use crate::results::summary::{Power, Summary};
use crate::results::{ensure_in_range, Applicability};

/// Input parameters and the derived W, T, ω, φ (keys of guide §14 `params`).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ParamsOut {
    #[serde(flatten)]
    pub input: PulledMassParams,
    pub periods: u32,
    #[serde(rename = "W")]
    pub weight: f64,
    #[serde(rename = "T")]
    pub period: f64,
    pub omega: f64,
    pub phi: f64,
}

impl ParamsOut {
    /// The inputs `p` with their derived quantities, for a run of `periods`.
    pub fn of(p: &PulledMassParams, periods: u32) -> Self {
        Self {
            input: *p,
            periods,
            weight: p.weight(),
            period: p.period(),
            omega: p.omega(),
            phi: p.phi(),
        }
    }
}

/// The guide §14 object for the pulled mass.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Evaluation {
    pub model: &'static str,
    pub params: ParamsOut,
    pub closed_form: ClosedForm,
    pub linear: Summary,
    pub harmonic: Summary,
    pub checks: Vec<Check>,
    /// Which closed forms describe the motion (shown in text and reports).
    #[serde(skip)]
    pub applicability: Vec<Applicability>,
}

/// Both laws integrated, kept for figures and time series.
pub struct Runs {
    pub linear: Run,
    pub harmonic: Run,
}

/// Validates `p`, evaluates the closed forms and integrates both laws for `periods` periods.
pub fn evaluate(p: &PulledMassParams, periods: u32) -> Result<Evaluation> {
    Ok(evaluate_with_runs(p, periods, false)?.0)
}

/// As [`evaluate`], also returning the runs (with segments when `record_segments`).
pub fn evaluate_with_runs(
    p: &PulledMassParams,
    periods: u32,
    record_segments: bool,
) -> Result<(Evaluation, Runs)> {
    let linear = linear_part(p, periods, record_segments)?;
    let harmonic_run = run_of(p, LawKind::Harmonic, periods, record_segments)?;
    let applicability = applicability(&linear.closed_form);
    let evaluation = Evaluation {
        model: "pulled-mass",
        params: ParamsOut::of(p, periods),
        closed_form: linear.closed_form,
        linear: linear.summary,
        harmonic: summary_of(p, &harmonic_run),
        checks: linear.checks,
        applicability,
    };
    in_range(
        &evaluation.params,
        &evaluation.closed_form,
        [&evaluation.linear, &evaluation.harmonic],
    )?;
    let runs = Runs {
        linear: linear.run,
        harmonic: harmonic_run,
    };
    Ok((evaluation, runs))
}

/// Only what the checks read: the closed forms against the linearized law's run (returned, with
/// segments when `record_segments`); the harmonic law is not integrated. Refuses what
/// [`evaluate_with_runs`] refuses on the same grounds (parameters, closed forms, linear run).
pub fn linear_checks(
    p: &PulledMassParams,
    periods: u32,
    record_segments: bool,
) -> Result<(Vec<Check>, Run)> {
    let linear = linear_part(p, periods, record_segments)?;
    in_range(
        &ParamsOut::of(p, periods),
        &linear.closed_form,
        [&linear.summary],
    )?;
    Ok((linear.checks, linear.run))
}

/// The closed forms, the linearized law's run and summary, and the checks against them.
struct Linear {
    closed_form: ClosedForm,
    run: Run,
    summary: Summary,
    checks: Vec<Check>,
}

fn linear_part(p: &PulledMassParams, periods: u32, record_segments: bool) -> Result<Linear> {
    p.validate()?;
    validate_periods(periods)?;
    let closed_form = cf::evaluate(p.g, p.period(), p.force, p.phi(), p.mu_s, p.mu_d);
    let run = run_of(p, LawKind::Linear, periods, record_segments)?;
    let summary = summary_of(p, &run);
    let checks = checks(p, &closed_form, &run, &summary);
    Ok(Linear {
        closed_form,
        run,
        summary,
        checks,
    })
}

/// The exact integration of `law` for `periods` periods (with segments when `record_segments`).
fn run_of(p: &PulledMassParams, law: LawKind, periods: u32, record_segments: bool) -> Result<Run> {
    let opts = RunOptions {
        periods,
        record_segments,
        dissipation: true,
    };
    integrate_with(
        &pulled_mass::body(p),
        &pulled_mass::force_law(p, law)?,
        &opts,
        Replay::Compact,
    )
}

fn summary_of(p: &PulledMassParams, run: &Run) -> Summary {
    Summary::new(run, &analyse(run), |v_avg, friction| Power {
        key: Key::Power.id(),
        symbol: "F v̄",
        driving: v_avg.map(|v| p.force * v),
        friction,
    })
}

/// Refuses parameters whose combination drives a derived parameter, a closed form or an
/// integrated quantity (of `summaries`) out of the range of double precision.
fn in_range<const N: usize>(
    params: &ParamsOut,
    closed_form: &ClosedForm,
    summaries: [&Summary; N],
) -> Result<()> {
    let derived = [
        ("W", params.weight),
        ("T", params.period),
        ("omega", params.omega),
        ("phi", params.phi),
    ];
    let closed = Key::numbers()
        .filter_map(|entry| Some((entry.quantity.id, closed_form.value(entry.key).computed()?)));
    ensure_in_range(
        derived
            .into_iter()
            .chain(closed)
            .chain(summaries.into_iter().flat_map(Summary::numbers)),
        "F, m, k and g",
    )
}

/// Which closed forms of guide §7 describe the motion in the regime of `c`: those whose
/// registry entry names the regime, less the speed maximum of (17) when it falls outside the
/// first period.
pub fn applicability(c: &ClosedForm) -> Vec<Applicability> {
    let maximum = [Key::TauMaxSpeed, Key::TMaxSpeed, Key::VMax];
    Key::numbers()
        .map(|e| {
            let reason = if !e.key.describes(c.regime) {
                Some(why_not(c.regime, e.regimes))
            } else if maximum.contains(&e.key) && c.tau_max_speed >= 1.0 {
                Some(
                    "τ_M ≥ 1 (φ ≥ 2μd): the speed maximum of (17) falls outside the first period"
                        .to_string(),
                )
            } else {
                None
            };
            Applicability::new(e.key, reason)
        })
        .collect()
}

/// Why a form that describes the motion in `describes` does not in `regime`.
fn why_not(regime: Regime, describes: &[Regime]) -> String {
    match regime {
        // The forms of the slip from rest and of the same-period stick need a slip onset.
        Regime::ImmediateContinuousSlip if describes.contains(&Regime::SlipStick) => {
            "immediate slip (φ > 2μs): the mass slips from t = 0 and never sticks".to_string()
        }
        Regime::ImmediateContinuousSlip | Regime::ContinuousSlip => {
            "continuous slip (φ > φ_c): the mass never sticks again".to_string()
        }
        Regime::SlipStick => "the mass sticks within the period (20): no late stick".to_string(),
        Regime::SlipStickLate => "(20) fails (φ > 1/Θ): the mass sticks early in the next period; \
                                  the late-stick forms apply"
            .to_string(),
    }
}

/// Every closed form with a measurable counterpart on the linear run, in the regime where it
/// describes the motion. A quantity the run should show but does not fails its check, unless
/// the run is too short to show it or the parameters sit on a regime boundary within rounding
/// (then it is not observable). Event times are compared as fractions of the period.
fn checks(p: &PulledMassParams, c: &ClosedForm, run: &Run, summary: &Summary) -> Vec<Check> {
    let first = FirstCycle::of(run);
    let t_of = |e: Option<Event>| e.map(|e| e.t);
    let time = |key: Key, closed: f64, numeric: Option<f64>| {
        Check::measured_on_scale(key, closed, numeric, run.period)
    };
    let mut out = Vec::new();
    if !c.immediate_slip {
        out.push(time(Key::TSlip, c.t_slip, t_of(first.slip)));
        // a just after the onset, from the force law at the located slip time, relative to
        // g: the force law's amplitude per unit mass (the slip time carries its rounding).
        let body = pulled_mass::body(p);
        let a_at = |t: f64| {
            pulled_mass::force_law(p, LawKind::Linear)
                .ok()
                .map(|law| body.slip_acceleration(law.drive(t), law.normal(t), 1.0))
        };
        let a = t_of(first.slip).and_then(a_at);
        out.push(Check::measured_on_scale(Key::ASlip, c.a_slip, a, p.g));
        // τ_M < 1: the first maximum is the (17) one, in every non-immediate regime.
        if c.tau_max_speed < 1.0 {
            out.push(time(Key::TMaxSpeed, c.t_max_speed, t_of(first.maximum)));
            out.push(Check::measured(
                Key::VMax,
                c.v_max,
                first.maximum.map(|e| e.v),
            ));
        }
    }
    let unsettled = unsettled(run.periods, summary);
    match c.regime {
        Regime::SlipStick => {
            let stick = t_of(first.stick);
            let duration = stick.zip(t_of(first.slip)).map(|(st, sl)| st - sl);
            out.push(time(Key::TStick, c.t_stick, stick));
            out.push(time(Key::SlipDuration, c.slip_duration, duration));
            push_steady(
                &mut out,
                summary,
                [
                    (Key::VAvg, c.v_avg),
                    (Key::AdvancePerPeriod, c.advance_per_period),
                    (Key::Power, c.power),
                ],
                &unsettled,
            );
        }
        Regime::SlipStickLate => {
            if let (Some(late), Some(v), Some(x), Some(power)) = (
                c.tau_stick_late,
                c.v_avg_late,
                c.advance_per_period_late,
                c.power_late,
            ) {
                let tau = t_of(first.stick).map(|t| t / run.period);
                out.push(
                    Check::measured_on_scale(Key::TauStickLate, late, tau, 1.0)
                        .conditioned(
                            late_stick_floor(p),
                            "near φ_c the late stick is a double root of v(t)",
                        )
                        .unobservable_if(unsettled.clone()),
                );
                push_steady(
                    &mut out,
                    summary,
                    [
                        (Key::VAvgLate, v),
                        (Key::AdvancePerPeriodLate, x),
                        (Key::PowerLate, power),
                    ],
                    &unsettled,
                );
            }
        }
        Regime::ContinuousSlip | Regime::ImmediateContinuousSlip => {}
    }
    // Labels: undecidable on a regime boundary, and the regime needs a settled motion.
    let boundary = on_boundary(p, c.regime);
    out.push(
        Check::label(Key::Regime, c.regime.integrated().id(), summary.regime.id())
            .unobservable_if(unsettled.or_else(|| boundary.clone())),
    );
    out.push(
        Check::label(
            Key::ImmediateSlip,
            &c.immediate_slip.to_string(),
            &run.immediate_slip.to_string(),
        )
        .unobservable_if(boundary),
    );
    out
}

/// Why the regime is undecidable: φ within [`BOUNDARY_BAND`] of a boundary of guide §9.
fn on_boundary(p: &PulledMassParams, regime: Regime) -> Option<String> {
    let phi = p.phi();
    [1.0 - BOUNDARY_BAND, 1.0 + BOUNDARY_BAND]
        .into_iter()
        .any(|f| cf::regime(phi * f, p.mu_s, p.mu_d) != regime)
        .then(|| {
            format!(
                "φ is within {BOUNDARY_BAND:e} of a regime boundary (2μs, 1/Θ or φ_c): \
                 rounding decides the regime"
            )
        })
}

/// The relative accuracy of τ_ST,late: the root of v = 0 late in the next period is a double
/// root at φ_c, where 2τ'_M² − v_M/(gTμd) = A vanishes: rounding ε·2τ'_M² in A moves the root
/// by ε·τ'_M²/√A, capped at √ε·τ'_M where A is within rounding of 0.
fn late_stick_floor(p: &PulledMassParams) -> f64 {
    let phi = p.phi();
    let tp = cf::tau_accel_zero_falling(phi, p.mu_d);
    let a = 2.0 * tp * tp - cf::v_max_reduced(phi, p.mu_s, p.mu_d) / p.mu_d;
    let eps = f64::EPSILON;
    16.0 * eps * tp * tp / a.max(0.0).sqrt().max(eps.sqrt() * tp.abs())
}

/// Checks of v̄, x_T and P = F v̄ (against the measured friction dissipation): the keys and
/// their closed-form values, same-period or late; not observable when the run is `unsettled`.
fn push_steady(
    out: &mut Vec<Check>,
    s: &Summary,
    [v, x, power]: [(Key, f64); 3],
    unsettled: &Option<String>,
) {
    let dissipated = s.power.friction;
    for (key, closed, numeric) in [
        (v.0, v.1, s.v_avg),
        (x.0, x.1, s.advance_per_period),
        (power.0, power.1, dissipated),
    ] {
        // No widened tolerance: with the force law written about its vertex, a slip of
        // relative length φ/μs is measured to rounding of its own size (guide §12).
        out.push(Check::measured(key, closed, numeric).unobservable_if(unsettled.clone()));
    }
}

/// The first slip of a run from rest: its onset, first speed maximum and stick.
struct FirstCycle {
    slip: Option<Event>,
    maximum: Option<Event>,
    stick: Option<Event>,
}

impl FirstCycle {
    fn of(run: &Run) -> Self {
        let mut events = run.events.iter();
        let slip = events
            .find(|e| matches!(e.kind, EventKind::Slip { .. }))
            .copied();
        let mut maximum = None;
        let mut stick = None;
        for e in events {
            match e.kind {
                EventKind::SpeedMax if maximum.is_none() => maximum = Some(*e),
                EventKind::Stick { .. } => {
                    stick = Some(*e);
                    break;
                }
                EventKind::Reversal { .. } | EventKind::Slip { .. } => break,
                EventKind::SpeedMax => {}
            }
        }
        Self {
            slip,
            maximum,
            stick,
        }
    }
}
