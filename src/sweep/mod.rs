//! `stickslip sweep`: one parameter of a model varied on a uniform grid; at each point both laws
//! are integrated exactly (v̄, slips and sticks per period, regime) next to the closed-form
//! regime — the paper's remark that the double slip-stick is "critically related with small
//! changes of the parameters", made visible.
//!
//! ```text
//! base params (flags / scenario) + grid (param, from, to, steps)
//!     → points in parallel (rayon), each an independent evaluation
//!     → render (sweep.csv, sweep.svg, one-line summary)  → report::write_all
//! ```
//!
//! A grid point whose parameter set is invalid (e.g. μd > μs mid-sweep) is kept as an
//! "invalid" row; only a sweep that cannot be set up (unknown parameter, bad range) is an error.

mod render;

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::models::{pulled_mass::results as pulled_mass, woodpecker::results as woodpecker};
use crate::params::{invalid, num, PulledMassParams, WoodpeckerParams};
use crate::results::Summary;

pub use render::{render, summary_line};

/// Fewest and most grid points.
pub const MIN_STEPS: u32 = 2;
pub const MAX_STEPS: u32 = 100_000;

/// The base parameters of the swept model (every value but the swept one stays fixed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Base {
    PulledMass(PulledMassParams),
    Woodpecker(WoodpeckerParams),
}

/// A numeric parameter that can be swept: its name, CSV unit suffix, axis label and the factor
/// from SI to the axis unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Param {
    pub name: &'static str,
    /// Unit as a CSV suffix ("m", "kg", "N_m"); empty for dimensionless parameters.
    pub unit: &'static str,
    /// Unit as written in messages ("m", "N/m"); empty for dimensionless parameters.
    pub unit_text: &'static str,
    pub axis_label: &'static str,
    pub axis_scale: f64,
}

const fn param(
    name: &'static str,
    unit: &'static str,
    unit_text: &'static str,
    axis_label: &'static str,
    axis_scale: f64,
) -> Param {
    Param {
        name,
        unit,
        unit_text,
        axis_label,
        axis_scale,
    }
}

/// The sweepable parameters of the pulled mass.
pub const PULLED_MASS_PARAMS: [Param; 6] = [
    param("mu_s", "", "", "μs", 1.0),
    param("mu_d", "", "", "μd", 1.0),
    param("mass", "kg", "kg", "m (g)", 1e3),
    param("k", "N_m", "N/m", "k (N/m)", 1.0),
    param("force", "N", "N", "F (mN)", 1e3),
    param("g", "m_s2", "m/s²", "g (m/s²)", 1.0),
];

/// The sweepable parameters of the woodpecker.
pub const WOODPECKER_PARAMS: [Param; 11] = [
    param("mu_s", "", "", "μs", 1.0),
    param("mu_d", "", "", "μd", 1.0),
    param("k", "N_m", "N/m", "k (N/m)", 1.0),
    param("m_sleeve", "kg", "kg", "m_S (g)", 1e3),
    param("m_bird", "kg", "kg", "m_W (g)", 1e3),
    param("l", "m", "m", "l (mm)", 1e3),
    param("h", "m", "m", "h (mm)", 1e3),
    param("z0", "m", "m", "z0 (mm)", 1e3),
    param("d0", "m", "m", "d0 (mm)", 1e3),
    param("g", "m_s2", "m/s²", "g (m/s²)", 1.0),
    param("lever", "", "", "λ", 1.0),
];

impl Base {
    /// "pulled-mass" or "woodpecker".
    pub fn model(&self) -> &'static str {
        match self {
            Base::PulledMass(_) => "pulled-mass",
            Base::Woodpecker(_) => "woodpecker",
        }
    }

    /// The parameters this model can sweep.
    pub fn params(&self) -> &'static [Param] {
        match self {
            Base::PulledMass(_) => &PULLED_MASS_PARAMS,
            Base::Woodpecker(_) => &WOODPECKER_PARAMS,
        }
    }

    /// The base with parameter `name` set to `value` (`name` is one of [`Base::params`]).
    fn with(&self, name: &str, value: f64) -> Base {
        match *self {
            Base::PulledMass(mut p) => {
                match name {
                    "mu_s" => p.mu_s = value,
                    "mu_d" => p.mu_d = value,
                    "mass" => p.mass = value,
                    "k" => p.k = value,
                    "force" => p.force = value,
                    _ => p.g = value,
                }
                Base::PulledMass(p)
            }
            Base::Woodpecker(mut p) => {
                match name {
                    "mu_s" => p.mu_s = value,
                    "mu_d" => p.mu_d = value,
                    "k" => p.k = value,
                    "m_sleeve" => p.m_sleeve = value,
                    "m_bird" => p.m_bird = value,
                    "l" => p.l = value,
                    "h" => p.h = value,
                    "z0" => p.z0 = value,
                    "d0" => p.d0 = value,
                    "g" => p.g = value,
                    _ => p.lever = Some(value),
                }
                Base::Woodpecker(p)
            }
        }
    }
}

/// What the user asked to sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct GridSpec {
    pub param: String,
    pub from: f64,
    pub to: f64,
    pub steps: u32,
    /// Periods integrated at each point.
    pub periods: u32,
}

/// The outcome of one law at one point.
#[derive(Clone, Debug, PartialEq)]
pub struct LawPoint {
    /// Mean speed of the settled orbit (m/s); `None` when no periodic orbit was found.
    pub v_avg: Option<f64>,
    pub slips: u32,
    pub sticks: u32,
    pub regime: &'static str,
}

impl LawPoint {
    fn of(s: &Summary) -> Self {
        Self {
            v_avg: s.v_avg,
            slips: s.slips_per_period,
            sticks: s.sticks_per_period,
            regime: s.regime.id(),
        }
    }
}

/// One grid point: `None` laws when the parameter set is invalid (or, for the woodpecker's
/// linear law, when its counterpart is undefined).
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    pub value: f64,
    /// Why the point is invalid, if it is.
    pub invalid: Option<Error>,
    pub harmonic: Option<LawPoint>,
    pub linear: Option<LawPoint>,
    pub closed_form: Option<&'static str>,
}

/// A finished sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    pub model: &'static str,
    pub param: Param,
    pub spec: GridSpec,
    pub points: Vec<Point>,
}

/// Checks the grid request against the model: a known parameter, finite distinct ends, and
/// [`MIN_STEPS`] ≤ steps ≤ [`MAX_STEPS`].
pub fn validate(base: &Base, spec: &GridSpec) -> Result<Param> {
    let known = base.params();
    let Some(param) = known.iter().find(|p| p.name == spec.param) else {
        let names: Vec<_> = known.iter().map(|p| p.name).collect();
        return Err(invalid(
            "param",
            &spec.param,
            format!("param in {{{}}} ({})", names.join(", "), base.model()),
        ));
    };
    for (name, value) in [("from", spec.from), ("to", spec.to)] {
        if !value.is_finite() {
            return Err(invalid(
                name,
                num(value),
                format!("-inf < {name} < inf ({} values)", param.name),
            ));
        }
    }
    if spec.from == spec.to {
        return Err(invalid(
            "to",
            num(spec.to),
            format!("to != from = {} (sweep of {})", num(spec.from), param.name),
        ));
    }
    if !(MIN_STEPS..=MAX_STEPS).contains(&spec.steps) {
        return Err(invalid(
            "steps",
            spec.steps,
            format!("{MIN_STEPS} <= steps <= {MAX_STEPS}"),
        ));
    }
    crate::params::validate_periods(spec.periods)?;
    Ok(*param)
}

/// The i-th of `n` uniform grid values from `from` to `to`, both ends exact.
pub fn grid_value(from: f64, to: f64, i: u32, n: u32) -> f64 {
    if i + 1 == n {
        return to;
    }
    from + (to - from) * f64::from(i) / f64::from(n - 1)
}

/// A progress bar on stderr when stderr is a terminal; hidden when it is piped.
pub fn progress_bar(len: u32) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(u64::from(len)), ProgressDrawTarget::hidden());
    if std::io::stderr().is_terminal() {
        bar.set_draw_target(ProgressDrawTarget::stderr());
        if let Ok(style) = ProgressStyle::with_template("sweep {bar:40} {pos}/{len} {eta}") {
            bar.set_style(style);
        }
    }
    bar
}

/// Runs the sweep in parallel over the grid, ticking `progress` once per point.
///
/// Errors: the request fails [`validate`]; every point is invalid (the first point's error is
/// returned, so that a bad fixed parameter is named); or the engine fails at some point.
pub fn run(base: &Base, spec: &GridSpec, progress: &ProgressBar) -> Result<Sweep> {
    let param = validate(base, spec)?;
    let points = (0..spec.steps)
        .into_par_iter()
        .map(|i| {
            let value = grid_value(spec.from, spec.to, i, spec.steps);
            let point = evaluate_point(&base.with(param.name, value), value, spec.periods);
            progress.inc(1);
            point
        })
        .collect::<Result<Vec<_>>>()?;
    progress.finish_and_clear();
    // No valid point: a fixed parameter is bad, or the whole range is; say why at the first.
    let all_invalid = points.iter().all(|p| p.invalid.is_some());
    if let Some(first) = points.first().and_then(|p| p.invalid.clone()) {
        if all_invalid {
            return Err(first);
        }
    }
    Ok(Sweep {
        model: base.model(),
        param,
        spec: spec.clone(),
        points,
    })
}

/// Evaluates one grid point; an invalid parameter set is a point, not an error.
fn evaluate_point(base: &Base, value: f64, periods: u32) -> Result<Point> {
    let evaluated = match base {
        Base::PulledMass(p) => pulled_mass::evaluate(p, periods).map(|e| {
            (
                LawPoint::of(&e.harmonic),
                Some(LawPoint::of(&e.linear)),
                e.closed_form.regime.id(),
            )
        }),
        Base::Woodpecker(p) => woodpecker::evaluate(p, periods).map(|e| {
            (
                LawPoint::of(&e.harmonic),
                e.linear.as_ref().map(LawPoint::of),
                e.closed_form.regime.id(),
            )
        }),
    };
    match evaluated {
        Ok((harmonic, linear, closed)) => Ok(Point {
            value,
            invalid: None,
            harmonic: Some(harmonic),
            linear,
            closed_form: Some(closed),
        }),
        Err(e @ (Error::InvalidParam { .. } | Error::InvalidLaw(_))) => Ok(Point {
            value,
            invalid: Some(e),
            harmonic: None,
            linear: None,
            closed_form: None,
        }),
        Err(e) => Err(e),
    }
}
