//! The whole evaluation of the woodpecker: closed forms of the linearized law, both laws
//! integrated exactly, which formulas describe the motion, and the checks (guide §8, guide §14).

use serde::Serialize;

use crate::engine::{
    analyse, integrate_with, Event, EventKind, IntegrationRegime, Replay, Run, RunOptions,
};
use crate::error::Result;
use crate::models::woodpecker::formula::{
    self as cf, LinearWoodpecker, Orbit, OrbitRegime, OrbitSlip, Phase, WoodpeckerClosedForm,
};
use crate::models::woodpecker::lobe::HaltKind;
use crate::models::woodpecker::params::PARAMS;
use crate::models::woodpecker::quantity::{Key, OrbitQuantity, Scope};
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker, LawKind};
use crate::params::validate_periods;
use crate::results::checks::{unsettled, Check, BOUNDARY_BAND};
use crate::results::quantity::Registry;
use crate::results::summary::{Power, Summary};
use crate::results::{ensure_in_range, Applicability};

/// Input parameters and the derived quantities (keys of guide §14 `params`).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ParamsOut {
    #[serde(flatten)]
    pub input: WoodpeckerParams,
    pub periods: u32,
    #[serde(rename = "W_S")]
    pub sleeve_weight: f64,
    #[serde(rename = "T")]
    pub period: f64,
    pub omega: f64,
    pub lambda: f64,
    pub zeta0: Option<f64>,
    pub delta0: Option<f64>,
}

impl ParamsOut {
    /// The inputs `p` with their derived quantities, for a run of `periods`.
    pub fn of(p: &WoodpeckerParams, periods: u32) -> Self {
        let amplitudes = woodpecker::linear_amplitudes(p);
        Self {
            input: *p,
            periods,
            sleeve_weight: p.sleeve_weight(),
            period: p.period(),
            omega: p.omega(),
            lambda: p.lambda(),
            zeta0: amplitudes.map(|a| a.0),
            delta0: amplitudes.map(|a| a.1),
        }
    }
}

/// The guide §14 object for the woodpecker.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Evaluation {
    pub model: &'static str,
    pub params: ParamsOut,
    pub closed_form: WoodpeckerClosedForm,
    /// Null when the counterpart is undefined for z0, d0 (no linear law to integrate).
    pub linear: Option<Summary>,
    pub harmonic: Summary,
    pub checks: Vec<Check>,
    /// Which paper formulas describe the motion (shown in text and reports).
    #[serde(skip)]
    pub applicability: Vec<Applicability>,
    /// Why the closed forms do not apply at all, if so.
    #[serde(skip)]
    pub domain_note: Option<String>,
}

/// Both laws integrated (the linear one only when its counterpart is defined).
pub struct Runs {
    pub linear: Option<Run>,
    pub harmonic: Run,
}

/// The closed-form inputs of `p` (NaN amplitudes when the counterpart is undefined, which the
/// closed forms turn into nulls).
pub fn linear_inputs(p: &WoodpeckerParams) -> LinearWoodpecker {
    let (zeta0, delta0) = woodpecker::linear_amplitudes(p).unwrap_or((f64::NAN, f64::NAN));
    LinearWoodpecker {
        mu_s: p.mu_s,
        mu_d: p.mu_d,
        lambda: p.lambda(),
        k: p.k,
        w_s: p.sleeve_weight(),
        g: p.g,
        zeta0,
        delta0,
        tau_quarter: 0.25 * p.period(),
    }
}

/// Validates `p`, evaluates the closed forms and integrates both laws for `periods` periods.
pub fn evaluate(p: &WoodpeckerParams, periods: u32) -> Result<Evaluation> {
    Ok(evaluate_with_runs(p, periods, false)?.0)
}

/// As [`evaluate`], also returning the runs (with segments when `record_segments`).
pub fn evaluate_with_runs(
    p: &WoodpeckerParams,
    periods: u32,
    record_segments: bool,
) -> Result<(Evaluation, Runs)> {
    let linear = linear_part(p, periods, record_segments)?;
    let harmonic_run = run_of(p, LawKind::Harmonic, periods, record_segments)?;
    let (linear_run, linear_summary) = linear.run.unzip();
    let evaluation = Evaluation {
        model: "woodpecker",
        params: ParamsOut::of(p, periods),
        closed_form: linear.closed_form,
        linear: linear_summary,
        harmonic: summary_of(p, &harmonic_run),
        checks: linear.checks,
        applicability: linear.applicability,
        domain_note: linear.domain_note,
    };
    in_range(
        &evaluation.params,
        &evaluation.closed_form,
        evaluation
            .linear
            .iter()
            .chain(std::iter::once(&evaluation.harmonic)),
    )?;
    let runs = Runs {
        linear: linear_run,
        harmonic: harmonic_run,
    };
    Ok((evaluation, runs))
}

/// Only what the checks read: the closed forms against the linearized law's run (returned, with
/// segments when `record_segments`; `None` outside its domain); the harmonic law is not
/// integrated. Refuses what [`evaluate_with_runs`] refuses on the same grounds (parameters,
/// closed forms, linear run).
pub fn linear_checks(
    p: &WoodpeckerParams,
    periods: u32,
    record_segments: bool,
) -> Result<(Vec<Check>, Option<Run>)> {
    let linear = linear_part(p, periods, record_segments)?;
    let (run, summary) = linear.run.unzip();
    in_range(
        &ParamsOut::of(p, periods),
        &linear.closed_form,
        summary.iter(),
    )?;
    Ok((linear.checks, run))
}

/// The closed forms, the linearized law's run and summary (where the law exists), and the checks
/// against them.
struct Linear {
    closed_form: WoodpeckerClosedForm,
    run: Option<(Run, Summary)>,
    checks: Vec<Check>,
    applicability: Vec<Applicability>,
    domain_note: Option<String>,
}

fn linear_part(p: &WoodpeckerParams, periods: u32, record_segments: bool) -> Result<Linear> {
    p.validate()?;
    validate_periods(periods)?;
    let closed_form = cf::evaluate(&linear_inputs(p));
    let run = woodpecker::linear_amplitudes(p)
        .map(|_| run_of(p, LawKind::Linear, periods, record_segments))
        .transpose()?
        .map(|run| {
            let summary = summary_of(p, &run);
            (run, summary)
        });
    let domain_note = domain_note(p, &closed_form);
    let applicability = applicability(&closed_form, domain_note.as_deref());
    let checks = match &run {
        Some((run, summary)) if domain_note.is_none() => {
            checks(p, &closed_form, &applicability, run, summary)
        }
        _ => Vec::new(),
    };
    Ok(Linear {
        closed_form,
        run,
        checks,
        applicability,
        domain_note,
    })
}

/// The exact integration of `law` for `periods` periods (with segments when `record_segments`).
fn run_of(p: &WoodpeckerParams, law: LawKind, periods: u32, record_segments: bool) -> Result<Run> {
    let opts = RunOptions {
        periods,
        record_segments,
        dissipation: true,
    };
    integrate_with(
        &woodpecker::body(p),
        &woodpecker::force_law(p, law)?,
        &opts,
        Replay::Compact,
    )
}

fn summary_of(p: &WoodpeckerParams, run: &Run) -> Summary {
    let w_s = p.sleeve_weight();
    Summary::new(run, &analyse(run), |v_avg, friction| Power {
        key: Key::PowerWeight.id(),
        symbol: "W_S v̄",
        driving: v_avg.map(|v| w_s * v),
        friction,
    })
}

/// Refuses parameters whose combination drives a derived parameter, a closed form or an
/// integrated quantity (of `summaries`) out of the range of double precision.
fn in_range<'a>(
    p: &ParamsOut,
    closed_form: &WoodpeckerClosedForm,
    summaries: impl Iterator<Item = &'a Summary>,
) -> Result<()> {
    let derived = [
        ("W_S", Some(p.sleeve_weight)),
        ("T", Some(p.period)),
        ("omega", Some(p.omega)),
        ("lambda", Some(p.lambda)),
        ("zeta0", p.zeta0),
        ("delta0", p.delta0),
    ]
    .into_iter()
    .filter_map(|(name, x)| Some((name, x?)));
    let closed = Key::numbers()
        .filter_map(|entry| Some((entry.quantity.id, closed_form.value(entry.key).computed()?)));
    ensure_in_range(
        derived
            .chain(closed)
            .chain(summaries.flat_map(Summary::numbers)),
        "k, the masses, l, h, z0, d0 and g",
    )
}

/// Why the closed forms do not apply at all (outside their domain), if so.
pub fn domain_note(p: &WoodpeckerParams, c: &WoodpeckerClosedForm) -> Option<String> {
    if woodpecker::linear_amplitudes(p).is_none() {
        return Some(format!(
            "the {} counterpart is undefined for |z0| > d0 (z0 = {} m, d0 = {} m): F_e never \
             changes sign; only the harmonic law is integrated",
            p.counterpart.id(),
            crate::error::short(p.z0),
            crate::error::short(p.d0)
        ));
    }
    if c.regime != OrbitRegime::OutsideClosedFormDomain {
        return None;
    }
    let (zeta0, delta0) = (c.zeta0.unwrap_or(f64::NAN), c.delta0.unwrap_or(f64::NAN));
    Some(if !(delta0 >= 0.0 && delta0 < zeta0) {
        format!(
            "the closed forms need 0 <= delta0 < zeta0 (F_e changes sign with the positive lobe \
             first); here delta0 = {delta0:.6e} m, zeta0 = {zeta0:.6e} m"
        )
    } else {
        format!(
            "the closed forms need u_s^(-) = 2 lambda mu_s - 1 > 0; here u_s^(-) = {:.6}",
            c.u_s_minus.unwrap_or(f64::NAN)
        )
    })
}

/// The quantities of a phase's slip from rest ([`Scope::Slip`]), in the order of their
/// applicability and checks.
const PHASE_KEYS: [[Key; 8]; 2] = [
    [
        Key::TSlip1,
        Key::ASlip1,
        Key::TMaxSpeed1,
        Key::VMax1,
        Key::TStick1,
        Key::S1,
        Key::Gamma1,
        Key::Distance1,
    ],
    [
        Key::TSlip2,
        Key::ASlip2,
        Key::TMaxSpeed2,
        Key::VMax2,
        Key::TStick2,
        Key::S2,
        Key::Gamma2,
        Key::Distance2,
    ],
];

/// For each paper formula of the phases and of the whole period: does it describe the motion?
pub fn applicability(c: &WoodpeckerClosedForm, domain_note: Option<&str>) -> Vec<Applicability> {
    let mut out = Vec::new();
    let mut push = |quantity: Key, reason: Option<String>| {
        out.push(Applicability::new(quantity, reason));
    };
    let orbit_slips: &[OrbitSlip] = c.orbit.as_ref().map_or(&[], |o| &o.slips);
    for (i, keys) in PHASE_KEYS.iter().enumerate() {
        let phase = if i == 0 { Phase::One } else { Phase::Two };
        let name = if i == 0 { "I" } else { "II" };
        let halt = match orbit_slips.iter().find(|s| s.phase == phase) {
            Some(slip) => Some(Some(slip.halt)),
            // Continuous slip: the first slip from rest still follows the phase-I onset formulas.
            None if first_slip_only(c) && phase == Phase::One => Some(None),
            None => None,
        };
        // The speed peaks in lobe B, where (46)/(62) put it, iff u_B h_B ≥ 1 (guide §8.6 step 2).
        let (u_b, h_b) = if i == 0 {
            (c.u_d_plus, c.eta)
        } else {
            (c.u_d_minus, c.eta_prime)
        };
        let max_in_lobe_b = u_b.zip(h_b).is_some_and(|(u, h)| u * h >= 1.0);
        for (j, &key) in keys.iter().enumerate() {
            let reason = match (domain_note, halt) {
                (Some(note), _) => Some(note.to_string()),
                (None, None) => Some(format!(
                    "no slip starts from rest in phase {name} on the periodic orbit ({})",
                    c.regime.words()
                )),
                (None, Some(halt)) => match (j, halt) {
                    (0 | 1, _) => None,
                    (2 | 3, _) if max_in_lobe_b => None,
                    (2 | 3, _) => Some(format!(
                        "no speed maximum in the next lobe (a > 0 there): the phase-{name} \
                         maximum is not (46)/(62)"
                    )),
                    (_, Some(HaltKind::B)) => None,
                    (_, Some(h)) => Some(format!(
                        "the phase-{name} slip halts on flank {} (guide §8.6), not on the rising flank \
                         of the next lobe that (49)/(60) assume",
                        halt_name(h)
                    )),
                    (_, None) => {
                        Some("continuous slip: the first slip from rest never halts".to_string())
                    }
                },
            };
            push(key, reason);
        }
    }
    let period_reason = if c.paper_regime_valid {
        None
    } else {
        Some(
            "outside the paper's standard regime (both sticks inside their half periods): \
             (68)-(71) do not give the motion; the lobe-engine orbit does"
                .to_string(),
        )
    };
    for e in Key::ENTRIES
        .iter()
        .filter(|e| e.regimes == Scope::PaperRegime)
    {
        push(e.key, period_reason.clone());
    }
    out
}

/// Continuous slip from a delayed start: only the first slip from rest has closed forms.
fn first_slip_only(c: &WoodpeckerClosedForm) -> bool {
    c.orbit.is_none() && c.regime == OrbitRegime::ContinuousOrMultiperiod && !c.immediate_slip
}

fn halt_name(h: HaltKind) -> &'static str {
    match h {
        HaltKind::B => "B",
        HaltKind::BLate => "B_late",
        HaltKind::A => "A",
        HaltKind::ALate => "A_late",
    }
}

/// Whether an integration regime is the one the closed-form regime predicts.
fn regime_agrees(closed: OrbitRegime, numeric: IntegrationRegime) -> bool {
    use IntegrationRegime as I;
    match (closed, closed.integrated()) {
        (_, Some(integrated)) => numeric == integrated,
        (OrbitRegime::ContinuousOrMultiperiod, None) => {
            matches!(numeric, I::ContinuousSlip | I::Multiperiod | I::NotPeriodic)
        }
        (_, None) => false,
    }
}

/// One slip of the orbit as measured on the linear run: onset, maxima, stick.
struct MeasuredSlip {
    slip: Event,
    maxima: Vec<Event>,
    stick: Option<Event>,
}

/// The measured slip whose onset matches `expected` (s, within the period) in period `n`.
fn measure(run: &Run, n: u32, expected: f64) -> Option<MeasuredSlip> {
    let start = f64::from(n) * run.period;
    let i = run.events.iter().position(|e| {
        matches!(e.kind, EventKind::Slip { .. })
            && e.period == n
            && ((e.t - start) - expected).abs() <= 1e-6 * run.period
    })?;
    let mut maxima = Vec::new();
    let mut stick = None;
    for e in &run.events[i + 1..] {
        match e.kind {
            EventKind::SpeedMax => maxima.push(*e),
            EventKind::Stick { .. } => {
                stick = Some(*e);
                break;
            }
            _ => break,
        }
    }
    Some(MeasuredSlip {
        slip: run.events[i],
        maxima,
        stick,
    })
}

/// Checks of the closed forms that describe the motion, and of the lobe-engine orbit.
fn checks(
    p: &WoodpeckerParams,
    c: &WoodpeckerClosedForm,
    applicability: &[Applicability],
    run: &Run,
    summary: &Summary,
) -> Vec<Check> {
    let applies = |key: Key| {
        applicability
            .iter()
            .any(|a| a.quantity == key.into() && a.applies)
    };
    let mut out = Vec::new();
    // A period of the settled orbit whose slips halt before the run ends (halts come < 2T
    // after the period start).
    let n = run.periods.saturating_sub(3);
    let law = woodpecker::force_law(p, LawKind::Linear).ok();
    let body = woodpecker::body(p);
    // The acceleration at a slip onset, measured relative to the largest force per unit mass
    // over the period (k·d0 can dwarf the weight: the slip time's rounding then moves a_SL
    // by ε·T times the slope of forces that large).
    let force_scale = law.as_ref().map_or(p.g, |l| {
        (0..16)
            .map(|i| {
                let t = run.period * f64::from(i) / 16.0;
                (l.drive(t).abs() + p.mu_d * l.normal(t).abs()) / body.mass
            })
            .fold(p.g, f64::max)
    });
    let accel_at = |t: f64| {
        law.as_ref()
            .map(|l| body.slip_acceleration(l.drive(t), l.normal(t), 1.0))
    };
    let time = |key, closed, numeric| Check::measured_on_scale(key, closed, numeric, run.period);
    let unsettled = unsettled(run.periods, summary);
    // The slips to measure: the orbit's, from a settled period; or, in continuous slip, the
    // first slip from rest in the first period.
    let slips: Vec<(Phase, f64, u32, Option<&OrbitSlip>)> = match &c.orbit {
        Some(orbit) => orbit
            .slips
            .iter()
            .map(|s| (s.phase, s.t_slip, n, Some(s)))
            .collect(),
        None => c
            .t_slip_1
            .filter(|_| first_slip_only(c))
            .map(|t| (Phase::One, t, 0, None))
            .into_iter()
            .collect(),
    };
    for (k, &(phase, t_expected, period, orbit_slip)) in slips.iter().enumerate() {
        let start = f64::from(period) * run.period;
        let m = measure(run, period, t_expected);
        let keys = &PHASE_KEYS[usize::from(phase == Phase::Two)];
        let phase_values = phase_values(c, phase);
        let t_slip = m.as_ref().map(|m| m.slip.t - start);
        let first_max = m.as_ref().and_then(|m| m.maxima.first().copied());
        let stick = m.as_ref().and_then(|m| m.stick);
        // Measured counterparts, by index into PHASE_KEYS (S and Γ have none).
        let accel = t_slip.and_then(|t| accel_at(t + start));
        // Measured counterparts, by index into PHASE_KEYS (S and Γ have none), with the
        // scale of their error: event times as fractions of the period.
        let measured = [
            (0, t_slip, run.period),
            (1, accel, force_scale),
            (2, first_max.map(|e| e.t - start), run.period),
            (3, first_max.map(|e| e.v), 0.0),
            (4, stick.map(|e| e.t - start), run.period),
            (7, stick.zip(m.as_ref()).map(|(st, m)| st.x - m.slip.x), 0.0),
        ];
        for (j, value, scale) in measured {
            if let (true, Some(closed)) = (applies(keys[j]), phase_values[j]) {
                out.push(
                    Check::measured_on_scale(keys[j], closed, value, scale)
                        .unobservable_if(unsettled.clone()),
                );
            }
        }
        if let Some(slip) = orbit_slip {
            let covered = |j: usize| applies(keys[j]) && phase_values[j].is_some();
            let covered = [covered(4), covered(2), covered(7)];
            let from = out.len();
            push_orbit_checks(&mut out, k + 1, slip, m.as_ref(), start, covered, &time);
            mark_unobservable(&mut out[from..], &unsettled);
        }
    }
    if let Some(orbit) = &c.orbit {
        let from = out.len();
        push_period_checks(&mut out, c, orbit, summary, applies(Key::VAvg));
        mark_unobservable(&mut out[from..], &unsettled);
    }
    let regime = Check::label_agreeing(
        Key::Regime,
        c.regime.id(),
        summary.regime.id(),
        regime_agrees(c.regime, summary.regime),
    );
    let immediate = Check::label(
        Key::ImmediateSlip,
        &c.immediate_slip.to_string(),
        &run.immediate_slip.to_string(),
    );
    // Only a failure asks whether rounding could decide the regime (a dozen closed-form
    // evaluations). Within that band of a boundary the orbit's stick is a tangency: its time
    // moves as the square root of the distance to the boundary (at μd,HALT^(II) of the Fig. 15
    // set, 6e-9 T for one ulp of μd in a 40-digit integration) and one ulp can remove it, so
    // every value the boundary decides is not observable at this conditioning.
    let boundary = (out.iter().any(Check::failed) || !regime.passed() || !immediate.passed())
        .then(|| on_boundary(p))
        .flatten();
    mark_unobservable(&mut out, &boundary);
    out.push(regime.unobservable_if(unsettled.or_else(|| boundary.clone())));
    out.push(immediate.unobservable_if(boundary));
    out
}

/// The checks marked not observable for `reason`, when there is one.
fn mark_unobservable(checks: &mut [Check], reason: &Option<String>) {
    for c in checks {
        *c = c.clone().unobservable_if(reason.clone());
    }
}

/// Why the regime is undecidable: a relative change of [`BOUNDARY_BAND`] in one parameter
/// changes the closed-form regime or the immediate slip.
fn on_boundary(p: &WoodpeckerParams) -> Option<String> {
    let closed_form = |p: &WoodpeckerParams| cf::evaluate(&linear_inputs(p));
    let base = closed_form(p);
    let base = (base.regime, base.immediate_slip);
    PARAMS.iter().find_map(|spec| {
        let value = (spec.get)(p)?;
        [1.0 - BOUNDARY_BAND, 1.0 + BOUNDARY_BAND]
            .into_iter()
            .any(|f| {
                let mut q = *p;
                (spec.set)(&mut q, value * f);
                let c = closed_form(&q);
                (c.regime, c.immediate_slip) != base
            })
            .then(|| {
                format!(
                    "not observable at this conditioning: a relative change of \
                     {BOUNDARY_BAND:e} in {} changes the regime, so rounding decides it",
                    spec.key
                )
            })
    })
}

/// The closed-form values of one phase in the order of [`PHASE_KEYS`].
fn phase_values(c: &WoodpeckerClosedForm, phase: Phase) -> [Option<f64>; 8] {
    match phase {
        Phase::One => [
            c.t_slip_1,
            c.a_slip_1,
            c.t_max_speed_1,
            c.v_max_1,
            c.t_stick_1,
            c.s_1,
            c.gamma_1,
            c.distance_1,
        ],
        Phase::Two => [
            c.t_slip_2,
            c.a_slip_2,
            c.t_max_speed_2,
            c.v_max_2,
            c.t_stick_2,
            c.s_2,
            c.gamma_2,
            c.distance_2,
        ],
    }
}

/// Orbit checks of one slip: its halt time, every speed maximum and its distance (guide §8.6), less
/// those a paper formula already checks (`covered`: stick, first maximum, distance).
fn push_orbit_checks(
    out: &mut Vec<Check>,
    k: usize,
    slip: &OrbitSlip,
    m: Option<&MeasuredSlip>,
    start: f64,
    covered: [bool; 3],
    time: &dyn Fn(OrbitQuantity, f64, Option<f64>) -> Check,
) {
    let [stick_covered, first_max_covered, distance_covered] = covered;
    if !stick_covered {
        let stick = m.and_then(|m| m.stick);
        out.push(time(
            OrbitQuantity::TStick { slip: k },
            slip.t_halt,
            stick.map(|e| e.t - start),
        ));
    }
    for (j, &(t, v)) in slip.speed_maxima.iter().enumerate() {
        if j == 0 && first_max_covered {
            continue;
        }
        let measured = m.and_then(|m| m.maxima.get(j));
        out.push(time(
            OrbitQuantity::TMaxSpeed {
                slip: k,
                maximum: j + 1,
            },
            t,
            measured.map(|e| e.t - start),
        ));
        out.push(Check::measured(
            OrbitQuantity::VMax {
                slip: k,
                maximum: j + 1,
            },
            v,
            measured.map(|e| e.v),
        ));
    }
    if !distance_covered {
        let distance = m.and_then(|m| m.stick.map(|st| st.x - m.slip.x));
        out.push(Check::measured(
            OrbitQuantity::Distance { slip: k },
            slip.distance,
            distance,
        ));
    }
}

/// Checks of the advance and mean speed per period: (68)–(71) where they apply, and the orbit.
fn push_period_checks(
    out: &mut Vec<Check>,
    c: &WoodpeckerClosedForm,
    orbit: &Orbit,
    s: &Summary,
    paper_applies: bool,
) {
    if paper_applies {
        if let (Some(y), Some(v)) = (c.distance_per_period, c.v_avg) {
            out.push(Check::measured(
                Key::DistancePerPeriod,
                y,
                s.advance_per_period,
            ));
            out.push(Check::measured(Key::VAvg, v, s.v_avg));
        }
    }
    out.push(Check::measured(
        Key::OrbitDistancePerPeriod,
        orbit.distance_per_period,
        s.advance_per_period,
    ));
    out.push(Check::measured(Key::OrbitVAvg, orbit.v_avg, s.v_avg));
}
