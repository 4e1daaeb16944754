//! Steady state of a run: the period multiplicity of the orbit, and what happens per period
//! once it has settled (guide §4, guide §14 integration summary).

use serde::Serialize;

use super::run::{Event, EventKind, Run};
use super::series::Series;

/// Two event patterns match when their times agree to this fraction of the period.
const PHASE_TOL: f64 = 1e-9;
/// Longest orbit looked for, in periods.
const MAX_MULTIPLICITY: u32 = 4;

/// The kind of long-time motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OrbitKind {
    /// The body never leaves rest.
    NoSlip,
    /// A periodic orbit of the given number of periods.
    Periodic { multiplicity: u32 },
    /// The body never comes back to rest in the last period.
    ContinuousSlip,
    /// No repetition found within the integrated periods.
    NotPeriodic,
}

/// Regime of an integrated law (guide §14 `regime`), serialized as its [`id`].
///
/// [`id`]: IntegrationRegime::id
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntegrationRegime {
    NoSlip,
    SingleSlipStick,
    DoubleSlipStick,
    DoubleSlipNoHalt,
    ContinuousSlip,
    /// Slips without ever sticking, its direction reversing where v passes through 0 with the
    /// drive above the static capacity (the woodpecker when the spring can lift the sleeve).
    ContinuousSlipReversing,
    Multiperiod,
    NotPeriodic,
}

impl IntegrationRegime {
    /// Every regime.
    pub const ALL: [Self; 8] = [
        Self::NoSlip,
        Self::SingleSlipStick,
        Self::DoubleSlipStick,
        Self::DoubleSlipNoHalt,
        Self::ContinuousSlip,
        Self::ContinuousSlipReversing,
        Self::Multiperiod,
        Self::NotPeriodic,
    ];

    /// The identifier used in JSON and reports.
    pub const fn id(self) -> &'static str {
        match self {
            Self::NoSlip => "no_slip",
            Self::SingleSlipStick => "single_slip_stick",
            Self::DoubleSlipStick => "double_slip_stick",
            Self::DoubleSlipNoHalt => "double_slip_no_halt",
            Self::ContinuousSlip => "continuous_slip",
            Self::ContinuousSlipReversing => "continuous_slip_reversing",
            Self::Multiperiod => "multiperiod",
            Self::NotPeriodic => "not_periodic",
        }
    }

    /// The regime in plain words.
    pub fn words(self) -> &'static str {
        match self {
            Self::NoSlip => "no slip at all",
            Self::SingleSlipStick => "one slip and one stick per period",
            Self::DoubleSlipStick => "two slips and two sticks per period",
            Self::DoubleSlipNoHalt => {
                "one slip per period that slows down without stopping in between"
            }
            Self::ContinuousSlip => "continuous slip, never sticking",
            Self::ContinuousSlipReversing => {
                "continuous slip with direction reversals, never sticking"
            }
            Self::Multiperiod => "a motion repeating only after several periods",
            Self::NotPeriodic => "no periodic motion within the periods integrated",
        }
    }
}

impl IntegrationRegime {
    /// The value of JSON `regime` key (guide §14). The contract knows no reversal regime: a motion that
    /// never sticks is `continuous_slip` whether or not it reverses; [`Self::id`] keeps the two
    /// apart for the words and the maps.
    pub const fn json_id(self) -> &'static str {
        match self {
            Self::ContinuousSlipReversing => Self::ContinuousSlip.id(),
            other => other.id(),
        }
    }
}

impl Serialize for IntegrationRegime {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.json_id())
    }
}

/// The settled motion, read off the last periods of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct Steady {
    pub kind: OrbitKind,
    /// Slip, stick and reversal events of the last period, in time order.
    pub events: Vec<Event>,
    /// Speed maxima of the last period.
    pub maxima: Vec<Event>,
    /// Slip onsets (reversals included) and sticks in the last period.
    pub slips_per_period: u32,
    pub sticks_per_period: u32,
    /// Mean advance per period over the orbit (m), mean speed (m/s), mean friction power (W);
    /// `None` when there is no periodic orbit, the friction power also when the run did not
    /// integrate the dissipation ([`RunOptions::dissipation`](super::RunOptions)).
    pub advance_per_period: Option<f64>,
    pub v_avg: Option<f64>,
    pub friction_power: Option<f64>,
}

impl Steady {
    /// The regime of guide §14 for this orbit.
    pub fn regime(&self) -> IntegrationRegime {
        // Reversals only, no stick, in the last period: the body slipped throughout it, whether
        // or not the orbit has settled within the periods integrated.
        let reversing = !self.events.is_empty()
            && self
                .events
                .iter()
                .all(|e| matches!(e.kind, EventKind::Reversal { .. }));
        if reversing
            && matches!(
                self.kind,
                OrbitKind::NotPeriodic | OrbitKind::Periodic { .. }
            )
        {
            return IntegrationRegime::ContinuousSlipReversing;
        }
        match self.kind {
            OrbitKind::NoSlip => IntegrationRegime::NoSlip,
            OrbitKind::ContinuousSlip => IntegrationRegime::ContinuousSlip,
            OrbitKind::NotPeriodic => IntegrationRegime::NotPeriodic,
            OrbitKind::Periodic { multiplicity } if multiplicity > 1 => {
                IntegrationRegime::Multiperiod
            }
            OrbitKind::Periodic { .. } => match self.slips_per_period {
                0 if self.advance_per_period == Some(0.0) => IntegrationRegime::NoSlip,
                0 => IntegrationRegime::ContinuousSlip,
                1 if self.maxima.len() >= 2 => IntegrationRegime::DoubleSlipNoHalt,
                1 => IntegrationRegime::SingleSlipStick,
                _ => IntegrationRegime::DoubleSlipStick,
            },
        }
    }

    /// Period multiplicity n of a periodic orbit.
    pub fn multiplicity(&self) -> Option<u32> {
        match self.kind {
            OrbitKind::Periodic { multiplicity } => Some(multiplicity),
            OrbitKind::NoSlip => Some(1),
            _ => None,
        }
    }
}

/// Finds the steady state of a run: the smallest n ≤ 4 for which the events of the last n
/// periods repeat those of the n before (times to 1e-9 T, same advance to 1e-9 relative).
pub fn analyse(run: &Run) -> Steady {
    let big_n = run.periods;
    let last = big_n.saturating_sub(1);
    let in_period = |p: u32| run.events.iter().filter(move |e| e.period == p);
    let events: Vec<Event> = in_period(last)
        .filter(|e| e.is_transition())
        .copied()
        .collect();
    let maxima: Vec<Event> = in_period(last)
        .filter(|e| e.kind == EventKind::SpeedMax)
        .copied()
        .collect();
    let slips = events
        .iter()
        .filter(|e| !matches!(e.kind, EventKind::Stick { .. }))
        .count() as u32;
    let sticks = events
        .iter()
        .filter(|e| matches!(e.kind, EventKind::Stick { .. }))
        .count() as u32;
    let mut steady = Steady {
        kind: OrbitKind::NotPeriodic,
        events,
        maxima,
        slips_per_period: slips,
        sticks_per_period: sticks,
        advance_per_period: None,
        v_avg: None,
        friction_power: None,
    };
    if run.first_slip.is_none() {
        steady.kind = OrbitKind::NoSlip;
        steady.advance_per_period = Some(0.0);
        steady.v_avg = Some(0.0);
        steady.friction_power = Some(0.0);
        return steady;
    }
    let moving_at_end = run.v_at_period_start.last().is_some_and(|v| v != 0.0);
    if slips + sticks == 0 && moving_at_end {
        steady.kind = OrbitKind::ContinuousSlip;
        steady.events.clear();
        steady.maxima.clear();
        return steady;
    }
    if let Some(n) = (1..=MAX_MULTIPLICITY).find(|&n| 2 * n <= big_n && repeats(run, n)) {
        let n_usize = n as usize;
        let xs = &run.x_at_period_start;
        let k = xs.len() - 1;
        let advance = (at(xs, k) - at(xs, k - n_usize)) / f64::from(n);
        steady.kind = OrbitKind::Periodic { multiplicity: n };
        steady.advance_per_period = Some(advance);
        steady.v_avg = Some(advance / run.period);
        if let Some(last) = run.dissipation.len().checked_sub(n_usize) {
            let energy: f64 = (last..run.dissipation.len())
                .map(|i| at(&run.dissipation, i))
                .sum();
            steady.friction_power = Some(energy / (f64::from(n) * run.period));
        }
    }
    steady
}

/// Whether the last n periods repeat the n periods before them.
fn repeats(run: &Run, n: u32) -> bool {
    let big_n = run.periods;
    let window = |from: u32, to: u32| -> Vec<&Event> {
        run.events
            .iter()
            .filter(|e| e.is_transition() && e.period >= from && e.period < to)
            .collect()
    };
    let recent = window(big_n - n, big_n);
    let before = window(big_n - 2 * n, big_n - n);
    let shift = f64::from(n) * run.period;
    let same_events = recent.len() == before.len()
        && recent.iter().zip(&before).all(|(a, b)| {
            a.kind == b.kind && ((a.t - b.t) - shift).abs() <= PHASE_TOL * run.period
        });
    let xs = &run.x_at_period_start;
    let k = xs.len() - 1;
    let n = n as usize;
    let (d_recent, d_before) = (at(xs, k) - at(xs, k - n), at(xs, k - n) - at(xs, k - 2 * n));
    let vs = &run.v_at_period_start;
    let v_scale = (k - 2 * n..=k).fold(0.0_f64, |m, i| m.max(at(vs, i).abs()));
    same_events
        && (d_recent - d_before).abs() <= PHASE_TOL * d_recent.abs().max(d_before.abs())
        && (at(vs, k) - at(vs, k - n)).abs() <= PHASE_TOL * v_scale
}

/// Value `i` of a run's per-period series, which has periods + 1 values (NaN past its end, which
/// no comparison passes).
fn at(series: &Series, i: usize) -> f64 {
    series.get(i).unwrap_or(f64::NAN)
}
