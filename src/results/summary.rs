//! The integration summary of one law (guide §14 `linear` / `harmonic`).

use serde::Serialize;

use crate::engine::{Event, EventKind, IntegrationRegime, Run, Steady};

/// One slip/stick event of the steady period.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct EventOut {
    /// Absolute time (s).
    pub t: f64,
    /// "slip", "stick" or "reversal".
    pub kind: &'static str,
    /// (t mod T)/T.
    pub phase: f64,
}

/// One speed maximum of the steady period.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct MaximumOut {
    /// Absolute time (s), velocity (m/s), phase (t mod T)/T.
    pub t: f64,
    pub v: f64,
    pub phase: f64,
}

/// The power of the driving force on the settled orbit and the friction dissipation measured
/// on the run (W); serialized as `{key: driving, "power_friction": friction}`.
#[derive(Clone, Debug, PartialEq)]
pub struct Power {
    /// The JSON key (guide §14) of the driving power: `power` (pulled mass, F v̄) or `power_weight`
    /// (woodpecker, W_S v̄).
    pub key: &'static str,
    /// The driving power as a product ("F v̄", "W_S v̄").
    pub symbol: &'static str,
    pub driving: Option<f64>,
    pub friction: Option<f64>,
}

impl Serialize for Power {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(2))?;
        map.serialize_entry(self.key, &self.driving)?;
        map.serialize_entry("power_friction", &self.friction)?;
        map.end()
    }
}

/// Summary of an exact integration of one law; keys as guide §14.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Summary {
    pub regime: IntegrationRegime,
    pub immediate_slip: bool,
    pub first_slip_time: Option<f64>,
    pub period_multiplicity: Option<u32>,
    pub slips_per_period: u32,
    pub sticks_per_period: u32,
    pub v_avg: Option<f64>,
    pub advance_per_period: Option<f64>,
    #[serde(flatten)]
    pub power: Power,
    pub steady_events: Vec<EventOut>,
    pub steady_speed_maxima: Vec<MaximumOut>,
}

impl Summary {
    /// Every number of the summary, named as in guide §14 (for [`super::ensure_in_range`]).
    pub fn numbers(&self) -> Vec<(&'static str, f64)> {
        let mut out: Vec<(&'static str, f64)> = [
            ("first_slip_time", self.first_slip_time),
            ("v_avg", self.v_avg),
            ("advance_per_period", self.advance_per_period),
            (self.power.key, self.power.driving),
            ("power_friction", self.power.friction),
        ]
        .into_iter()
        .filter_map(|(name, x)| Some((name, x?)))
        .collect();
        out.extend(self.steady_events.iter().map(|e| ("steady_events.t", e.t)));
        for m in &self.steady_speed_maxima {
            out.extend([
                ("steady_speed_maxima.t", m.t),
                ("steady_speed_maxima.v", m.v),
            ]);
        }
        out
    }

    /// Builds the summary of `run` with its steady state; `power` computes the power keys from
    /// (v̄, friction power).
    pub fn new(
        run: &Run,
        steady: &Steady,
        power: impl FnOnce(Option<f64>, Option<f64>) -> Power,
    ) -> Self {
        let phase = |t: f64| (t / run.period).rem_euclid(1.0);
        Self {
            regime: steady.regime(),
            immediate_slip: run.immediate_slip,
            first_slip_time: run.first_slip,
            period_multiplicity: steady.multiplicity(),
            slips_per_period: steady.slips_per_period,
            sticks_per_period: steady.sticks_per_period,
            v_avg: steady.v_avg,
            advance_per_period: steady.advance_per_period,
            power: power(steady.v_avg, steady.friction_power),
            steady_events: steady
                .events
                .iter()
                .map(|e: &Event| EventOut {
                    t: e.t,
                    kind: kind_name(e.kind),
                    phase: phase(e.t),
                })
                .collect(),
            steady_speed_maxima: steady
                .maxima
                .iter()
                .map(|e| MaximumOut {
                    t: e.t,
                    v: e.v,
                    phase: phase(e.t),
                })
                .collect(),
        }
    }
}

/// The guide §14 name of an event kind.
pub fn kind_name(kind: EventKind) -> &'static str {
    match kind {
        EventKind::Slip { .. } => "slip",
        EventKind::Stick { .. } => "stick",
        EventKind::Reversal { .. } => "reversal",
        EventKind::SpeedMax => "speed_max",
    }
}
